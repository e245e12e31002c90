// The `swarm` subcommands other than `run` (see run_command.hpp). Each returns the process exit
// status and writes its messages to `out` / `err`.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "run_launch.hpp"
#include "view_server.hpp"
#include <vector>

namespace swarm::tools {

struct RenderOptions {
  std::string run_dir;
  std::optional<std::uint32_t> tick;  // set: a frontier snapshot at this tick
  std::string out_path;               // "" = RUN_DIR/map.png or RUN_DIR/frontiers-<T>.png
  int scale = 6;                      // pixels per cell
};

// `swarm render`: 0 on success; 2 when the run directory or its record is missing or damaged
// (or the picture cannot be written), with a message saying which.
int render_command(const RenderOptions& options, std::ostream& out, std::ostream& err);

struct ExportOptions {
  std::string run_dir;
  std::string mcap_path;
};

// `swarm export RUN_DIR --mcap FILE`: 0 when written; 2 when the run directory is not a run, its
// record is truncated or damaged, or the file cannot be written, with a message saying which.
int export_command(const ExportOptions& options, std::ostream& out, std::ostream& err);

struct ViewOptions {
  std::string run_dir;  // a replay; or, empty, --attach:
  bool attach = false;  // watch a running swarm (a deployment) live
  std::string scenario_path;  // its scenario: the map, team and tick length
  int domain = 0;
  std::string partition = "swarm";
  std::string discovery_server;  // HOST:PORT, or "" for simple discovery
  std::string profile;           // Fast DDS XML profile; "" = config::dds_profile_path()
  std::string security_dir;      // DDS-Security: the swarm's certificates (scripts/make-certs.sh); "" = none
  std::string identity = kViewerIdentity;  // the watcher's certificate in it (NAME.pem, NAME.key)
  ViewServerOptions server;
};

// `swarm view RUN_DIR` serves the run's replay page, `swarm view --attach --scenario FILE ...` a
// live view of a running swarm, until Ctrl-C: 0 then; 2 when the run directory is not a run, its
// record is truncated or damaged, the scenario does not load, or the address cannot be listened
// on; 1 when the DDS participant cannot be made.
int view_command(const ViewOptions& options, std::ostream& out, std::ostream& err);

// `swarm bench [SUITE] [Google Benchmark flags]`: with no suite runs swarm-bench-planner (ray
// casting rays/s, A*) and swarm-bench-mission (lockstep ticks/s of the default 11-process mission)
// from `bin_dir`, one after the other; or the one suite named: planner, mission, tour (the tour GA,
// exact orders, plowing and Group-k), mapf (the MAPF solvers on the MovingAI benchmark; minutes),
// darp (DARP and STC on data/darp beside the reference's figures).
// 0 when they ran, 1 when one failed, 2 when one is not built.
int bench_command(const std::string& bin_dir, const std::vector<std::string>& args,
                  std::ostream& err);

}  // namespace swarm::tools
