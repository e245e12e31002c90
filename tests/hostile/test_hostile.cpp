// The generated hostile-input suite: valid inputs, mutated, given to the `swarm` command that reads
// them. Flag values at 0, -1, 2^31, 2^32, 2^64, NaN, +-inf, 1e308 and 1e-300; scenario files with
// each of those in a numeric field, truncated or with garbage inserted; map files (YAML + PGM,
// MovingAI), robots, tour and graph files truncated, extended, garbled and with their numbers at
// the edges. Every case must end in success or in exit 2 with a message naming the flag, field or
// file (the commands' other statuses where they mean a result, e.g. `swarm mapf`'s 1 = not
// solved); none may crash, hang or leave a process behind. A fixed seed; each family prints how
// many cases it ran.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "swarm/record/record.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::vector<std::string> kEdgeNumbers = {"0",   "-1",  "2147483648", "4294967296", "18446744073709551616",
                                               "nan", "inf", "-inf",       "1e308",      "1e-300"};

struct Outcome {
  int code = -1;        // exit status; -1 when it did not exit
  int signal = 0;       // the signal that ended it
  bool hung = false;    // still running at the limit (then killed)
  bool left = false;    // a process of its group outlived it
  std::string output;   // stdout and stderr
};

// Runs `swarm ARGS` in a process group of its own, with a wall-clock limit.
Outcome run_swarm(const std::vector<std::string>& args, std::chrono::seconds limit) {
  int out[2];
  if (::pipe(out) != 0) return {};
  const std::string exe = std::string(SWARM_BIN_DIR) + "/swarm";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    const int devnull = ::open("/dev/null", O_RDONLY);
    ::dup2(devnull, 0);
    ::dup2(out[1], 1);
    ::dup2(out[1], 2);
    ::close(out[0]);
    std::vector<char*> argv{const_cast<char*>(exe.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(exe.c_str(), argv.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  ::close(out[1]);
  Outcome o;
  const auto deadline = Clock::now() + limit;
  char buf[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      o.hung = true;
      break;
    }
    pollfd p{out[0], POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left)) <= 0) continue;
    const ssize_t n = ::read(out[0], buf, sizeof buf);
    if (n <= 0) break;
    if (o.output.size() < 20000) o.output.append(buf, static_cast<std::size_t>(n));
  }
  if (o.hung) ::kill(-pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(out[0]);
  if (WIFEXITED(status)) o.code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) o.signal = WTERMSIG(status);
  o.left = ::kill(-pid, 0) == 0;
  if (o.left) ::kill(-pid, SIGKILL);
  return o;
}

void spit(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string joined(const std::vector<std::string>& args) {
  std::string out;
  for (const std::string& a : args) out += (out.empty() ? "" : " ") + a;
  return out;
}

// One family of cases: runs them, checks each, counts them.
class Family {
 public:
  explicit Family(std::string name) : name_(std::move(name)) {
    dir_ = std::string(SWARM_TEST_RUNS_DIR) + "/hostile-" + name_;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Family() {
    std::printf("[ hostile  ] %s: %d cases, %d refused with exit 2, %d failed\n", name_.c_str(), cases_, refused_,
                failed_);
    fs::remove_all(dir_);
  }
  const std::string& dir() const { return dir_; }
  std::string file(const std::string& name) const { return dir_ + "/" + name; }
  // A fresh output directory for a case.
  std::string out() { return dir_ + "/out-" + std::to_string(cases_); }

  // `names`: what a refusal must name (any one of them); `codes`: the statuses besides 0 and 2
  // that the command gives as a result.
  void expect(const std::vector<std::string>& args, const std::vector<std::string>& names,
              const std::set<int>& codes = {}, std::chrono::seconds limit = std::chrono::seconds(60)) {
    ++cases_;
    const Outcome o = run_swarm(args, limit);
    std::string wrong;
    if (o.hung) wrong = "still running after " + std::to_string(limit.count()) + " s";
    else if (o.signal != 0) wrong = "died of signal " + std::to_string(o.signal);
    else if (o.left) wrong = "left a process behind";
    else if (o.code != 0 && o.code != 2 && !codes.count(o.code)) wrong = "exit " + std::to_string(o.code);
    else if (o.code == 2 && !names.empty()) {
      bool named = false;
      for (const std::string& n : names) named = named || o.output.find(n) != std::string::npos;
      if (!named) {
        wrong = "exit 2 without naming any of:";
        for (const std::string& n : names) wrong += " '" + n + "'";
      }
    }
    if (o.code == 2) ++refused_;
    if (!wrong.empty()) {
      ++failed_;
      ADD_FAILURE() << name_ << ": swarm " << joined(args) << "\n  " << wrong << "\n  output: " << o.output.substr(0, 600);
    }
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir_, ec)) {
      if (e.path().filename().string().rfind("out-", 0) == 0) fs::remove_all(e.path(), ec);
    }
  }

 private:
  std::string name_;
  std::string dir_;
  int cases_ = 0;
  int refused_ = 0;
  int failed_ = 0;
};

// `text` with its byte range [from, to) replaced.
std::string spliced(const std::string& text, std::size_t from, std::size_t to, const std::string& with) {
  return text.substr(0, from) + with + text.substr(std::min(to, text.size()));
}

// Mutations of a text file: each number of each line at each edge value (or `per_file` of them,
// drawn with `rng`), cuts at random points, random garbage inserted. Each: (what, text, line).
struct Mutant {
  std::string what;
  std::string text;
  int line = 0;  // 1-based line changed; 0 when the change is not one line's
  std::string key;  // the word before the number, where there is one
};

std::vector<Mutant> mutants_of(const std::string& text, std::mt19937& rng, std::size_t numbers_per_file) {
  std::vector<Mutant> out;
  static const std::regex kNumber(R"((-?[0-9]+(?:\.[0-9]+)?(?:[eE][-+]?[0-9]+)?|\binf\b|\bnan\b))");
  struct Spot {
    std::size_t from, to;
    int line;
    std::string key;
  };
  std::vector<Spot> spots;
  std::size_t line_start = 0;
  int line_no = 1;
  while (line_start < text.size()) {
    const std::size_t end = std::min(text.find('\n', line_start), text.size());
    const std::string line = text.substr(line_start, end - line_start);
    if (line.find('#') != 0 && line.find("//") != 0) {
      static const std::regex kKey(R"(([A-Za-z_][A-Za-z_0-9-]*)\s*:?\s*$)");
      for (auto it = std::sregex_iterator(line.begin(), line.end(), kNumber); it != std::sregex_iterator(); ++it) {
        const std::string before = line.substr(0, static_cast<std::size_t>(it->position()));
        // Numbers inside names ("member-0-1", "maze1") are not numbers.
        if (!before.empty() && (std::isalnum(static_cast<unsigned char>(before.back())) || before.back() == '-' ||
                                before.back() == '_' || before.back() == '"'))
          continue;
        std::smatch k;
        std::string key;
        if (std::regex_search(before, k, kKey)) key = k[1].str();
        spots.push_back({line_start + static_cast<std::size_t>(it->position()),
                         line_start + static_cast<std::size_t>(it->position() + it->length()), line_no, key});
      }
    }
    line_start = end + 1;
    ++line_no;
  }
  std::shuffle(spots.begin(), spots.end(), rng);
  if (spots.size() > numbers_per_file) spots.resize(numbers_per_file);
  for (const Spot& s : spots) {
    for (const std::string& v : kEdgeNumbers) {
      out.push_back({"line " + std::to_string(s.line) + " number -> " + v, spliced(text, s.from, s.to, v), s.line, s.key});
    }
  }
  for (int i = 0; i < 3 && !text.empty(); ++i) {
    const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
    out.push_back({"cut at byte " + std::to_string(at), text.substr(0, at), 0, ""});
  }
  for (int i = 0; i < 2 && !text.empty(); ++i) {
    const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
    std::string junk;
    for (int k = 0; k < 6; ++k) junk += static_cast<char>(std::uniform_int_distribution<int>(1, 255)(rng));
    out.push_back({"garbage at byte " + std::to_string(at), spliced(text, at, at, junk), 0, ""});
  }
  out.push_back({"doubled", text + text, 0, ""});
  return out;
}

std::string source(const std::string& relative) { return std::string(SWARM_SOURCE_DIR) + "/" + relative; }

// A small MovingAI map: an 8 x 6 room with a wall stub.
const std::string kMovingAi = "type octile\nheight 6\nwidth 8\nmap\n........\n........\n...@@...\n........\n........\n........\n";

TEST(Hostile, FlagValues) {
  Family f("flags");
  const std::string map = f.file("room.map");
  spit(map, kMovingAi);
  // A run directory for render: a record of ticks 0..9.
  const std::string run_dir = f.file("run");
  fs::create_directories(run_dir);
  {
    swarm::record::RecordWriter w(run_dir);
    swarm::record::Frame h;
    h.mutable_header()->set_width(8);
    h.mutable_header()->set_height(6);
    h.mutable_header()->set_groups(1);
    h.mutable_header()->set_robots_per_group(1);
    w.append(h);
    for (std::uint32_t t = 0; t < 10; ++t) {
      swarm::record::Frame p;
      p.mutable_poses()->set_tick(t);
      p.mutable_poses()->add_xy(1);
      p.mutable_poses()->add_xy(1);
      w.append(p);
    }
  }
  const std::vector<std::string> run = {"run", "--check", "--map", "small", "--groups", "1", "--robots-per-group", "2"};
  for (const std::string& flag : {"--seed", "--groups", "--robots-per-group", "--max-ticks", "--tick-ms", "--timeout",
                                  "--domain", "--agents-per-process"}) {
    std::string field = flag.substr(2);
    std::replace(field.begin(), field.end(), '-', '_');
    for (const std::string& v : kEdgeNumbers) {
      std::vector<std::string> a = run;
      a.insert(a.end(), {flag, v});
      f.expect(a, {flag, field});
    }
  }
  for (const std::string& v : kEdgeNumbers) {
    f.expect({"run", "--check", "--map", map, "--groups", "1", "--robots-per-group", "1", "--map-resolution", v},
             {"--map-resolution", "map_resolution_m"});
    f.expect({"run", "--check", "--map", "small", "--start", v + ",1"}, {"--start", "start"});
    f.expect({"run", "--check", "--map", "small", "--kill", "member-0-1@" + v}, {"--kill", "kill_at_tick"});
  }
  const std::vector<std::pair<std::string, std::vector<std::string>>> darp = {
      {"--seed", {}}, {"--count", {}}, {"--max-iterations", {}}, {"--time-limit", {}}};
  for (const auto& [flag, extra] : darp) {
    for (const std::string& v : kEdgeNumbers) {
      f.expect({"darp", "--map", "small", "--count", "2", "--max-iterations", "20", flag, v, "--out", f.out()}, {flag},
               {1, 3});
    }
  }
  for (const std::string& flag : {"--seed", "--random", "--time-limit", "--w"}) {
    for (const std::string& v : kEdgeNumbers) {
      f.expect({"mapf", "--map", "small", "--random", "2", "--solver", "ecbs", "--time-limit", "5", flag, v, "--out", f.out()},
               {flag}, {1});
    }
  }
  for (const std::string& flag : {"--tick", "--scale"}) {
    for (const std::string& v : kEdgeNumbers) f.expect({"render", run_dir, flag, v, "--out", f.file("x.png")}, {flag});
  }
  // Every value refused before anything listens: none of them is a port.
  for (const std::string& v : kEdgeNumbers) f.expect({"view", run_dir, "--view-port", v}, {"--view-port"});
  for (const std::string& v : {std::string(""), std::string("not-an-address"), std::string("::g")}) {
    f.expect({"view", run_dir, "--view-bind", v}, {"--view-bind"});
  }
  f.expect({"export", run_dir, "--mcap", f.file("x.mcap")}, {});
  f.expect({"export", run_dir, "--mcap", f.file("no/such/folder/x.mcap")}, {"x.mcap"});
  for (const std::string& flag : {"--seed", "--generations"}) {
    for (const std::string& v : kEdgeNumbers) {
      f.expect({"tour", source("scenarios/tour/scenario1.tour"), "--variants", "nna", flag, v, "--out", f.out()}, {flag});
    }
  }
  for (const std::string& flag : {"--k", "--seed", "--margin"}) {
    for (const std::string& v : kEdgeNumbers) f.expect({"clean", "small", flag, v, "--out", f.out()}, {flag});
  }
}

TEST(Hostile, ScenarioFiles) {
  Family f("scenarios");
  std::mt19937 rng(2026);
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(source("scenarios"))) {
    if (e.path().extension() == ".pbtxt") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& p : files) {
    const std::string text = slurp(p.string());
    int n = 0;
    for (const Mutant& m : mutants_of(text, rng, 4)) {
      const std::string path = f.file(p.stem().string() + "-" + std::to_string(n++) + ".pbtxt");
      spit(path, m.text);
      std::vector<std::string> names = {path + ":"};
      if (!m.key.empty()) names.push_back(m.key);
      if (m.line == 0) names.push_back(path);  // a cut or garbage may leave a file that parses
      f.expect({"run", "--check", "--scenario", path}, names);
    }
  }
}

TEST(Hostile, MapServerMaps) {
  Family f("yaml-maps");
  std::mt19937 rng(2027);
  const std::string pgm = "P2\n8 6\n255\n0 0 0 0 0 0 0 0\n0 254 254 254 254 254 254 0\n0 254 254 254 254 254 254 0\n"
                          "0 254 254 0 0 254 254 0\n0 254 254 254 254 254 254 0\n0 0 0 0 0 0 0 0\n";
  const std::string yaml = "image: room.pgm\nresolution: 0.2\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                           "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  spit(f.file("room.pgm"), pgm);
  int n = 0;
  const auto check = [&](const std::string& yaml_text, const std::string& image) {
    const std::string y = f.file("map-" + std::to_string(n++) + ".yaml");
    spit(y, yaml_text);
    f.expect({"run", "--check", "--map", y, "--groups", "1", "--robots-per-group", "1"}, {y, image});
  };
  for (const Mutant& m : mutants_of(yaml, rng, 8)) check(m.text, "room.pgm");
  for (const Mutant& m : mutants_of(pgm, rng, 6)) {
    const std::string image = "img-" + std::to_string(n) + ".pgm";
    spit(f.file(image), m.text);
    check(std::regex_replace(yaml, std::regex("room\\.pgm"), image), image);
  }
  // Binary PGMs: short, long, and headers at the edges.
  std::string p5 = "P5\n8 6\n255\n";
  std::string pixels(48, '\xfe');
  for (std::size_t i = 0; i < 8; ++i) pixels[i] = pixels[40 + i] = '\0';
  for (const std::string& body : {p5 + pixels, p5 + pixels.substr(0, 47), p5 + pixels + "x", p5, std::string("P5\n"),
                                  "P5\n2147483647 2147483647\n255\n" + pixels, "P5\n8 6\n65535\n" + pixels,
                                  "P5\n-8 6\n255\n" + pixels, "P5\n8 6\n0\n" + pixels, std::string("P7\n8 6\n255\n")}) {
    const std::string image = "bin-" + std::to_string(n) + ".pgm";
    spit(f.file(image), body);
    check(std::regex_replace(yaml, std::regex("room\\.pgm"), image), image);
  }
}

TEST(Hostile, MovingAiMaps) {
  Family f("movingai");
  std::mt19937 rng(2028);
  std::vector<Mutant> mutants = mutants_of(kMovingAi, rng, 3);
  std::string rows;
  for (int r = 0; r < 6; ++r) rows += "........\n";
  mutants.push_back({"extra rows", kMovingAi + "........\n........\n", 0, ""});
  mutants.push_back({"short row", std::regex_replace(kMovingAi, std::regex("\\.\\.\\.@@\\.\\.\\."), "...@@.."), 0, ""});
  mutants.push_back({"bad cell", std::regex_replace(kMovingAi, std::regex("@@"), "@\x01"), 0, ""});
  mutants.push_back({"all walls", std::regex_replace(kMovingAi, std::regex("\\."), "@"), 0, ""});
  mutants.push_back({"no map line", std::regex_replace(kMovingAi, std::regex("map\n"), ""), 0, ""});
  mutants.push_back({"empty", "", 0, ""});
  int n = 0;
  for (const Mutant& m : mutants) {
    const std::string path = f.file("m-" + std::to_string(n++) + ".map");
    spit(path, m.text);
    f.expect({"run", "--check", "--map", path, "--groups", "1", "--robots-per-group", "1"}, {path});
    f.expect({"darp", "--map", path, "--count", "2", "--max-iterations", "20", "--out", f.out()}, {path}, {1, 3});
    f.expect({"mapf", "--map", path, "--random", "2", "--time-limit", "5", "--out", f.out()}, {path}, {1});
  }
}

TEST(Hostile, RobotsTourAndGraphFiles) {
  Family f("files");
  std::mt19937 rng(2029);
  int n = 0;
  const std::string robots = "1 1\n5 3\n";
  for (const Mutant& m : mutants_of(robots, rng, 4)) {
    const std::string path = f.file("robots-" + std::to_string(n++) + ".txt");
    spit(path, m.text);
    f.expect({"darp", "--map", "small", "--robots-file", path, "--max-iterations", "20", "--out", f.out()}, {path},
             {1, 3});
  }
  const std::string tour = slurp(source("scenarios/tour/scenario1.tour"));
  for (const Mutant& m : mutants_of(tour, rng, 5)) {
    const std::string path = f.file("t-" + std::to_string(n++) + ".tour");
    spit(path, m.text);
    f.expect({"tour", path, "--variants", "nna", "--out", f.out()}, {path});
  }
  const std::string graph = "vertices 6\nedge 0 1\nedge 1 2\nedge 2 3\nedge 3 4\nedge 4 5\nedge 5 0\nedge 0 3\n"
                            "agent 0 3\nagent 3 0\n";
  for (const Mutant& m : mutants_of(graph, rng, 5)) {
    const std::string path = f.file("g-" + std::to_string(n++) + ".graph");
    spit(path, m.text);
    f.expect({"mapf", "--graph", path, "--time-limit", "5", "--out", f.out()}, {path}, {1});
  }
}

}  // namespace
