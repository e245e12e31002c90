// `swarm experiment tour` and `swarm experiment clean`: offline experiments (no swarm runs) that
// check the claims of the collection-tour paper (Kim & Lee 2025) and of Group-k (Jeon, Jo & Noh
// 2006) over seeds, and write table.txt, results.csv, results.json and PNG plots into --out DIR
// (default runs/experiment-<tour|clean>-<time>).
//
//   swarm experiment tour  [--scenarios a.tour,b.tour] [--seeds 10] [--layouts 10] [--jobs N] [--out DIR]
//   swarm experiment clean [--maps clutter,empty] [--seeds 5] [--k 0.5] [--margin 0] [--jobs N] [--out DIR]
//
// Each prints a progress line per finished job, the tables (mean ± std over seeds) and the checks
// ("yes" / "NO" with the numbers). Exit status: 0 done (whatever the checks say); 2 bad input (an
// unreadable scenario or map, 0 seeds / layouts / jobs, an output directory that cannot be written).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace swarm::tools {

struct TourExperimentOptions {
  std::vector<std::string> scenarios;  // empty = scenarios/tour/scenario1.tour, scenario2.tour
  std::int64_t seeds = 10;             // GA seeds 1..N for each layout
  std::int64_t layouts = 10;           // the file's own layout and N - 1 re-scattered ones
  std::int64_t jobs = 0;               // 0 = the core count
  std::string out_dir;
};

struct CleanExperimentOptions {
  std::vector<std::string> maps;  // empty = clutter, empty
  std::int64_t seeds = 5;         // seed 1 starts at the paper's (1, 1); others at random free cells
  double k = 0.5;
  int margin = 0;                 // GroupKConfig::area_margin (not in the paper)
  std::int64_t jobs = 0;
  std::string out_dir;
};

int tour_experiment(const TourExperimentOptions& options, std::ostream& out, std::ostream& err);
int clean_experiment(const CleanExperimentOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
