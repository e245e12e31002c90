// The launcher: one swarm run's processes from a scenario and flags (scenario + flags -> run
// directory -> the role processes -> supervise, supervisor.hpp). `swarm run` (tools/cli/run_command.hpp)
// adds pictures and a summary; `swarm experiment` reuses prepare_run and
// build_run_processes to start many runs at once (one run_processes call per run, each on its own
// thread; every concurrent run gets its own DDS domain, RunOptions::domain_id, and every run its
// own partition, so runs never hear each other), and RunOptions::customize to change scenario
// fields that have no flag.
//
//   swarm::tools::RunOptions o;           // what the flags said
//   o.overrides.groups = 2;
//   swarm::tools::PreparedRun run = swarm::tools::prepare_run(o);  // throws config::ConfigError
//   auto procs = swarm::tools::build_run_processes(run.launch, run.world.scenario);
//   auto result = swarm::tools::run_processes(procs, std::chrono::seconds(600));
//
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <ctime>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "supervisor.hpp"
#include "swarm/config/scenario.hpp"

namespace swarm::tools {

// Flags that override single scenario fields; unset = keep the file's value.
struct RunOverrides {
  std::optional<std::string> map;    // built-in name, YAML or MovingAI .map path (relative to the working dir)
  std::optional<double> map_resolution;  // metres per cell of a MovingAI .map
  std::optional<std::string> start;  // "X,Y" in metres, map frame
  std::optional<std::uint32_t> groups;
  std::optional<std::uint32_t> robots_per_group;
  std::optional<std::string> mode;  // group-frontier | baseline | ideal
  std::vector<std::string> mission;  // --mission explore,cover: the phases, with default settings
  std::optional<std::uint64_t> seed;
  std::optional<std::uint32_t> max_ticks;
  std::optional<bool> realtime;          // --realtime: ticks at a wall rate, delays in ms
  std::optional<std::uint32_t> tick_ms;  // --tick-ms
  // Fault injection: "member-G-I@T" (crash at tick T), "leader-G@A-B" (links cut A..B),
  // "leader-G@T+S" (process frozen at tick T for S seconds).
  std::vector<std::string> kills;
  std::vector<std::string> cuts;
  std::vector<std::string> freezes;
};

struct RunOptions {
  std::string scenario_path;  // "" = DATA/scenarios/default.pbtxt
  RunOverrides overrides;
  std::string out_dir;  // "" = runs/<YYYYmmdd-HHMMSS>-<map>-<mode>-s<seed>
  std::string mcap_path;  // "" = none; else `swarm run` writes the run's record there as MCAP at the end
  // `swarm run --view`: a live view of the run in the browser on view_bind:view_port while it runs.
  bool view = false;
  std::string view_bind = "127.0.0.1";
  int view_port = 8765;
  std::chrono::seconds timeout{600};
  std::string bin_dir;  // "" = the folder of the running executable
  // Changes further scenario fields after the flags are applied and before validation (how
  // `swarm experiment` sets link delays, loss, caps or the map encoding); empty = none.
  std::function<void(swarm::scenario::Scenario&)> customize;
  // The DDS domain of the run (0..kMaxDomainId); unset = domain_id_for(getpid()). Concurrent runs of one
  // `swarm` process each take their own.
  std::optional<int> domain_id;
  // Where the search for a free domain starts when domain_id is unset (swarm experiment spreads
  // its workers); unset = domain_id_for(getpid()).
  std::optional<int> preferred_domain;
  // How the run's processes find each other: through a Fast DDS discovery server of the run's own
  // (fast-discovery-server on a free loopback port, started first and stopped last), or by
  // simple discovery (every participant announces itself to every other; traffic grows with the
  // square of the process count).
  enum class Discovery { Server, Simple };
  Discovery discovery = Discovery::Server;
  // Robots of one group per member process (--agents-per-process): 1 = a process per robot.
  int agents_per_process = 1;
  // DDS-Security (--secure): a CA, one certificate per process and signed governance and
  // permissions are made in RUN_DIR/security (scripts/make-certs.sh), and every process
  // authenticates and encrypts; a participant without a certificate sees nothing. Uses simple
  // discovery (the discovery server has no certificate).
  bool secure = false;
  std::string partition;  // the run's DDS partition; "" = partition_name(pid, now): unique
};

// Where and how the role processes of one run talk and write.
// The certificate name of a watcher of a secure run (swarm run --view, swarm view --attach): every
// --secure run's RUN_DIR/security has one, granted to subscribe only (scripts/make-certs.sh).
inline constexpr const char* kViewerIdentity = "swarm-view";

struct RunLaunch {
  std::string run_dir;        // absolute
  std::string scenario_path;  // RUN_DIR/scenario.pbtxt
  std::string bin_dir;        // holds swarm-sim, swarm-gcs, swarm-leader, swarm-member
  int domain_id = 1;
  std::string partition;
  bool progress_bar = false;  // GCS: --progress bar (a terminal) or plain
  std::string discovery_server;  // "127.0.0.1:PORT" of the run's discovery server; "" = simple
  std::string discovery_server_exe;  // fast-discovery-server's path, when discovery_server is set
  std::string dds_profile;           // the Fast DDS profile every process (and the server) loads
  int agents_per_process = 1;        // member robots of one group per swarm-member process
  std::string security_dir;          // RUN_DIR/security with --secure, else ""
};

struct PreparedRun {
  swarm::config::World world;
  RunLaunch launch;
  // The run's hold on its DDS domain (an flock on TMP/swarm-dds-domain-<d>.lock): every role's
  // participant id is its agent id, so two runs in one domain would bind the same ports. Released
  // when the last copy of this PreparedRun goes (or by the kernel if swarm dies).
  std::shared_ptr<const void> domain_lock;
  // The run's hold on its directory (an flock on RUN_DIR/.lock), taken before anything is written
  // there: a second run into the same --out would write over the first's record as it writes.
  std::shared_ptr<const void> run_dir_lock;
};

// Applies `o` to `s`. A --map that differs from the scenario's map clears its start unless
// --start is given too. Throws config::ConfigError naming the flag for a malformed value
// (e.g. --start "3;4"); range checks are validate()'s.
void apply_overrides(swarm::scenario::Scenario& s, const RunOverrides& o);

// Loads the scenario, applies the flags and options.customize, validates and resolves the world
// and the mission; creates nothing (`swarm run --check`). Throws config::ConfigError.
[[nodiscard]] config::World resolve_run(const RunOptions& options);

// resolve_run, then creates the run directory (and RUN_DIR/logs) and writes RUN_DIR/scenario.pbtxt. A map given by
// a relative path is written as an absolute path, so the roles can read it from any folder.
// Throws config::ConfigError for every problem the user can fix (exit status 2), including a
// domain id out of range.
[[nodiscard]] PreparedRun prepare_run(const RunOptions& options);

// The processes of one run, named sim, gcs, leader-G and member-G-I (G = 0..groups-1,
// I = 1..robots_per_group-1; index 0 of a group is its leader), logs in RUN_DIR/logs/NAME.log.
[[nodiscard]] std::vector<ProcessSpec> build_run_processes(const RunLaunch& launch,
                                                           const swarm::scenario::Scenario& s);

// 1 + pid % kMaxDomainId: a DDS domain per swarm process, so runs started by different users or
// shells rarely share one (the partition separates them anyway).
[[nodiscard]] int domain_id_for(pid_t pid);
// The largest DDS domain id a run uses: with the profile's 500 ports per domain, every port of
// domains 0..48 (up to 240 participants each) is below 32768, out of the kernel's ephemeral range.
inline constexpr int kMaxDomainId = 48;
// Runs without --domain take a free one of 1..kAutoDomains; 41..48 are left to tests and to
// explicit --domain.
inline constexpr int kAutoDomains = 40;
// The run's discovery server listens on 127.0.0.1 at this port of its domain's block (past the
// 240 participants' ports): unique per domain, so per run.
[[nodiscard]] inline int discovery_server_port(int domain) { return 7400 + 500 * domain + 495; }
// "swarm-<pid>-<epoch-ns>": unique per run.
[[nodiscard]] std::string partition_name(pid_t pid, std::int64_t epoch_ns);
// "runs/<YYYYmmdd-HHMMSS>-<map>-<mode>-s<seed>" (local time; a YAML map shows as its stem).
[[nodiscard]] std::string default_run_dir(const swarm::scenario::Scenario& s, std::time_t now);
// "maze1" for a built-in map, the file stem for a YAML path ("map" if it has none).
[[nodiscard]] std::string map_label(const std::string& map);
// The folder of /proc/self/exe.
[[nodiscard]] std::string executable_dir();
}  // namespace swarm::tools
