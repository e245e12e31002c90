// Shared pieces of the per-kind analyses (experiment_explore.cpp, experiment_latency.cpp,
// experiment_bandwidth.cpp, experiment_loss.cpp): selecting the runs of one table cell, their
// statistics and how cells, markers and footnotes are written. Internal to swarm_tools_lib.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiment.hpp"
#include "stats.hpp"

namespace swarm::tools::analysis {

// What the per-kind analysis adds to the common CSV and run list.
struct KindOutputs {
  std::string table;
  nlohmann::json aggregates = nlohmann::json::array();
  nlohmann::json findings = nlohmann::json::object();
  std::vector<std::pair<std::string, Figure>> figures;
};

void analyze_explore(const ExperimentPlan& plan, const std::vector<RunRow>& rows, KindOutputs& out);
void analyze_latency(const ExperimentPlan& plan, const std::vector<RunRow>& rows, KindOutputs& out);
void analyze_bandwidth(const ExperimentPlan& plan, const std::vector<RunRow>& rows,
                       KindOutputs& out);
void analyze_loss(const ExperimentPlan& plan, const std::vector<RunRow>& rows, KindOutputs& out);

// One cap of a bandwidth sweep: its bytes per second, its runs' mean steps, whether all of them
// completed, and the 95 % interval of its paired difference to the uncapped runs of the same
// seeds, in percent (NaN with fewer than two pairs).
struct KneePoint {
  double cap = 0;
  double steps = 0;
  bool all_complete = true;
  double low_pct = std::numeric_limits<double>::quiet_NaN();
  double high_pct = std::numeric_limits<double>::quiet_NaN();
};
struct Knee {
  double cap = 0;
  // A cap at or above the knee whose interval reaches past the tolerance: the seeds cannot tell
  // that it costs less than the tolerance (nullopt: every one is clearly within it).
  std::optional<double> uncertain_at;
};
// The knee: going down from the largest cap until the first that is incomplete or slower than
// uncapped_steps by more than tolerance_percent, the smallest whose mean steps are within the
// tolerance. With an interval, "slower" means its lower end is past the tolerance, so that one
// noisy cap does not end the walk; such a cap, with its mean past the tolerance, is passed over
// but is no knee. Without an interval, "slower" is its mean. nullopt when no cap before the end
// of the walk has its mean within the tolerance.
[[nodiscard]] std::optional<Knee> knee_of(const std::vector<KneePoint>& points, double uncapped_steps,
                                          double tolerance_percent);

// The settings a kind sweeps, in table order (make_plan runs each for every map and method).
[[nodiscard]] std::vector<RunSetting> settings_of(const ExperimentPlan& plan);

enum class Metric {
  kSteps,
  kRounds,
  kStepsTo99,
  kExploredPercent,
  kTrafficBytes,
  kRadioBytes,    // kTrafficBytes without the simulator's sensing of the robots (on the robot)
  kOnRobotBytes,  // that sensing alone
  kConflicts,     // vertex + edge conflict events (a chained mission's)
  kDelivered,     // collect's delivered objects
  kMapBytes,
  kMapBytesPerRobotSecond,
  kPhaseTicks,    // one phase's ticks (Measure::phase_ticks)
};
// What a table row reads off each run: a Metric, or the ticks of a chained mission's phase i.
struct Measure {
  Metric metric;
  std::size_t phase = 0;
  Measure(Metric m) : metric(m) {}  // NOLINT(google-explicit-constructor): every Metric is a Measure
  [[nodiscard]] static Measure phase_ticks(std::size_t i) {
    Measure m(Metric::kPhaseTicks);
    m.phase = i;
    return m;
  }
};

// The runs of one table cell.
struct Cell {
  int planned = 0;
  int failed = 0;
  int incomplete = 0;              // ran to max_ticks: their steps are a lower bound
  int ended_early = 0;             // RunNumbers::ended_early(): left out of ok
  std::vector<const RunRow*> ok;  // the runs whose numbers count

  [[nodiscard]] int complete() const { return static_cast<int>(ok.size()) - incomplete; }
};

[[nodiscard]] Cell cell_of(const std::vector<RunRow>& rows,
                           const std::function<bool(const RunRow&)>& in_cell);
// Runs of (map, method) with exactly `setting`.
[[nodiscard]] Cell cell_of(const std::vector<RunRow>& rows, const std::string& map,
                           const std::string& method, const RunSetting& setting);

[[nodiscard]] Summary summary_of(const Cell& c, Measure m);
// One run's value of `m` (nullopt: it has none, e.g. no steps to 99 %).
[[nodiscard]] std::optional<double> value_of(const RunNumbers& n, Measure m);
// `m` of c's runs against the reference's runs of the same seeds (seeds in only one are left
// out): the mean paired difference with its 95 % confidence interval (stats.hpp).
[[nodiscard]] PairedDifference paired_of(const Cell& c, const Cell& reference, Measure m);
// {"pairs", "mean", "ci95": [low, high], "mean_percent", "ci95_percent": [..], "significant"}.
[[nodiscard]] nlohmann::json paired_json(const PairedDifference& d);
// "mean ± std" plus markers: "*" some runs failed (left out), "!" some runs ended early (left
// out), "+" some runs incomplete (counted with max_ticks).
[[nodiscard]] std::string format_cell(const Cell& c, Measure m, int decimals);
// "5/5", or "2/5 (2 failed, 1 ended early)"; counts complete runs of the planned ones.
[[nodiscard]] std::string completion_text(const Cell& c);
[[nodiscard]] nlohmann::json summary_json(const Summary& s);
[[nodiscard]] nlohmann::json cell_json(const Cell& c);  // runs, ok, failed, complete counts
[[nodiscard]] nlohmann::json optional_json(const std::optional<double>& v);

// One table row: `label`, then f(setting) for each setting.
[[nodiscard]] std::vector<std::string> row_over(
    const std::string& label, const std::vector<RunSetting>& settings,
    const std::function<std::string(const RunSetting&)>& f);

// A sweep over one scenario field (latency, bandwidth cap, loss): its settings in column order.
struct Sweep {
  std::string heading;               // first header cell, e.g. "loss on every link, maze1"
  std::vector<std::string> columns;  // one header per setting
  std::vector<RunSetting> settings;
  std::size_t reference = 0;         // the column the "vs <reference_name>" rows compare with
  std::string reference_name;        // e.g. "no loss"
};

// Steps, planning rounds (and steps to 99 % when asked) of every method over the sweep on `map`,
// each with "METHOD vs <reference>" rows and "METHOD vs baseline" rows (when the baseline is
// among the methods): the mean paired difference over seeds in percent of the reference, its 95 %
// confidence interval, "(n.s.)" when that includes 0; then the complete runs.
[[nodiscard]] std::string sweep_table(const Sweep& sweep, const ExperimentPlan& plan,
                                      const std::vector<RunRow>& rows, const std::string& map,
                                      bool with_steps_to_99);

// Mean (values) ± std (errors) of `m` over the sweep's settings for one method on `map`.
[[nodiscard]] PlotSeries sweep_series(const Sweep& sweep, const std::vector<RunRow>& rows,
                                      const std::string& map, const std::string& method,
                                      Colour colour, const std::string& name, Measure m);

// The lines under every table: what the markers mean (only those used) and each failed run with
// its log.
[[nodiscard]] std::string footnotes(const std::vector<RunRow>& rows);
// "seeds 1-5" / "seeds 1, 3, 4" over every planned run; "groups x robots" when all agree.
[[nodiscard]] std::string seeds_text(const std::vector<RunRow>& rows);
[[nodiscard]] std::string team_text(const std::vector<RunRow>& rows);
// An experiment's figure of means over seeds: titled "<subject>: mean +/- std over <seeds>", with
// the note that error bars are standard deviations. The panels are the caller's.
[[nodiscard]] Figure seed_stats_figure(const std::string& subject, const std::vector<RunRow>& rows);
// "45 runs: 44 ok (43 complete), 1 failed" (and ", 2 ended early" when some did).
[[nodiscard]] std::string runs_text(const std::vector<RunRow>& rows);

// Okabe-Ito colours: group-frontier blue, baseline vermillion, ideal bluish green; others grey
// shades in order.
[[nodiscard]] Colour method_colour(const std::string& method, int index);

[[nodiscard]] std::string format_number(double v, int decimals);
// "4 kB/s", "unlimited".
[[nodiscard]] std::string format_rate(double bytes_per_s);
[[nodiscard]] std::string encoding_name(swarm::scenario::MapEncoding e);

}  // namespace swarm::tools::analysis
