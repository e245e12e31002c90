// `swarm experiment darp`: the DARP paper's comparisons (docs/papers.md section 2), offline,
// on our own maps: the airport-terminal-like map and the near-empty rectangle (maps/README.md).
//
// 1. Initialisations (the paper's Tables 6-11, Fig. 8/9). For every map, start condition
//    (bottleneck: robots drawn within 8 steps of the map's narrowest passage; entrance: bunched
//    around a cell within 3 steps of the entrance; far: spread far apart; near: bunched anywhere),
//    robot count and seed, the same starts are given to every method:
//      standalone  DARP from the robots' cells (the paper's "random + DARP": the starts are the
//                  condition's randomised coordinates)
//      random      DARP from random cells of the map (DarpInit::Random)
//      kmeans      K-Means starts (the paper's Baseline 2)
//      bfs-kmeans  BFS + K-Means applied always (as the paper's tables)
//      selective   BFS + K-Means only when alpha0 > 0.21 (the paper's pipeline)
//    Reported: iterations mean ± std (a failed run counts I_max, a lower bound), failures, final
//    imbalance, alpha0 and alpha after re-initialisation, seconds (thread CPU time), and the check
//    "BFS + K-Means needs >= 50 % fewer iterations than standalone on the terminal" (paper: -75 %).
//    Each run divides with --division: auto (the default: DARP for at most 100 iterations, then
//    the repair, darp.hpp) or darp (DARP alone, up to I_max: the paper's comparisons, which count
//    DARP's iterations); the table says how many runs the repair finished and how many did not
//    converge at all.
// 2. Far vs close sweep (the paper's Tables 3 and 4): the rectangle, n = 1..sweep_max robots,
//    spread vs bunched starts, standalone DARP, beside the paper's iterations.
//
// Writes into --out DIR: results.csv (one row per run), results.json (runs and aggregates),
// table.txt, darp_boxplot.png (iterations per condition and method, one panel per map),
// darp_sweep.png (iterations vs n), pictures/ (the divisions of seed 1). Progress: one line per
// finished group of runs. Exit 0 when every run ended (converged or not: failures are results),
// 2 on bad input.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace swarm::tools {

struct DarpExperimentOptions {
  std::optional<int> seeds;              // per condition and robot count; default 5, --full 10
  std::vector<int> robots;               // empty = {6}; --full: {6, 7, 8}
  std::vector<std::string> maps;         // empty = {"terminal", "rectangle"}
  std::vector<std::string> conditions;   // empty = bottleneck, entrance, far, near
  std::vector<std::string> methods;      // empty = standalone, kmeans, bfs-kmeans, selective
  std::string division = "auto";         // auto | darp (planner::DivisionMethod); darp = the paper's figures
  std::string distance = "euclidean";
  int max_iterations = 10000;
  int sweep_max = 10;                    // 0 = no sweep
  std::optional<int> sweep_seeds;        // default 5, --full 10
  bool full = false;                     // robots 6, 7, 8 and 10 seeds (unless given)
  int jobs = 0;                          // 0 = the core count
  std::string out_dir;                   // "" = runs/experiment-darp-<YYYYmmdd-HHMMSS>
};

int experiment_darp_command(const DarpExperimentOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
