// `swarm experiment mapf`: the MAPF solvers side by side, offline (no swarm is started).
//
//   (a) the paper's Tables 1 and 2 (docs/papers.md section 3) on its warehouse world (warehouse-5x8):
//       5, 10, 15, 20, 25 robots x --runs random instances; collisions, work time and stop time
//       per robot, compute time, for CBS (the paper's rule: a timed-out CBS returns its last
//       constraint-tree node), the two-stage GA, the single-stage GA, ECBS and LaCAM*; a table,
//       a plot (paper.png), and whether the paper's claims hold (two-stage beats single-stage;
//       CBS's time-outs leave more collisions than the GA) — yes or NO, with the numbers.
//   (b) the field's standard view on the MovingAI maps (--movingai DIR, its *.map files and their
//       -random-1..5 scenarios): success rate and sum of costs / lower bound against the number of
//       agents within --time-limit, for cbs, ecbs and lacam; one plot per map (movingai-<map>.png).
//       A solver that solves none of the scenarios at some count is not run at larger counts.
//
// Defaults fit about 10 minutes on 2 cores; the paper's settings: --runs 100 --cbs-limit 600.
// Writes results.csv (one row per run), results.json, table.txt and the plots into --out DIR
// (default runs/experiment-mapf-<time>), with a progress line per finished run.
// Exit 0 when it ran, 2 on bad input (an unknown part or solver, a missing --movingai folder).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace swarm::tools {

struct MapfExperimentOptions {
  std::string part = "all";                  // paper | movingai | all
  std::string warehouse = "warehouse-5x8";   // (a): the world (warehouse-RxC)
  std::vector<int> robots = {5, 10, 15, 20, 25};
  int runs = 10;                             // (a): random instances per robot count (paper: 100)
  double cbs_limit_s = 10;                   // (a): time limit of every solver (paper's CBS: 600)
  std::vector<std::string> paper_solvers = {"cbs", "ga", "ga1", "ecbs", "lacam"};
  std::string movingai_dir = "data/movingai";  // (b)
  std::vector<std::string> maps;             // (b): map stems; empty = every .map in the folder
  std::vector<int> agents = {10, 20, 30, 40, 50, 100};  // (b): agent counts
  int scenarios = 5;                         // (b): random-1 .. random-N
  double time_limit_s = 10;                  // (b)
  std::vector<std::string> movingai_solvers = {"cbs", "ecbs", "lacam"};
  double w = 1.2;                            // ecbs
  int jobs = 2;                              // solves at once
  std::uint64_t seed = 1;                    // (a): instance r uses seed + r
  std::string out_dir;
  // GA overrides (ga.hpp), 0 / negative = default.
  int ga_population = 0, ga_generations1 = -1, ga_generations2 = -1, ga_elite = -1, ga_initial_idle = -1;
  double ga_crossover = -1, ga_mutation = -1;
};

int experiment_mapf_command(const MapfExperimentOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
