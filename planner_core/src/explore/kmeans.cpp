#include "swarm/planner/explore/kmeans.hpp"

#include <algorithm>
#include <limits>

#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {
namespace {

double sq_dist(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double dx = a.x() - b.x();
  const double dy = a.y() - b.y();
  return dx * dx + dy * dy;
}

int count_distinct(const std::vector<Eigen::Vector2d>& points) {
  std::vector<std::pair<double, double>> v;
  v.reserve(points.size());
  for (const auto& p : points) v.emplace_back(p.x(), p.y());
  std::sort(v.begin(), v.end());
  return static_cast<int>(std::unique(v.begin(), v.end()) - v.begin());
}

// Nearest centre of every point, ties to the lowest index. Returns true if any label changed.
bool assign(const std::vector<Eigen::Vector2d>& points, const std::vector<Eigen::Vector2d>& centres,
            std::vector<int>& labels) {
  bool changed = false;
  for (std::size_t i = 0; i < points.size(); ++i) {
    int best = 0;
    double best_d = sq_dist(points[i], centres[0]);
    for (std::size_t c = 1; c < centres.size(); ++c) {
      const double d = sq_dist(points[i], centres[c]);
      if (d < best_d) {
        best_d = d;
        best = static_cast<int>(c);
      }
    }
    if (labels[i] != best) {
      labels[i] = best;
      changed = true;
    }
  }
  return changed;
}

// k-means++: the first centre uniformly, each next one with probability proportional to the
// squared distance to the nearest centre chosen so far. Points already chosen have weight 0, so
// with k <= distinct points all centres are distinct.
std::vector<Eigen::Vector2d> seed_plus_plus(const std::vector<Eigen::Vector2d>& points, int k,
                                            Rng& rng) {
  const std::size_t n = points.size();
  std::vector<Eigen::Vector2d> centres;
  centres.reserve(k);
  centres.push_back(points[rng.below(n)]);
  std::vector<double> d2(n);
  for (std::size_t i = 0; i < n; ++i) d2[i] = sq_dist(points[i], centres[0]);
  while (static_cast<int>(centres.size()) < k) {
    double total = 0;
    for (double d : d2) total += d;
    if (!(total > 0)) break;  // only if distinct points are closer than double can tell apart
    const double r = rng.uniform01() * total;
    // Walk the cumulative sum; the last point with positive weight catches rounding at the end.
    std::size_t pick = n;
    double acc = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (d2[i] <= 0) continue;
      pick = i;
      acc += d2[i];
      if (r < acc) break;
    }
    centres.push_back(points[pick]);
    for (std::size_t i = 0; i < n; ++i) d2[i] = std::min(d2[i], sq_dist(points[i], centres.back()));
  }
  return centres;
}

}  // namespace

KMeansResult kmeans(const std::vector<Eigen::Vector2d>& points, const KMeansConfig& config,
                    const std::function<bool()>& should_stop) {
  KMeansResult out;
  if (points.empty()) {
    out.converged = true;
    return out;
  }
  if (!config.initial_centres.empty()) {
    out.centres = config.initial_centres;
  } else {
    const int k = std::clamp(config.k, 1, count_distinct(points));
    Rng rng(config.seed);
    out.centres = seed_plus_plus(points, k, rng);
  }
  out.labels.assign(points.size(), -1);
  assign(points, out.centres, out.labels);

  const std::size_t kc = out.centres.size();
  std::vector<Eigen::Vector2d> sum(kc);
  std::vector<int> count(kc);
  for (int it = 0; it < config.max_iterations; ++it) {
    if (should_stop && should_stop()) return out;
    // Means in input order: the summation order is fixed, so the centres are reproducible.
    std::fill(sum.begin(), sum.end(), Eigen::Vector2d::Zero());
    std::fill(count.begin(), count.end(), 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      sum[out.labels[i]] += points[i];
      ++count[out.labels[i]];
    }
    for (std::size_t c = 0; c < kc; ++c) {
      if (count[c] > 0) out.centres[c] = sum[c] / static_cast<double>(count[c]);
    }
    ++out.iterations;
    if (!assign(points, out.centres, out.labels)) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace swarm::planner
