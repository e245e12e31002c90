// What the offline planning commands share (`swarm tour`, `swarm clean` and their experiments):
// the bad-input exception that becomes exit status 2, the output directory, a picture scale, number
// formatting and a small pool that runs independent jobs on several threads with progress lines.
//
//   const std::string dir = make_out_dir(options.out_dir, "tour-scenario1");  // runs/tour-scenario1-<time>
//   run_jobs(jobs.size(), 2, [&](std::size_t i) { results[i] = solve(jobs[i]); },
//            [&](std::size_t i, std::size_t done) { out << "[" << done << "/" << n << "] ...\n"; });
//
// Thread-safety: run_jobs calls `work` from several threads at once (each index once) and
// `finished` from one thread at a time.
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>

#include "format.hpp"
#include "swarm/planner/grid/grid.hpp"

namespace swarm::tools {

// Bad input on the command line or in a file: exit status 2, the message says what is wrong.
struct OfflineBadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The absolute output directory, created: `requested`, or runs/<fallback>-<YYYYmmdd-HHMMSS>.
// Throws OfflineBadInput naming the directory when it cannot be created.
[[nodiscard]] std::string make_out_dir(const std::string& requested, const std::string& fallback);

// Pixels per cell for a picture about 640 pixels across (4..40).
[[nodiscard]] int picture_scale(const planner::OccupancyGrid& map);

// The end of an offline experiment: prints the table, writes table.txt, results.csv, results.json
// and the figures into `dir` (experiment.hpp write_outputs), says where; 0, or 1 (with a message
// on `err`) when a file cannot be written.
struct ExperimentOutputs;
int finish_experiment(const std::string& dir, const ExperimentOutputs& outputs, const char* me,
                      std::ostream& out, std::ostream& err);

// Runs work(0..n-1) on up to `threads` threads; after each job, finished(index, jobs done so far)
// under a lock. An exception in a job is rethrown (the first one) after every thread stops.
void run_jobs(std::size_t n, std::size_t threads, const std::function<void(std::size_t)>& work,
              const std::function<void(std::size_t, std::size_t)>& finished);

}  // namespace swarm::tools
