// DARP's initialisations other than the robots' own cells (darp.hpp, DarpInit).
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "darp_engine.hpp"
#include "swarm/planner/explore/hungarian.hpp"
#include "swarm/planner/explore/kmeans.hpp"

namespace swarm::planner::detail {
namespace {

double sq(double v) { return v * v; }

// The unused cell of `piece` nearest (Euclidean) to `p`; ties to the lowest index. -1 if none.
int nearest_cell(const DarpSpace& space, const Eigen::Vector2d& p, int piece,
                 const std::vector<std::uint8_t>& used) {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < space.graph.size(); ++i) {
    if (space.piece[i] != piece || used[i]) continue;
    const double d = sq(space.graph.cells[i].x - p.x()) + sq(space.graph.cells[i].y - p.y());
    if (d < best_d) best_d = d, best = i;
  }
  return best;
}

std::vector<std::vector<int>> robots_by_piece(const DarpSpace& space) {
  std::vector<std::vector<int>> out(space.pieces);
  for (int r = 0; r < space.robots(); ++r) out[space.robot_piece[r]].push_back(r);
  return out;
}

}  // namespace

std::vector<int> random_starts(const DarpSpace& space, const std::vector<int>& robots,
                               DarpDistance distance, Rng& rng) {
  const RegionGraph& g = space.graph;
  std::vector<int> out(robots.size(), -1);
  std::vector<std::vector<int>> cells_of(space.pieces);
  for (int i = 0; i < g.size(); ++i) cells_of[space.piece[i]].push_back(i);
  std::vector<std::uint8_t> used(g.size(), 0);
  for (const std::vector<int>& members : robots_by_piece(space)) {
    if (members.empty()) continue;
    const std::vector<int>& cells = cells_of[space.piece[robots[members[0]]]];
    // Distinct uniform draws (the piece holds at least as many cells as robots: checked earlier).
    std::vector<int> drawn;
    while (drawn.size() < members.size()) {
      const int c = cells[rng.below(cells.size())];
      if (used[c]) continue;
      used[c] = 1;
      drawn.push_back(c);
    }
    // Match robots to the drawn cells with the least total distance: the robots' travel.
    Eigen::MatrixXd cost(members.size(), drawn.size());
    for (std::size_t a = 0; a < members.size(); ++a) {
      const int from = robots[members[a]];
      std::vector<int> steps;
      if (distance == DarpDistance::Geodesic) steps = bfs_steps(g, {from});
      for (std::size_t b = 0; b < drawn.size(); ++b) {
        cost(a, b) = distance == DarpDistance::Geodesic
                         ? steps[drawn[b]]
                         : std::sqrt(sq(g.cells[from].x - g.cells[drawn[b]].x) +
                                     sq(g.cells[from].y - g.cells[drawn[b]].y));
      }
    }
    const Assignment match = hungarian(cost);
    for (std::size_t a = 0; a < members.size(); ++a) out[members[a]] = drawn[match.row_to_col[a]];
  }
  return out;
}

std::vector<int> kmeans_starts(const DarpSpace& space, const std::vector<int>& robots,
                               const DarpConfig& config) {
  const RegionGraph& g = space.graph;
  std::vector<int> out(robots.size(), -1);
  std::vector<std::uint8_t> used(g.size(), 0);
  for (const std::vector<int>& members : robots_by_piece(space)) {
    if (members.empty()) continue;
    const int piece = space.robot_piece[members[0]];
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < g.size(); ++i) {
      if (space.piece[i] == piece) points.emplace_back(g.cells[i].x, g.cells[i].y);
    }
    KMeansConfig km;
    km.max_iterations = config.kmeans_max_iterations;
    for (int r : members) km.initial_centres.emplace_back(g.cells[robots[r]].x, g.cells[robots[r]].y);
    const KMeansResult clusters = kmeans(points, km);
    // Centre i grew from robot members[i]'s cell; snap it to the nearest unused cell (a centre
    // may fall in a wall or outside the region).
    for (std::size_t a = 0; a < members.size(); ++a) {
      const int c = nearest_cell(space, clusters.centres[a], piece, used);
      used[c] = 1;
      out[members[a]] = c;
    }
  }
  return out;
}

std::vector<int> bfs_kmeans_starts(const DarpSpace& space, const std::vector<int>& starts, int lloyd_steps) {
  std::vector<int> current = starts;
  for (int step = 0; step < std::max(1, lloyd_steps); ++step) {
    std::vector<int> next = bfs_kmeans_step(space, current);
    if (next == current) break;
    current = std::move(next);
  }
  return current;
}

std::vector<int> bfs_kmeans_step(const DarpSpace& space, const std::vector<int>& starts) {
  // Candidate regions: a multi-source BFS from the starts (FIFO, sources in robot order), each
  // cell labelled with the start whose wave reached it first: connected by construction.
  const RegionGraph& g = space.graph;
  const int n = static_cast<int>(starts.size());
  std::vector<int> label(g.size(), -1);
  std::vector<int> queue;
  queue.reserve(g.size());
  for (int r = 0; r < n; ++r) {
    label[starts[r]] = r;
    queue.push_back(starts[r]);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int c = queue[head];
    for (int nb : g.next[c]) {
      if (nb < 0 || label[nb] >= 0) continue;
      label[nb] = label[c];
      queue.push_back(nb);
    }
  }
  // K-Means' update step: each candidate region's mean, snapped to its nearest cell inside the
  // same candidate region (so a start never jumps a wall into another robot's candidate region).
  std::vector<Eigen::Vector2d> sum(n, Eigen::Vector2d::Zero());
  std::vector<int> count(n, 0);
  for (int i = 0; i < g.size(); ++i) {
    sum[label[i]] += Eigen::Vector2d(g.cells[i].x, g.cells[i].y);
    ++count[label[i]];
  }
  std::vector<int> out(starts);
  std::vector<double> best_d(n, std::numeric_limits<double>::infinity());
  for (int i = 0; i < g.size(); ++i) {
    const int r = label[i];
    const Eigen::Vector2d mean = sum[r] / count[r];
    const double d = sq(g.cells[i].x - mean.x()) + sq(g.cells[i].y - mean.y());
    if (d < best_d[r]) best_d[r] = d, out[r] = i;
  }
  return out;
}

}  // namespace swarm::planner::detail
