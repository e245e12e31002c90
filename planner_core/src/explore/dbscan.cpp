#include "swarm/planner/explore/dbscan.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace swarm::planner {
namespace {

// Floor division for negative coordinates too (cells may lie left of / below the origin).
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

// Square buckets of side `side` cells, keyed by bucket coordinates. Each bucket keeps its points'
// indices in input order; we only ever look buckets up by key, so the result never depends on
// the hash table's iteration order.
class BucketGrid {
 public:
  BucketGrid(const std::vector<Cell>& points, std::int64_t side) : points_(points), side_(side) {
    buckets_.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      buckets_[key(bx(points[i].x), by(points[i].y))].push_back(static_cast<int>(i));
    }
  }

  // Appends to `out` every point within eps of points_[i] (including i), bucket by bucket.
  void neighbours(int i, double eps2, std::vector<int>& out) const {
    out.clear();
    const Cell c = points_[i];
    const std::int64_t cx = bx(c.x), cy = by(c.y);
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const auto it = buckets_.find(key(cx + dx, cy + dy));
        if (it == buckets_.end()) continue;
        for (int j : it->second) {
          const double ddx = static_cast<double>(points_[j].x) - c.x;
          const double ddy = static_cast<double>(points_[j].y) - c.y;
          if (ddx * ddx + ddy * ddy <= eps2) out.push_back(j);
        }
      }
    }
  }

 private:
  std::int64_t bx(int x) const { return floor_div(x, side_); }
  std::int64_t by(int y) const { return floor_div(y, side_); }
  // Bucket coordinates fit in 32 bits each (cells are ints, side >= 1).
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
           static_cast<std::uint32_t>(y);
  }
  struct Mix {  // splitmix64 finaliser: cheap and spreads the packed key well.
    std::size_t operator()(std::uint64_t z) const {
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return static_cast<std::size_t>(z ^ (z >> 31));
    }
  };

  const std::vector<Cell>& points_;
  std::int64_t side_;
  std::unordered_map<std::uint64_t, std::vector<int>, Mix> buckets_;
};

}  // namespace

std::vector<int> dbscan(const std::vector<Cell>& points, double eps, int min_points) {
  assert(eps >= 0 && "dbscan: eps is a distance in cells and must be >= 0");
  const int n = static_cast<int>(points.size());
  constexpr int kUnvisited = -2;
  constexpr int kNoise = -1;
  std::vector<int> label(n, kUnvisited);
  if (n == 0) return label;
  if (!(eps >= 0)) eps = 0;  // NaN / negative in release builds: only exact duplicates link

  // A neighbour differs by at most eps <= side in each axis, so it lies in the 3x3 buckets around.
  // Capping the side keeps bucket coordinates in range; an eps that large links everything anyway.
  const double side_d = std::min(std::max(1.0, std::ceil(eps)), 1073741824.0);
  const BucketGrid grid(points, static_cast<std::int64_t>(side_d));
  const double eps2 = eps * eps;

  std::vector<int> nbrs, nbrs2, queue;
  int clusters = 0;
  for (int i = 0; i < n; ++i) {
    if (label[i] != kUnvisited) continue;
    grid.neighbours(i, eps2, nbrs);
    if (static_cast<int>(nbrs.size()) < min_points) {
      label[i] = kNoise;  // may still become a border point of a later cluster
      continue;
    }
    const int c = clusters++;
    label[i] = c;
    queue.assign(nbrs.begin(), nbrs.end());
    // Breadth-first expansion from core points; `queue` grows while we walk it.
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int j = queue[q];
      if (label[j] == kNoise) label[j] = c;  // border point claimed by this cluster
      if (label[j] != kUnvisited) continue;
      label[j] = c;
      grid.neighbours(j, eps2, nbrs2);
      if (static_cast<int>(nbrs2.size()) >= min_points) {
        for (int k : nbrs2) {
          if (label[k] < 0) queue.push_back(k);  // unvisited or noise: not claimed yet
        }
      }
    }
  }

  // Renumber so cluster ids follow each cluster's first point in the input. The loop above
  // numbers clusters by their first core point, which differs when a border point comes first.
  std::vector<int> remap(clusters, -1);
  int next = 0;
  for (int& l : label) {
    if (l < 0) continue;
    if (remap[l] < 0) remap[l] = next++;
    l = remap[l];
  }
  return label;
}

std::vector<std::vector<Cell>> clusters_of(const std::vector<Cell>& points,
                                           const std::vector<int>& labels) {
  assert(points.size() == labels.size());
  int k = 0;
  for (int l : labels) k = std::max(k, l + 1);
  std::vector<std::vector<Cell>> out(k);
  for (std::size_t i = 0; i < points.size() && i < labels.size(); ++i) {
    if (labels[i] >= 0) out[labels[i]].push_back(points[i]);
  }
  return out;
}

}  // namespace swarm::planner
