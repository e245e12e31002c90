#include "stats.hpp"

#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>

namespace swarm::tools {

Summary summarize(const std::vector<double>& values) {
  Summary s;
  s.n = values.size();
  if (s.n == 0) {
    s.mean = s.std = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  double sum = 0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n == 1) return s;
  double squares = 0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(squares / static_cast<double>(s.n - 1));
  return s;
}

std::optional<double> percent_change(double value, double reference) {
  if (!std::isfinite(value) || !std::isfinite(reference) || reference == 0) return std::nullopt;
  return 100.0 * (value - reference) / reference;
}

std::optional<double> mean_of(const std::vector<std::optional<double>>& values) {
  double sum = 0;
  int n = 0;
  for (const auto& v : values) {
    if (v && std::isfinite(*v)) {
      sum += *v;
      ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

std::string format_mean_std(const Summary& s, int decimals) {
  if (s.n == 0) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f ± %.*f", decimals, s.mean, decimals, s.std);
  return buf;
}

std::string format_percent_change(const std::optional<double>& pct) {
  if (!pct) return "-";
  char buf[32];
  // Never print "-0.0 %".
  const double v = std::fabs(*pct) < 0.05 ? 0.0 : *pct;
  std::snprintf(buf, sizeof buf, "%+.1f %%", v);
  return buf;
}

double t_quantile_975(std::size_t df) {
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                      2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                      2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (df == 0) return std::numeric_limits<double>::quiet_NaN();
  if (df <= std::size(kTable)) return kTable[df - 1];
  const double z = 1.959964, n = static_cast<double>(df);
  const double z3 = z * z * z, z5 = z3 * z * z;
  return z + (z3 + z) / (4 * n) + (5 * z5 + 16 * z3 + 3 * z) / (96 * n * n);
}

PairedDifference paired_difference(const std::vector<double>& values, const std::vector<double>& reference) {
  PairedDifference d;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  d.mean = d.low = d.high = d.mean_pct = d.low_pct = d.high_pct = nan;
  if (values.size() != reference.size() || values.size() < 2) return d;
  std::vector<double> diff;
  for (std::size_t i = 0; i < values.size(); ++i) diff.push_back(values[i] - reference[i]);
  const Summary s = summarize(diff);
  d.n = s.n;
  const double half = t_quantile_975(s.n - 1) * s.std / std::sqrt(static_cast<double>(s.n));
  d.mean = s.mean;
  d.low = s.mean - half;
  d.high = s.mean + half;
  d.significant = d.low > 0 || d.high < 0;
  const double base = summarize(reference).mean;
  if (base != 0 && std::isfinite(base)) {
    d.mean_pct = 100 * d.mean / base;
    d.low_pct = 100 * d.low / base;
    d.high_pct = 100 * d.high / base;
  }
  return d;
}

std::string format_paired_pct(const PairedDifference& d) {
  if (d.n < 2 || !std::isfinite(d.low_pct)) return "-";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%+.1f %% [%+.1f, %+.1f]%s", d.mean_pct, d.low_pct, d.high_pct,
                d.significant ? "" : " (n.s.)");
  return buf;
}

}  // namespace swarm::tools
