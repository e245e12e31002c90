// Summary statistics for experiment tables: mean, sample standard deviation, relative change.
//
//   swarm::tools::Summary s = swarm::tools::summarize({368, 402, 351});
//   // s.n == 3, s.mean == 373.67, s.std == 25.97 (sample std, n - 1 in the denominator)
//   auto pct = swarm::tools::percent_change(s.mean, 626.0);  // -40.3: 40.3 % fewer than 626
//
// Pure functions, thread-safe.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace swarm::tools {

struct Summary {
  std::size_t n = 0;  // number of values
  double mean = 0;    // NaN when n == 0
  double std = 0;     // sample standard deviation (n - 1); 0 when n == 1; NaN when n == 0
};

// Mean and sample standard deviation of `values`.
[[nodiscard]] Summary summarize(const std::vector<double>& values);

// 100 * (value - reference) / reference: negative = fewer than the reference. nullopt when the
// reference is 0 or either number is not finite.
[[nodiscard]] std::optional<double> percent_change(double value, double reference);

// The mean of the finite values of `values` (nullopt when there is none): the paper's
// "29.45 % faster on average" is the mean of the per-map percent changes.
[[nodiscard]] std::optional<double> mean_of(const std::vector<std::optional<double>>& values);

// Student's t quantile 0.975 with `df` degrees of freedom (df >= 1): the half-width of a 95 %
// confidence interval is this times the standard error. Exact to 3 decimals for df <= 30 (table),
// within 0.001 beyond (Cornish-Fisher expansion around the normal quantile).
[[nodiscard]] double t_quantile_975(std::size_t df);

// A paired comparison: `values[i]` and `reference[i]` measured on the same seed (the same run but
// for the setting compared). The mean of the differences with its 95 % confidence interval
// (Student's t, n - 1 degrees of freedom), and the same as percent of the reference's mean.
// `significant` when the interval excludes 0. n < 2 (or different lengths): no interval (NaN).
struct PairedDifference {
  std::size_t n = 0;
  double mean = 0, low = 0, high = 0;                  // value - reference
  double mean_pct = 0, low_pct = 0, high_pct = 0;      // of the reference's mean
  bool significant = false;
};
[[nodiscard]] PairedDifference paired_difference(const std::vector<double>& values, const std::vector<double>& reference);
// "+4.0 % [+0.3, +7.7]", with " (n.s.)" when the interval includes 0; "-" without an interval.
[[nodiscard]] std::string format_paired_pct(const PairedDifference& d);

// "368.0 ± 25.8" with `decimals` digits after the point; "-" when s.n == 0.
[[nodiscard]] std::string format_mean_std(const Summary& s, int decimals);
// "-40.3 %" / "+2.0 %" with one decimal; "-" for nullopt.
[[nodiscard]] std::string format_percent_change(const std::optional<double>& pct);

}  // namespace swarm::tools
