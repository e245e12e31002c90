// `swarm experiment KIND` and `swarm report DIR...` (experiment.hpp holds what they share).
//
//   swarm experiment explore  [--seeds 5] [--maps open,maze1,maze2]
//                             [--methods group-frontier,baseline,ideal]
//   swarm experiment latency  [--seeds 3] [--maps maze1] [--methods group-frontier,baseline]
//   swarm experiment bandwidth [--seeds 3] [--maps maze1] [--methods group-frontier]
//                             [--encodings RAW_CELLS,RUN_LENGTH,ZSTD_RUN_LENGTH] [--cap-links leader_gcs,member_leader]
//                             [--cap-bases mean,peak] [--cap-fractions 2,1,0.5,0.25,0.125] [--caps B/S,...]
//   swarm experiment loss     [--seeds 3] [--maps maze1] [--methods group-frontier,baseline]
//     common: [--jobs N (default: the core count)] [--out DIR] [--scenario FILE] [--timeout S]
//   swarm report DIR... [--out DIR]
//
// Exit statuses: 0 every run ok (experiment) / tables written (report); 1 some runs failed or
// ended early (the table is still written, those runs marked) or an output could not be
// written; 2 bad input
// (an unknown map or method, 0 seeds or jobs, an output directory that cannot be written, a
// report directory with no runs), with a message saying what is accepted; 130 interrupted.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "experiment.hpp"

namespace swarm::tools {

struct ExperimentOptions {
  ExperimentKind kind = ExperimentKind::kExplore;
  std::vector<std::string> maps;     // empty = default_maps(kind)
  std::vector<std::string> methods;  // empty = default_methods(kind)
  std::optional<std::int64_t> seeds;  // unset = default_seeds(kind); must be >= 1
  std::optional<std::int64_t> jobs;   // unset = the core count; must be >= 1
  std::string out_dir;                // "" = runs/experiment-<kind>-<YYYYmmdd-HHMMSS>
  std::string scenario_path;          // "" = DATA/scenarios/default.pbtxt
  // Per run. A mission of the default size takes well under a minute even at max_ticks, so a run
  // still going after 5 minutes is stuck: it is stopped and counted as failed.
  std::chrono::seconds timeout{300};
  std::string bin_dir;                // "" = the folder of the running executable
  // bandwidth: the sweep's choices, by flag (--encodings, --cap-fractions, --cap-links, --cap-bases,
  // --caps); as names here, checked by experiment_command.
  std::vector<std::string> encodings, cap_links, cap_bases;
  std::vector<double> cap_fractions, caps;
  std::vector<std::string> mission;  // latency, bandwidth, loss: --mission (empty = the scenario's)
};

int experiment_command(const ExperimentOptions& options, std::ostream& out, std::ostream& err);

struct ReportOptions {
  // Either one experiment directory (with experiment.json), or run directories (with
  // metrics.json) and folders whose subfolders are run directories.
  std::vector<std::string> dirs;
  // "" = the experiment directory itself, or runs/report-<YYYYmmdd-HHMMSS> for run directories.
  std::string out_dir;
};

int report_command(const ReportOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
