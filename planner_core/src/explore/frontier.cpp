#include "swarm/planner/explore/frontier.hpp"

#include <cstddef>

namespace swarm::planner {

bool is_frontier(const OccupancyGrid& map, Cell c) {
  if (!map.is_free(c)) return false;
  // Orthogonal neighbours only: an Unknown cell seen across a diagonal gap is not something a
  // robot standing here could sense or drive into directly.
  for (int k = 0; k < 4; ++k) {
    if (map.is_unknown({c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]})) return true;
  }
  return false;
}

std::vector<Cell> find_frontiers(const OccupancyGrid& map) {
  std::vector<Cell> out;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      if (is_frontier(map, {x, y})) out.push_back({x, y});
    }
  }
  return out;
}

std::vector<int> step_distances(const OccupancyGrid& map, const std::vector<Cell>& from, const MotionModel& motion) {
  std::vector<int> dist(map.size(), -1);
  // Breadth first from every seed at once; a plain vector used as a FIFO keeps the order
  // deterministic.
  std::vector<int> queue;
  queue.reserve(map.size());
  for (const Cell& s : from) {
    if (!map.is_free(s)) continue;
    const int i = map.index(s);
    if (dist[i] >= 0) continue;
    dist[i] = 0;
    queue.push_back(i);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int d = dist[queue[head]] + 1;
    motion.for_each_neighbour(map, map.cell_of(queue[head]), [&](Cell n, double) {
      const int ni = map.index(n);
      if (dist[ni] >= 0) return;
      dist[ni] = d;
      queue.push_back(ni);
    });
  }
  return dist;
}

std::vector<std::uint8_t> reachable_mask(const OccupancyGrid& map, const std::vector<Cell>& from,
                                         const MotionModel& motion) {
  const std::vector<int> dist = step_distances(map, from, motion);
  std::vector<std::uint8_t> mask(dist.size(), 0);
  for (std::size_t i = 0; i < dist.size(); ++i) mask[i] = dist[i] >= 0 ? 1 : 0;
  return mask;
}

std::vector<Cell> reachable_frontiers(const OccupancyGrid& map, const std::vector<Cell>& from) {
  const std::vector<std::uint8_t> mask = reachable_mask(map, from);
  std::vector<Cell> out;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const Cell c{x, y};
      if (mask[map.index(c)] && is_frontier(map, c)) out.push_back(c);
    }
  }
  return out;
}

}  // namespace swarm::planner
