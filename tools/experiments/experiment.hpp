// `swarm experiment` and `swarm report`: what an experiment is (a plan of runs, each a `swarm run`
// with its map, method, seed and a few scenario fields changed), how it is stored on disk, and how
// its runs are turned into a table, a CSV, a JSON file and plots.
//
// An experiment directory holds
//   experiment.json   the plan (kind, parameters, every run with its setting) and each run's status
//   runs/<name>/      one run directory per run, as `swarm run` writes it
//   results.csv       one row per run (csv_header(kind) columns)
//   results.json      the runs and the aggregates (mean, std, percent changes, findings)
//   table.txt         the table the experiment printed
//   <kind>.png        the plot(s), e.g. table2.png for explore
// The outputs are always computed from experiment.json + the run directories' metrics.json and
// scenario.pbtxt (load_rows -> analyze_experiment), both when the experiment ends and when
// `swarm report DIR` rebuilds them, so the two give the same bytes.
//
//   ExperimentPlan plan = make_plan(ExperimentKind::kExplore, {"open", "maze1"},
//                                   {"group-frontier", "baseline"}, 5, base_scenario);
//   write_manifest(dir, plan);
//   ... run plan.runs (experiment_runner.hpp), set each run's status, write_manifest again ...
//   ExperimentOutputs o = analyze_experiment(plan, load_rows(dir, plan));
//   write_outputs(dir, o);
//   std::cout << o.table;
//
// Thread-safety: none of these functions share state.
#pragma once

#include <cstdint>
#include <ctime>
#include <optional>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "plot.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::tools {

enum class ExperimentKind { kExplore, kLatency, kBandwidth, kLoss };

// "explore" | "latency" | "bandwidth" | "loss".
[[nodiscard]] std::string kind_name(ExperimentKind kind);
[[nodiscard]] std::optional<ExperimentKind> parse_kind(const std::string& name);

// The link classes a bandwidth experiment caps, and what a cap set from the demand is based on.
inline constexpr const char* kCappedLinks[] = {"leader_gcs", "member_leader"};
inline constexpr const char* kDemandBases[] = {"mean", "peak"};

// A cap set from what the link class carried uncapped: `fraction` of its measured rate per
// sender, the mean over the run ("mean") or the busiest second ("peak").
struct DemandCap {
  std::string link;   // kCappedLinks
  std::string basis;  // kDemandBases
  double fraction = 0;
  friend bool operator==(const DemandCap&, const DemandCap&) = default;
};

// Scenario fields one run sets on top of its base scenario (besides map, method and seed);
// unset = the base scenario's value.
struct RunSetting {
  std::optional<std::uint32_t> leader_gcs_delay_ticks;
  std::optional<std::uint32_t> member_leader_delay_ticks;
  std::optional<swarm::scenario::MapEncoding> map_encoding;
  std::optional<double> leader_gcs_bandwidth_bytes_per_s;     // 0 = unlimited
  std::optional<double> member_leader_bandwidth_bytes_per_s;  // 0 = unlimited
  // Bandwidth: the cap on demand.link is this share of the measured demand; its bytes per second
  // are set once the uncapped runs have measured it (unset until then: the run waits).
  std::optional<DemandCap> demand;
  std::optional<double> loss;                              // the same on every link

  static RunSetting delays(std::uint32_t leader_gcs, std::uint32_t member_leader);
  static RunSetting encoding_and_cap(swarm::scenario::MapEncoding e, double bytes_per_s);
  static RunSetting demand_cap(swarm::scenario::MapEncoding e, DemandCap cap);
  static RunSetting every_link_loss(double loss);
  // A demand cap whose bytes per second are not known yet.
  [[nodiscard]] bool waits_for_demand() const;

  void apply(swarm::scenario::Scenario& s) const;
  friend bool operator==(const RunSetting&, const RunSetting&) = default;
};

enum class RunStatus { kPending, kOk, kFailed };

// One run of an experiment.
struct ExperimentRun {
  std::string dir;     // relative to the experiment directory (report on plain run dirs: as given)
  std::string map;     // built-in name or map_server YAML path
  std::string method;  // group-frontier | baseline | ideal
  std::uint64_t seed = 1;
  RunSetting setting;
  bool pictures = false;  // keep map.png and a mid-run frontier snapshot
  RunStatus status = RunStatus::kPending;
  std::string failure;  // why it failed, one line
  std::string log;      // the failed process's log, relative to the experiment directory
};

// What an experiment was asked to do (DIR/experiment.json).
struct ExperimentPlan {
  ExperimentKind kind = ExperimentKind::kExplore;
  std::string scenario;  // the base scenario file; "" = DATA/scenarios/default.pbtxt
  std::vector<std::string> maps;
  std::vector<std::string> methods;
  std::uint32_t seeds = 0;  // seeds 1..seeds
  // The phases every run drives (`swarm run --mission`); empty = the base scenario's. Steps are
  // then the whole mission's ticks, and the tables add conflicts (and delivered objects).
  std::vector<std::string> mission;
  // latency: a planning interval (the base scenario's replan threshold) and the swept delays.
  std::uint32_t planning_interval_ticks = 0;
  std::vector<std::uint32_t> leader_gcs_delays_ticks;
  std::vector<std::uint32_t> member_leader_delays_ticks;
  // bandwidth: the encodings compared (no cap); then with cap_encoding either absolute
  // leader<->GCS caps (leader_gcs_caps_bytes_per_s, 0 = unlimited), or, when that is empty, caps
  // on each of kCappedLinks at cap_fractions of its measured mean and peak rate per sender
  // (demand, per map label and link, measured on the uncapped cap_encoding runs).
  std::vector<swarm::scenario::MapEncoding> encodings;
  std::vector<double> leader_gcs_caps_bytes_per_s;
  std::vector<double> cap_fractions;
  std::vector<std::string> cap_links;  // of kCappedLinks
  std::vector<std::string> cap_bases;  // of kDemandBases
  swarm::scenario::MapEncoding cap_encoding = swarm::scenario::RUN_LENGTH;
  struct Demand {
    double mean_bytes_per_s = 0, peak_bytes_per_s = 0;  // per sender
    std::size_t runs = 0;                               // the uncapped runs it was measured on
    // The busiest sender's own mean rate over the run, and who that was in most runs (in
    // busiest_sender_runs of them): a cap binds it first. 0 and empty when the runs' metrics name
    // no sender.
    double busiest_mean_bytes_per_s = 0;
    std::string busiest_sender;
    std::size_t busiest_sender_runs = 0;
    // "gcs in 3 of 3 runs" (the name alone from a manifest that did not count the runs).
    [[nodiscard]] std::string busiest_sender_text() const;
  };
  std::map<std::string, std::map<std::string, Demand>> demand;
  // loss: the loss probabilities swept (every link).
  std::vector<double> losses;
  // false for `swarm report` on plain run directories (no experiment.json).
  bool from_manifest = true;
  std::vector<ExperimentRun> runs;
};

// The methods and maps an experiment accepts, and each kind's defaults.
[[nodiscard]] std::vector<std::string> known_methods();  // group-frontier, baseline, ideal
[[nodiscard]] std::vector<std::string> default_maps(ExperimentKind kind);
[[nodiscard]] std::vector<std::string> default_methods(ExperimentKind kind);
[[nodiscard]] std::uint32_t default_seeds(ExperimentKind kind);

// What a user chose of a kind's sweep instead of its default (empty: the default). Bandwidth only.
struct SweepChoices {
  std::vector<swarm::scenario::MapEncoding> encodings;
  std::vector<double> cap_fractions;                 // shares of the demand
  std::vector<std::string> cap_links, cap_bases;     // of kCappedLinks, kDemandBases
  std::vector<double> leader_gcs_caps_bytes_per_s;   // absolute caps instead of shares (0 = unlimited)
};

// The plan with every run, in the order they are run and tabled (map, method, setting, seed).
// `base` is the loaded base scenario (for the planning interval and the default encoding).
[[nodiscard]] ExperimentPlan make_plan(ExperimentKind kind, std::vector<std::string> maps,
                                       std::vector<std::string> methods, std::uint32_t seeds,
                                       const swarm::scenario::Scenario& base,
                                       const std::string& scenario_path, const SweepChoices& choices = {});

// experiment.json in `dir`. write_manifest throws std::runtime_error when it cannot be written;
// read_manifest throws swarm::config::ConfigError naming the file when it is missing or damaged.
void write_manifest(const std::string& dir, const ExperimentPlan& plan);
[[nodiscard]] ExperimentPlan read_manifest(const std::string& dir);
inline constexpr const char* kManifestFile = "experiment.json";

// One run's numbers, from its metrics.json and scenario.pbtxt.
struct RunNumbers {
  bool complete = false;
  double steps = 0;
  std::optional<double> steps_to_99;
  double planning_rounds = 0;
  double explored_fraction = 0;
  double ticks_run = 0;
  double wall_seconds = 0;
  std::uint32_t groups = 0;
  std::uint32_t robots_per_group = 0;
  double robots = 0;
  double tick_seconds = 0;
  double traffic_bytes = 0;
  double map_bytes = 0;  // the map topics: patch_up, patch_down, patch_gcs, round
  bool explores = true;                // the mission's first phase explores (ended_early needs that)
  double conflicts = 0;                // vertex + edge conflict events over the run (ground truth)
  std::optional<double> delivered;     // objects delivered over the collect phases; none without one
  std::vector<double> phase_ticks;     // each phase's ticks (end_tick - start_tick), in mission order
  // Per link class (its comm name): what it carried, its busiest second (from RUN_DIR/traffic.csv;
  // absent when the run has none), and under a cap how long messages queued (ticks; absent
  // uncapped) and how many were lost for good.
  struct Link {
    double bytes = 0;
    std::optional<double> peak_bytes_per_s;
    std::optional<double> queue_median_ticks, queue_p95_ticks;
    double dropped_messages = 0;
    std::string busiest_sender;  // the agent that sent the most bytes on it (empty: not recorded)
    double busiest_sender_bytes = 0;
  };
  std::map<std::string, Link> links;

  // map_bytes / (robots x ticks_run x tick_seconds); 0 when that is 0.
  [[nodiscard]] double map_bytes_per_robot_second() const;
  // traffic_bytes splits into what the simulator sends the robots (their own sensors' data: in a
  // deployment it never leaves the robot) and the rest, which crosses the radio.
  [[nodiscard]] double on_robot_bytes() const;
  [[nodiscard]] double radio_bytes() const;
  // The agents with a token bucket on `link` (comm/link.hpp: one per sender and class):
  // leader_gcs: the leaders and the GCS; member_leader: every robot (members up, leaders down).
  [[nodiscard]] double senders(const std::string& link) const;
  // The link's rate per sender: over the run, and in its busiest second (nullopt without it).
  [[nodiscard]] double mean_bytes_per_s_per_sender(const std::string& link) const;
  [[nodiscard]] std::optional<double> peak_bytes_per_s_per_sender(const std::string& link) const;
  // The busiest sender's own rate over the run (nullopt when the metrics name no sender).
  [[nodiscard]] std::optional<double> busiest_sender_bytes_per_s(const std::string& link) const;
  // The GCS declared the map complete, but the simulator's ground truth says less than
  // kCompleteExploredFraction was seen: the run's steps mean nothing.
  [[nodiscard]] bool ended_early() const;
};

inline constexpr double kCompleteExploredFraction = 0.99;

struct RunRow {
  ExperimentRun run;
  std::optional<RunNumbers> numbers;  // nullopt: the run failed (run.failure says why)
};

// The map topics whose bytes the bandwidth experiment counts.
[[nodiscard]] const std::vector<std::string>& map_topics();

// Reads RUN_DIR/metrics.json and RUN_DIR/scenario.pbtxt; nullopt + `why` when either is missing
// or damaged.
[[nodiscard]] std::optional<RunNumbers> load_run_numbers(const std::string& run_dir,
                                                         std::string& why);

// Bandwidth: each map's demand per sender on each of kCappedLinks (the mean over the successful
// uncapped cap_encoding runs among `rows` of their mean and peak rates), and every run waiting for
// it given its cap. Returns the map labels it could not measure (no such run, or no traffic.csv).
std::vector<std::string> resolve_demand(ExperimentPlan& plan, const std::vector<RunRow>& rows);

// Every run of the plan with its numbers (a run marked ok whose metrics are gone counts as
// failed; a pending run that left metrics counts as ok).
[[nodiscard]] std::vector<RunRow> load_rows(const std::string& experiment_dir,
                                            const ExperimentPlan& plan);

// A plan for `swarm report` on plain run directories: kind explore, grouped by mode and map
// (maps in built-in order, then by name; methods in known_methods() order). Throws
// swarm::config::ConfigError when a directory has no metrics.json.
[[nodiscard]] ExperimentPlan plan_from_run_dirs(const std::vector<std::string>& run_dirs);

struct ExperimentOutputs {
  std::string table;  // printed, and written to table.txt
  std::string csv;    // results.csv
  std::string json;   // results.json
  std::vector<std::pair<std::string, Figure>> figures;  // file name -> figure
};

[[nodiscard]] ExperimentOutputs analyze_experiment(const ExperimentPlan& plan,
                                                   const std::vector<RunRow>& rows);

// A CSV field: as is, or quoted when it holds a comma, a quote or a newline.
[[nodiscard]] std::string csv_escape(const std::string& s);
// Writes `text` to `path` (truncating); throws std::runtime_error naming the file.
void write_file(const std::filesystem::path& path, const std::string& text);

// Writes table.txt, results.csv, results.json and the figures into `dir`; returns the paths
// written. Throws std::runtime_error naming a file that cannot be written.
std::vector<std::string> write_outputs(const std::string& dir, const ExperimentOutputs& outputs);

// The CSV header of a kind: run, map, method, seed, the kind's setting columns, then status,
// complete, steps, steps_to_99, planning_rounds, explored_percent, ticks_run, wall_seconds,
// traffic_bytes, map_bytes, map_bytes_per_robot_second, radio_bytes, sim_robot_on_robot_bytes
// (traffic_bytes split: RunNumbers::radio_bytes), for each of kCappedLinks LINK_bytes,
// LINK_peak_bytes_per_s (its busiest second), LINK_queue_median_ticks and LINK_queue_p95_ticks
// (under a cap), then log, failure.
[[nodiscard]] std::vector<std::string> csv_header(ExperimentKind kind);

}  // namespace swarm::tools
