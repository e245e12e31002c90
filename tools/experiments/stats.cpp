#include "stats.hpp"

#include <cmath>
#include <cstdio>
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

}  // namespace swarm::tools
