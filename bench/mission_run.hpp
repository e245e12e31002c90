// One whole `swarm run` mission as a benchmark iteration, shared by the mission and scale suites:
// started exactly as `swarm run` starts it (prepare_run -> build_run_processes -> run_processes),
// timed from launch, its metrics.json read back.
#pragma once

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "live_run_view.hpp"
#include "run_launch.hpp"

namespace swarm::bench {

struct MissionTiming {
  double ticks = 0;          // ticks the lockstep loop ran
  double loop_seconds = 0;   // tick 0 to the end (the GCS's wall_seconds)
  double total_seconds = 0;  // launch to the last process's exit
  // Launch to tick 0: discovery and start-up (total minus the loop; includes the short shutdown).
  double startup_seconds() const { return total_seconds - loop_seconds; }
};

// Runs the mission `options` describes (its out_dir is set here, under `root`); nullopt and
// `error` set when a process failed or the metrics are missing.
inline std::optional<MissionTiming> run_mission(tools::RunOptions options, const std::filesystem::path& root,
                                                int run, std::string& error) {
  options.out_dir = (root / std::to_string(run)).string();
  const auto start = std::chrono::steady_clock::now();
  const tools::PreparedRun prepared = tools::prepare_run(options);
  auto processes = tools::build_run_processes(prepared.launch, prepared.world.scenario);
  for (auto& p : processes) p.echo_stdout = false;
  tools::LiveRunView view;  // with options.view: watched live, as `swarm run --view` does
  if (options.view) {
    std::ostringstream quiet;
    if (view.start(options, prepared, quiet, quiet) != 0) {
      error = "the live view did not start: " + quiet.str();
      return std::nullopt;
    }
  }
  const auto result = tools::run_processes(processes, options.timeout);
  view.stop();
  MissionTiming t;
  t.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.ok) {
    error = "the mission failed: " + result.message + " (logs in " + prepared.launch.run_dir + "/logs)";
    return std::nullopt;
  }
  std::ifstream in(prepared.launch.run_dir + "/metrics.json");
  if (!in) {
    error = "no metrics.json in " + prepared.launch.run_dir;
    return std::nullopt;
  }
  const auto m = nlohmann::json::parse(in);
  t.loop_seconds = m.at("wall_seconds").get<double>();
  t.ticks = m.at("ticks_run").get<double>();
  return t;
}

}  // namespace swarm::bench
