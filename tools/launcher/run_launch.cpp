#include "run_launch.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "format.hpp"
#include "swarm/tasks/registry.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
namespace cfg = swarm::config;

bool is_builtin_map(const std::string& map) {
  const auto names = cfg::builtin_map_names();
  return std::find(names.begin(), names.end(), map) != names.end();
}

// "3.5,4" -> (3.5, 4); nullopt when malformed.
std::optional<std::pair<double, double>> parse_xy(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  auto number = [](const std::string& s) -> std::optional<double> {
    if (s.empty()) return std::nullopt;
    std::size_t used = 0;
    try {
      const double v = std::stod(s, &used);
      if (used != s.size() || !std::isfinite(v)) return std::nullopt;
      return v;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  };
  const auto x = number(text.substr(0, comma));
  const auto y = number(text.substr(comma + 1));
  if (!x || !y) return std::nullopt;
  return std::make_pair(*x, *y);
}


// The lock file of DDS domain `d` held (flock, exclusive) by this process, or nullptr when another
// run holds it. O_CLOEXEC: the role processes do not inherit it.
// An exclusive flock on `path` (created if missing), held while the returned pointer lives; null
// when another process holds it.
std::shared_ptr<const void> try_lock_file(const fs::path& path, const char* what) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error(std::string("cannot open the ") + what + " " + path.string() + ": " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return nullptr;
  }
  // The pointer must not be null (a null shared_ptr reads as "no lock"): it holds the fd.
  return std::shared_ptr<const void>(new int(fd), [](const void* p) {
    const int* held = static_cast<const int*>(p);
    ::close(*held);
    delete held;
  });
}

std::shared_ptr<const void> try_lock_domain(int d) {
  return try_lock_file(fs::temp_directory_path() / ("swarm-dds-domain-" + std::to_string(d) + ".lock"), "domain lock");
}

// The executable `name` on $PATH (execv does not search it); "" when there is none.
std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return "";
}

// --secure: one certificate per process of the run (the names build_run_processes gives them)
// and the signed governance and permissions, by scripts/make-certs.sh, in RUN_DIR/security.
void make_certificates(RunLaunch& l, const swarm::scenario::Scenario& s);

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) {
    throw cfg::ConfigError("cannot write " + path + " (" + std::strerror(errno) +
                           "); choose a writable run directory with --out DIR");
  }
}

// A tick written in a fault flag; one too large for a tick is a bad flag, not a crash.
std::uint32_t tick_of(const std::string& digits) {
  const unsigned long long v = digits.size() > 10 ? ~0ULL : std::stoull(digits);
  if (v > 0xFFFFFFFFULL) throw cfg::ConfigError("tick " + digits + " is too large (at most 4294967295)");
  return static_cast<std::uint32_t>(v);
}

// Each value of a fault flag is AGENT then `form_after_agent`; `fill` sets the fault from the match
// (group 1 is the agent).
template <class Fill>
void add_faults(swarm::scenario::Scenario& s, const char* flag, const std::vector<std::string>& values,
                const std::string& form_after_agent, const char* expected, Fill fill) {
  const std::regex form(R"(([a-z]+(?:-[0-9]+(?:-[0-9]+)?)?))" + form_after_agent);
  for (const std::string& v : values) {
    std::smatch m;
    if (!std::regex_match(v, m, form)) {
      throw cfg::ConfigError(std::string(flag) + ": expected " + expected + " (got '" + v + "')");
    }
    auto* f = s.add_faults();
    f->set_agent(m[1]);
    try {
      fill(*f, m);
    } catch (const cfg::ConfigError& e) {
      throw cfg::ConfigError(std::string(flag) + " " + v + ": " + e.what());
    }
  }
}

}  // namespace



void apply_overrides(swarm::scenario::Scenario& s, const RunOverrides& o) {
  if (o.map) {
    std::string map = *o.map;
    // A path on the command line is relative to the working directory, not the scenario file.
    if (!is_builtin_map(map)) map = fs::absolute(map).lexically_normal().string();
    if (map != s.map() && !o.start) s.clear_start();
    s.set_map(map);
  }
  if (o.start) {
    const auto xy = parse_xy(*o.start);
    if (!xy) {
      throw cfg::ConfigError(
          "--start: expected X,Y in metres in the map frame, e.g. --start 3.5,4 (got '" +
          *o.start + "')");
    }
    s.mutable_start()->set_x(xy->first);
    s.mutable_start()->set_y(xy->second);
  }
  if (o.map_resolution) s.set_map_resolution_m(*o.map_resolution);
  if (o.groups) s.set_groups(*o.groups);
  if (o.robots_per_group) s.set_robots_per_group(*o.robots_per_group);
  if (o.mode) s.mutable_explore()->set_mode(cfg::parse_mode(*o.mode));
  if (!o.mission.empty()) {
    try {
      cfg::set_mission(s, o.mission);
    } catch (const cfg::ConfigError& e) {
      throw cfg::ConfigError(std::string("--mission: ") + e.what());
    }
  }
  if (o.seed) s.set_seed(*o.seed);
  if (o.max_ticks) {
    s.set_max_ticks(*o.max_ticks);
  } else if (o.mission.size() > 1) {
    // A chained mission from the command line gets the scenario's limit per phase: a chain that is
    // still making progress is not cut off at one phase's limit (one that is not is ended as
    // stalled, Scenario.stall_ticks).
    s.set_max_ticks(s.max_ticks() * static_cast<std::uint32_t>(o.mission.size()));
  }
  if (o.realtime) s.set_realtime(*o.realtime);
  if (o.tick_ms) s.set_tick_ms(*o.tick_ms);
  // Names are checked against the run's groups by validate(); here only the shape.
  using Match = std::smatch;
  using Fault = swarm::scenario::Fault;
  add_faults(s, "--kill", o.kills, R"(@(?:tick:)?([0-9]+)(?:\+([0-9]{1,6}(?:\.[0-9]+)?)s?)?)",
             "AGENT@TICK, e.g. --kill member-1-2@100, or gcs@TICK+SECONDS (restarted after SECONDS), e.g. --kill gcs@40+2",
             [](Fault& f, const Match& m) {
               f.set_kill_at_tick(tick_of(m[2]));
               if (m[3].matched) f.set_restart_after_seconds(std::stod(m[3]));
             });
  add_faults(s, "--cut", o.cuts, R"(@(?:tick:)?([0-9]+)-([0-9]+))", "AGENT@FROM-TO, e.g. --cut leader-1@80-180",
             [](Fault& f, const Match& m) {
               f.set_cut_from_tick(tick_of(m[2]));
               f.set_cut_to_tick(tick_of(m[3]));
             });
  add_faults(s, "--freeze", o.freezes, R"(@(?:tick:)?([0-9]+)\+([0-9]{1,6}(?:\.[0-9]+)?)s?)",
             "AGENT@TICK+SECONDS, e.g. --freeze leader-1@80+10", [](Fault& f, const Match& m) {
               f.set_freeze_at_tick(tick_of(m[2]));
               f.set_freeze_seconds(std::stod(m[3]));
             });
}

cfg::World resolve_run(const RunOptions& options) {
  const std::string scenario_path =
      options.scenario_path.empty()
          ? (fs::path(cfg::data_dir()) / "scenarios" / "default.pbtxt").string()
          : options.scenario_path;
  swarm::scenario::Scenario s = cfg::load_scenario(scenario_path);
  const std::string scenario_dir = fs::absolute(scenario_path).parent_path().string();
  apply_overrides(s, options.overrides);
  if (options.customize) options.customize(s);
  cfg::validate(s, scenario_path + " (with the command-line flags)");

  // A start from the command line is the flag's to answer for, not the scenario file's alone.
  const std::string start_source =
      options.overrides.start ? scenario_path + " with --start " + *options.overrides.start : scenario_path;
  cfg::World world = cfg::resolve_world(s, scenario_dir, start_source);
  swarm::tasks::resolve_mission(world, scenario_path);
  return world;
}

PreparedRun prepare_run(const RunOptions& options) {
  PreparedRun run{resolve_run(options), {}, {}, {}};
  swarm::scenario::Scenario& used = run.world.scenario;
  // The roles read RUN_DIR/scenario.pbtxt, whose folder is the run directory: a map file must
  // be named absolutely there.
  if (!is_builtin_map(used.map())) used.set_map(fs::absolute(run.world.map_path).string());

  const std::string dir =
      options.out_dir.empty() ? default_run_dir(used, std::time(nullptr)) : options.out_dir;
  RunLaunch& l = run.launch;
  l.run_dir = fs::absolute(dir).lexically_normal().string();
  if (!l.run_dir.empty() && l.run_dir.size() > 1 && l.run_dir.back() == '/') l.run_dir.pop_back();
  std::error_code ec;
  fs::create_directories(fs::path(l.run_dir) / "logs", ec);
  if (ec) {
    throw cfg::ConfigError("cannot create the run directory " + l.run_dir + " (" + ec.message() +
                           "); choose another with --out DIR");
  }
  run.run_dir_lock = try_lock_file(fs::path(l.run_dir) / ".lock", "run directory lock");
  if (!run.run_dir_lock) {
    throw cfg::ConfigError("--out " + l.run_dir + ": another swarm run is writing to this directory; choose another --out");
  }
  // A run into a directory an earlier run left: its results must not be taken for this run's
  // (a run that ends early has its metrics.json amended, or written from the record).
  for (const char* old : {"metrics.json", "run.pb", "map.png"}) fs::remove(fs::path(l.run_dir) / old, ec);
  l.scenario_path = (fs::path(l.run_dir) / "scenario.pbtxt").string();
  write_text_file(l.scenario_path, cfg::to_text(used));

  l.bin_dir = options.bin_dir.empty() ? executable_dir() : options.bin_dir;
  const pid_t pid = ::getpid();
  // Domain 0 is the discovery servers' own (their participants bind its ports): runs use 1..48.
  if (options.domain_id && (*options.domain_id < 1 || *options.domain_id > kMaxDomainId)) {
    throw cfg::ConfigError("DDS domain id " + std::to_string(*options.domain_id) +
                           " is out of range; swarm runs use 1.." +
                           std::to_string(kMaxDomainId));
  }
  if (options.domain_id) {
    run.domain_lock = try_lock_domain(*options.domain_id);
    if (!run.domain_lock) {
      throw cfg::ConfigError("DDS domain " + std::to_string(*options.domain_id) +
                             " is in use by another swarm run on this machine; choose another --domain or leave it out");
    }
    l.domain_id = *options.domain_id;
  } else {
    const int first = options.preferred_domain.value_or(domain_id_for(pid));
    for (int k = 0; k < kAutoDomains && !run.domain_lock; ++k) {
      l.domain_id = 1 + (first - 1 + k) % kAutoDomains;
      run.domain_lock = try_lock_domain(l.domain_id);
    }
    if (!run.domain_lock) {
      throw std::runtime_error("every DDS domain 1.." + std::to_string(kAutoDomains) +
                               " is in use by other swarm runs on this machine");
    }
  }
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                      std::chrono::system_clock::now().time_since_epoch())
                      .count();
  l.partition = options.partition.empty() ? partition_name(pid, static_cast<std::int64_t>(ns)) : options.partition;
  l.progress_bar = ::isatty(STDOUT_FILENO) != 0;
  l.dds_profile = cfg::dds_profile_path();
  if (options.agents_per_process < 1) {
    throw cfg::ConfigError("--agents-per-process must be at least 1 (got " +
                           std::to_string(options.agents_per_process) + ")");
  }
  l.agents_per_process = options.agents_per_process;
  if (l.agents_per_process > 1) {
    // A robot that shares its process cannot be killed or frozen alone: its process has another name.
    const std::vector<ProcessSpec> procs = build_run_processes(l, used);
    const auto alone = [&](const std::string& agent) {
      return std::any_of(procs.begin(), procs.end(), [&](const ProcessSpec& p) { return p.name == agent; });
    };
    for (const auto& f : used.faults()) {
      if ((f.has_kill_at_tick() || f.has_freeze_at_tick()) && !alone(f.agent())) {
        throw cfg::ConfigError("a kill or freeze of " + f.agent() +
                               " stops its whole process, and --agents-per-process " +
                               std::to_string(l.agents_per_process) +
                               " puts other robots in it: use --agents-per-process 1 with it");
      }
    }
  }
  if (options.discovery == RunOptions::Discovery::Server && !options.secure) {
    l.discovery_server_exe = find_on_path("fast-discovery-server");
    if (l.discovery_server_exe.empty()) {
      throw cfg::ConfigError(
          "fast-discovery-server is not on PATH: install Debian's fastdds-tools (scripts/install-deps.sh "
          "does), or run with --discovery simple");
    }
    l.discovery_server = "127.0.0.1:" + std::to_string(discovery_server_port(l.domain_id));
  }
  if (options.secure) make_certificates(l, used);
  return run;
}

std::vector<ProcessSpec> build_run_processes(const RunLaunch& l,
                                             const swarm::scenario::Scenario& s) {
  const fs::path bin(l.bin_dir);
  const fs::path logs = fs::path(l.run_dir) / "logs";
  std::vector<std::string> common = {"--scenario", l.scenario_path,
                                           "--run-dir",  l.run_dir,
                                           "--domain",   std::to_string(l.domain_id),
                                           "--partition", l.partition};
  auto spec = [&](const std::string& name, const std::string& exe,
                  const std::vector<std::string>& role_args) {
    ProcessSpec p;
    p.name = name;
    p.argv = {(bin / exe).string()};
    p.argv.insert(p.argv.end(), role_args.begin(), role_args.end());
    p.argv.insert(p.argv.end(), common.begin(), common.end());
    p.log_path = (logs / (name + ".log")).string();
    return p;
  };
  std::vector<ProcessSpec> procs;
  if (!l.discovery_server.empty()) {
    // Loopback only: the profile's server participant binds 127.0.0.1 and nothing else.
    const std::string port = l.discovery_server.substr(l.discovery_server.rfind(':') + 1);
    ProcessSpec server;
    server.name = "discovery";
    server.argv = {l.discovery_server_exe, "-i", "0", "-l", "127.0.0.1", "-p", port,
                   "-x", "swarm_discovery_server@" + l.dds_profile};
    server.log_path = (logs / "discovery.log").string();
    server.service = true;
    procs.push_back(std::move(server));
    common.push_back("--discovery-server");
    common.push_back(l.discovery_server);
  }
  if (!l.security_dir.empty()) {
    common.push_back("--security-dir");
    common.push_back(l.security_dir);
  }
  procs.push_back(spec("sim", "swarm-sim", {}));
  procs.back().ends_run = true;  // a stop asked of the run reaches the simulator first
  ProcessSpec gcs = spec("gcs", "swarm-gcs", {});
  gcs.argv.push_back("--progress");
  gcs.argv.push_back(l.progress_bar ? "bar" : "plain");
  gcs.echo_stdout = true;
  procs.push_back(std::move(gcs));
  for (std::uint32_t g = 0; g < s.groups(); ++g) {
    const std::string gs = std::to_string(g);
    procs.push_back(spec("leader-" + gs, "swarm-leader", {"--group", gs}));
  }
  // Members in chunks of agents_per_process consecutive robots of one group: "member-1-2" alone,
  // "members-1-1-3" for robots 1..3 of group 1.
  const std::uint32_t chunk = static_cast<std::uint32_t>(std::max(1, l.agents_per_process));
  for (std::uint32_t g = 0; g < s.groups(); ++g) {
    for (std::uint32_t first = 1; first < s.robots_per_group(); first += chunk) {
      const std::uint32_t last = std::min(s.robots_per_group() - 1, first + chunk - 1);
      std::string indices;
      for (std::uint32_t i = first; i <= last; ++i) indices += (i == first ? "" : ",") + std::to_string(i);
      const std::string gs = std::to_string(g);
      const std::string name = cfg::member_process_name(static_cast<int>(g), static_cast<int>(first), static_cast<int>(last));
      procs.push_back(spec(name, "swarm-member", {"--group", gs, "--index", indices}));
    }
  }
  for (const auto& f : s.faults()) {
    for (ProcessSpec& p : procs) {
      if (p.name != f.agent() || !f.has_kill_at_tick()) continue;
      p.killed_on_purpose = true;
      if (f.has_restart_after_seconds()) {
        // The GCS: started again, to resume from its journal (gcs/gcs_node.hpp "Restart").
        p.restart_after = std::chrono::milliseconds(static_cast<long long>(1000 * f.restart_after_seconds()));
        p.restart_argv = p.argv;
        p.restart_argv.push_back("--resume");
      }
    }
  }
  return procs;
}

namespace {
void make_certificates(RunLaunch& l, const swarm::scenario::Scenario& s) {
  const std::string dir = l.run_dir + "/security";
  ProcessSpec certs;
  certs.name = "make-certs";
  certs.argv = {"/bin/bash", cfg::data_dir() + "/scripts/make-certs.sh", dir};
  for (const ProcessSpec& p : build_run_processes(l, s)) {
    if (!p.service) certs.argv.push_back(p.name);
  }
  // A watcher's certificate too (swarm run --view, swarm view --attach): subscribe only.
  certs.argv.push_back("--read-only");
  certs.argv.push_back(kViewerIdentity);
  certs.log_path = l.run_dir + "/logs/make-certs.log";
  if (!run_processes({certs}, std::chrono::seconds(120)).ok) {
    throw std::runtime_error("could not make the run's certificates (scripts/make-certs.sh; see " + certs.log_path + ")");
  }
  l.security_dir = dir;
}
}  // namespace

std::string map_label(const std::string& map) {
  if (is_builtin_map(map)) return map;
  const std::string stem = fs::path(map).stem().string();
  return stem.empty() ? "map" : stem;
}

int domain_id_for(pid_t pid) { return 1 + static_cast<int>(pid % kMaxDomainId); }

std::string partition_name(pid_t pid, std::int64_t epoch_ns) {
  return "swarm-" + std::to_string(pid) + "-" + std::to_string(epoch_ns);
}

std::string default_run_dir(const swarm::scenario::Scenario& s, std::time_t now) {
  return "runs/" + local_timestamp(now) + "-" + map_label(s.map()) + "-" +
         cfg::mode_name(s.explore().mode()) + "-s" + std::to_string(s.seed());
}

std::string executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return ".";
  return exe.parent_path().string();
}

}  // namespace swarm::tools
