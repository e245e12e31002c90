// `swarm run`: the launcher's run (launcher/run_launch.hpp), then pictures and a summary.
//
// Exit statuses of run_command: 0 the mission is complete; 3 it ran but is incomplete (max_ticks
// reached, or a phase given up: the summary and metrics.json say which); 1 a process failed, the
// wall-clock timeout, or missing outputs; 2 a bad flag or scenario (ConfigError) or an unusable
// run directory; 130 interrupted.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "run_launch.hpp"

namespace swarm::tools {

inline constexpr int kExitIncomplete = 3;

// The last `n` lines of a text file (fewer if it is shorter; none if it cannot be read).
[[nodiscard]] std::vector<std::string> last_lines(const std::string& path, int n);

// After a successful run: the headline numbers of RUN_DIR/metrics.json as the GCS writes it
// (steps, steps_to_99, planning_rounds, explored_fraction, complete, wall_seconds,
// ticks_per_second, traffic.total.bytes / .messages), as a few lines for a person. Keys that are
// missing or null are left out. Throws std::runtime_error if the file is missing or not JSON.
[[nodiscard]] std::string summarize_metrics(const std::string& metrics_json_path);

// "512 B", "3.41 kB", "5.82 MB": byte counts for people (powers of 1000).
[[nodiscard]] std::string format_bytes(double bytes);

// The whole `swarm run`: returns the process exit status; messages go to `out` and `err`.
int run_command(const RunOptions& options, std::ostream& out, std::ostream& err);

// `swarm run --check`: the scenario and flags checked and the world resolved (map, start, robots'
// cells, the mission's goals and objects) as a run would, then one line of what would run.
// Nothing is created or started. 0 when it would run, 2 when not (the message says why).
int check_run_command(const RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
