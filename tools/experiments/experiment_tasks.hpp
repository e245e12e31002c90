// `swarm experiment cover` and `swarm experiment mapf-live`: live runs of one task (every role its
// own process over real DDS, through the same runner as `swarm run`), swept over the team size and
// the links, with each variant of the task side by side. Written into --out DIR (default
// runs/experiment-<task>-<time>): table.txt, results.csv (one row per run), results.json (runs and
// aggregates), and <task>.png (one panel per sweep, mean ± std over seeds).
//
//   cover      the map given (cover alone, on `small` by default); variants hierarchical | flat;
//              sweeps: robots 3, 6, 9, 12 (groups of 3); member<->leader delay 0, 2, 5, 10 ticks;
//              loss on every link 0, 5, 10 %. Numbers: the simulator's makespan (ticks until
//              every reachable cell was covered), coverage, executed path length and turns.
//   mapf-live  random goals on `small` by default; variants ECBS driven by the action-dependency
//              graph (ecbs-adg) or by the plan's timing (ecbs-timed), LaCAM by the graph
//              (lacam-adg); sweeps: member<->leader delay 0, 1, 3, 6, 10 ticks with jitter of half
//              of it; member<->leader loss 0, 5, 20 %; robots 4, 6, 9, 12. Numbers: planned
//              makespan, the executed one (first move to last), conflicts, blocked moves.
//
// Each sweep's other settings are the base ones (2 groups x 3, no delay, no loss). Exit status 0
// when the runs were made (a failed or incomplete run is a table entry, not an error), 2 on bad
// input, 1 when the outputs cannot be written.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace swarm::tools {

struct TaskExperimentOptions {
  std::string task;          // "cover" | "mapf-live"
  std::string map = "small";
  std::int64_t seeds = 2;    // seeds 1..N per point and variant
  std::int64_t jobs = 2;     // runs at once
  long timeout_s = 600;      // per run
  bool quick = false;        // only the first two points of the first sweep (tests)
  std::string out_dir;
};

int task_experiment(const TaskExperimentOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
