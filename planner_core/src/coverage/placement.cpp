#include "swarm/planner/coverage/placement.hpp"

#include <algorithm>
#include <limits>

#include "swarm/planner/coverage/region_graph.hpp"

namespace swarm::planner {
namespace {

// The cells within `radius` steps of `around` (around first), 4-connected through free cells.
std::vector<Cell> within(const OccupancyGrid& map, Cell around, int radius) {
  const RegionGraph g = RegionGraph::build(map);
  const int s = g.index_of(around);
  if (s < 0) return {};
  std::vector<int> order;
  const std::vector<int> steps = bfs_steps(g, {s}, &order);
  std::vector<Cell> out;
  for (int c : order) {
    if (steps[c] <= radius) out.push_back(g.cells[c]);
  }
  return out;
}

// n distinct cells of `cells`, uniformly (a partial Fisher-Yates shuffle).
std::vector<Cell> draw(std::vector<Cell> cells, int n, Rng& rng) {
  const std::size_t k = std::min<std::size_t>(cells.size(), static_cast<std::size_t>(std::max(n, 0)));
  for (std::size_t i = 0; i < k; ++i) std::swap(cells[i], cells[i + rng.below(cells.size() - i)]);
  cells.resize(k);
  return cells;
}

}  // namespace

std::vector<Cell> largest_piece(const OccupancyGrid& map) {
  const RegionGraph g = RegionGraph::build(map);
  int count = 0;
  const std::vector<int> label = components(g, count);
  std::vector<int> size(count, 0);
  for (int l : label) ++size[l];
  const int best = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
  std::vector<Cell> out;
  for (int i = 0; i < g.size(); ++i) {
    if (label[i] == best) out.push_back(g.cells[i]);
  }
  return out;
}

std::vector<Cell> spread_cells(const OccupancyGrid& map, int n, Rng& rng) {
  const std::vector<Cell> piece = largest_piece(map);
  std::vector<Cell> out;
  if (piece.empty() || n <= 0) return out;
  std::vector<double> nearest(piece.size(), std::numeric_limits<double>::infinity());
  Cell next = piece[rng.below(piece.size())];
  while (static_cast<int>(out.size()) < n && out.size() < piece.size()) {
    out.push_back(next);
    double far = 0;
    for (std::size_t i = 0; i < piece.size(); ++i) {
      nearest[i] = std::min(nearest[i], euclidean_distance(piece[i], next));
      far = std::max(far, nearest[i]);
    }
    std::vector<Cell> candidates;
    for (std::size_t i = 0; i < piece.size(); ++i) {
      if (nearest[i] > 0 && nearest[i] >= 0.7 * far) candidates.push_back(piece[i]);
    }
    if (candidates.empty()) break;
    next = candidates[rng.below(candidates.size())];
  }
  return out;
}

std::vector<Cell> bunched_cells(const OccupancyGrid& map, int n, std::optional<Cell> around, int radius, Rng& rng) {
  const std::vector<Cell> pool = around ? within(map, *around, radius) : largest_piece(map);
  if (pool.empty() || n <= 0) return {};
  const Cell centre = pool[rng.below(pool.size())];
  // The zone: the cells within r steps of the centre, r the smallest radius giving 3n cells.
  const RegionGraph g = RegionGraph::build(map);
  std::vector<int> order;
  const std::vector<int> steps = bfs_steps(g, {g.index_of(centre)}, &order);
  const std::size_t wanted = std::min(order.size(), static_cast<std::size_t>(3 * n));
  const int r = steps[order[wanted - 1]];
  std::vector<Cell> zone;
  for (int c : order) {
    if (steps[c] <= r) zone.push_back(g.cells[c]);
  }
  return draw(zone, n, rng);
}

std::vector<Cell> cells_near(const OccupancyGrid& map, int n, Cell around, int radius, Rng& rng) {
  return draw(within(map, around, radius), n, rng);
}

}  // namespace swarm::planner
