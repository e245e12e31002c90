// The `swarm` subcommands other than `run` (see run_command.hpp). Each returns the process exit
// status and writes its messages to `out` / `err`.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
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

// `swarm bench`: replaces this process with swarm-bench-planner from `bin_dir`, passing `args`;
// returns 2 (with a message) only when that binary is not there.
int bench_command(const std::string& bin_dir, const std::vector<std::string>& args,
                  std::ostream& err);

}  // namespace swarm::tools
