#include "commands.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>

#include "swarm/record/record.hpp"
#include "swarm/record/render.hpp"

namespace swarm::tools {

namespace fs = std::filesystem;

int render_command(const RenderOptions& o, std::ostream& out, std::ostream& err) {
  std::error_code ec;
  if (!fs::is_directory(o.run_dir, ec)) {
    err << "swarm render: " << o.run_dir
        << " is not a directory; give a run directory written by `swarm run` (runs/...)\n";
    return 2;
  }
  const std::string record = swarm::record::run_record_path(o.run_dir);
  if (!fs::exists(record, ec)) {
    err << "swarm render: " << o.run_dir << " has no " << swarm::record::kRunRecordFile
        << "; did the run finish? (its logs are in " << (fs::path(o.run_dir) / "logs").string()
        << ")\n";
    return 2;
  }
  std::string png = o.out_path;
  swarm::record::RecordPrefix read;
  try {
    read = swarm::record::read_record_prefix(record);
  } catch (const std::exception& e) {
    err << "swarm render: " << e.what() << "\n";
    return 2;
  }
  const auto& frames = read.frames;
  const std::optional<std::uint32_t> last_tick = swarm::record::last_tick(frames);
  if (!read.cut.empty()) {
    err << "swarm render: " << read.cut << "; drawing the " << frames.size() << " whole frames before it"
        << (last_tick ? " (up to tick " + std::to_string(*last_tick) + ")" : std::string()) << "\n";
  }
  if (o.tick && (!last_tick || *o.tick > *last_tick)) {
    err << "swarm render: --tick " << *o.tick << ": " << record << " "
        << (last_tick ? "holds ticks 0.." + std::to_string(*last_tick) : std::string("holds no tick")) << "\n";
    return 2;
  }
  try {
    if (o.tick) {
      if (png.empty()) {
        png = (fs::path(o.run_dir) / ("frontiers-" + std::to_string(*o.tick) + ".png")).string();
      }
      swarm::record::render_frontier_png(frames, *o.tick, png, o.scale);
    } else {
      if (png.empty()) png = (fs::path(o.run_dir) / "map.png").string();
      swarm::record::render_map_png(frames, png, o.scale);
    }
  } catch (const std::exception& e) {
    err << "swarm render: " << record << ": " << e.what() << "\n";
    return 2;
  }
  out << png << "\n";
  return 0;
}

int bench_command(const std::string& bin_dir, const std::vector<std::string>& args,
                  std::ostream& err) {
  // `swarm bench [SUITE] [Google Benchmark flags...]`: planner and mission by default; the others
  // (tour, mapf, darp, scale, traffic) only on request (mapf and scale take minutes).
  static const std::vector<std::string> kSuites = {"planner", "mission", "tour", "mapf", "darp", "scale", "traffic"};
  std::vector<std::string> suites{"planner", "mission"};
  std::vector<std::string> pass = args;
  if (!pass.empty() && std::find(kSuites.begin(), kSuites.end(), pass.front()) != kSuites.end()) {
    suites = {pass.front()};
    pass.erase(pass.begin());
  }
  for (const std::string& suite : suites) {
    const std::string exe = (fs::path(bin_dir) / ("swarm-bench-" + suite)).string();
    if (::access(exe.c_str(), X_OK) != 0) {
      err << "swarm bench: " << exe << " is not built; configure with -DSWARM_BUILD_BENCH=ON\n";
      return 2;
    }
    std::vector<char*> argv{const_cast<char*>(exe.c_str())};
    for (const std::string& a : pass) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    err.flush();
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::execv(exe.c_str(), argv.data());
      std::perror("swarm bench: exec");
      ::_exit(127);
    }
    int status = 0;
    if (pid < 0 || ::waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      err << "swarm bench: " << suite << " benchmarks failed\n";
      return 1;
    }
  }
  return 0;
}

}  // namespace swarm::tools
