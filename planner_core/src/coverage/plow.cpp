#include "swarm/planner/coverage/plow.hpp"

#include <algorithm>
#include <cassert>
#include <cstdint>

#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {
namespace {

// Neighbour offsets in sweep priority.
constexpr Cell kColumnOrder[4] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};  // up, down, right, left
constexpr Cell kRowOrder[4] = {{1, 0}, {-1, 0}, {0, -1}, {0, 1}};     // right, left, down, up

// Breadth-first search through Free cells from `from` to the nearest cell of `part` not yet
// covered; appends the way there (without `from`) to `path`. False when there is none.
bool go_to_nearest(const OccupancyGrid& map, const CellMask& part, const CellMask& covered,
                   std::vector<Cell>& path, std::vector<int>& parent, std::vector<int>& queue) {
  const Cell from = path.back();
  const MotionModel four = MotionModel::four();
  std::fill(parent.begin(), parent.end(), -2);  // -2 unseen, -1 the source
  queue.clear();
  queue.push_back(map.index(from));
  parent[static_cast<std::size_t>(map.index(from))] = -1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int at = queue[head];
    const auto ai = static_cast<std::size_t>(at);
    if (at != queue.front() && part[ai] && !covered[ai]) {
      std::vector<Cell> way;
      for (int i = at; parent[static_cast<std::size_t>(i)] != -1; i = parent[static_cast<std::size_t>(i)]) {
        way.push_back(map.cell_of(i));
      }
      path.insert(path.end(), way.rbegin(), way.rend());
      return true;
    }
    four.for_each_neighbour(map, map.cell_of(at), [&](Cell n, double) {
      const auto ni = static_cast<std::size_t>(map.index(n));
      if (parent[ni] != -2) return;
      parent[ni] = at;
      queue.push_back(static_cast<int>(ni));
    });
  }
  return false;
}

}  // namespace

std::vector<Cell> plow_part(const OccupancyGrid& map, const CellMask& part, CellMask& covered,
                            std::vector<Cell>& path, const PlowOptions& options) {
  assert(!path.empty() && part.size() == map.size() && covered.size() == map.size());
  const Cell* order = options.sweep == PlowOptions::Sweep::kColumns ? kColumnOrder : kRowOrder;
  const MotionModel four = MotionModel::four();
  const auto mark_from = [&](std::size_t first) {
    for (std::size_t i = first; i < path.size(); ++i) covered[static_cast<std::size_t>(map.index(path[i]))] = 1;
  };
  std::vector<int> parent(map.size()), queue;
  // A start outside the map goes nowhere (every cell of the part is missed).
  while (map.in_bounds(path.back())) {
    const Cell at = path.back();
    covered[static_cast<std::size_t>(map.index(at))] = 1;
    bool stepped = false;
    for (int k = 0; k < 4 && !stepped; ++k) {
      const Cell n{at.x + order[k].x, at.y + order[k].y};
      if (!map.in_bounds(n)) continue;
      const auto ni = static_cast<std::size_t>(map.index(n));
      if (!part[ni] || covered[ni] || four.check(map, at, n) != MoveCheck::Ok) continue;
      path.push_back(n);
      stepped = true;
    }
    if (stepped) continue;
    const std::size_t before = path.size();
    if (!go_to_nearest(map, part, covered, path, parent, queue)) break;
    mark_from(before);
  }
  std::vector<Cell> missed;
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (part[i] && !covered[i]) missed.push_back(map.cell_of(static_cast<int>(i)));
  }
  return missed;
}

CoveragePath plow(const OccupancyGrid& map, const CellMask& region, Cell start,
                  const PlowOptions& options) {
  CoveragePath out;
  out.cells.push_back(start);
  CellMask covered(map.size(), 0);
  out.missed = plow_part(map, region, covered, out.cells, options);
  return out;
}

}  // namespace swarm::planner
