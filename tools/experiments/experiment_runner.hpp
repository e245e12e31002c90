// Runs many `swarm run`s at once, each isolated, and reports each as it finishes: the engine of
// `swarm experiment`. Every job goes through prepare_run -> build_run_processes -> run_processes
// (run_command.hpp), exactly as `swarm run` does, on one of `jobs` worker threads. Worker w starts
// its runs' search for a free DDS domain at first_domain + w; prepare_run's domain locks make
// sure no two concurrent runs on the machine share one, and give every run its own partition. The GCS's progress is
// not echoed (it stays in logs/gcs.log).
//
//   std::vector<swarm::tools::RunJob> jobs = ...;  // RunOptions: out_dir, overrides, customize
//   swarm::tools::RunnerOptions r;
//   r.jobs = 2;
//   r.on_finished = [](std::size_t i, const RunOutcome& o) { std::cout << o.run_dir << "\n"; };
//   std::vector<swarm::tools::RunOutcome> outcomes = swarm::tools::run_jobs(jobs, r);
//
// A failed run (a process failed, the timeout passed, a bad scenario, no metrics) is an outcome
// with ok = false, never an exception, and the others go on. SIGINT/SIGTERM stop the runs in
// flight (run_processes) and no further run starts; those outcomes have interrupted = true.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace swarm::tools {

struct RunJob {
  RunOptions options;     // out_dir must be set
  bool pictures = false;  // after success: map.png and frontiers-<T>.png at the middle tick
};

struct RunOutcome {
  bool ok = false;
  bool interrupted = false;  // stopped by a signal, or never started because of one
  std::string run_dir;       // absolute ("" if the run directory was never created)
  std::string message;       // why it failed, one line
  std::string log_path;      // the failed process's log, when one failed
  double wall_seconds = 0;
  std::vector<std::string> pictures;  // written PNGs
  std::string picture_error;          // a picture that could not be drawn (the run is still ok)
};

struct RunnerOptions {
  int jobs = 1;          // runs at once (>= 1)
  int first_domain = 1;  // DDS domain of worker 0
  // Called from the worker thread, one call at a time (serialised), as each run ends.
  std::function<void(std::size_t index, const RunOutcome& outcome)> on_finished;
};

// Runs every job; returns their outcomes in job order.
[[nodiscard]] std::vector<RunOutcome> run_jobs(const std::vector<RunJob>& jobs,
                                               const RunnerOptions& options);

// The frontier snapshot tick of a run: the middle of its steps (at least 1).
[[nodiscard]] std::uint32_t middle_tick(double steps);

}  // namespace swarm::tools
