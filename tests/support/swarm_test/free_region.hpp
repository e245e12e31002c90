// The free cells 4-connected to the first free cell met walking from the middle of a map: where
// tests and benchmarks place robots and goals on a map they did not draw (a MovingAI map may have
// pockets that are left out).
#pragma once

#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::test {

inline std::vector<planner::Cell> free_region(const planner::OccupancyGrid& map) {
  const int n = static_cast<int>(map.size());
  int seed = -1;
  for (int i = 0; i < n && seed < 0; ++i) {
    if (map.at((n / 2 + i) % n) == planner::CellState::Free) seed = (n / 2 + i) % n;
  }
  if (seed < 0) return {};
  std::vector<char> seen(map.size(), 0);
  std::vector<planner::Cell> out{map.cell_of(seed)};
  seen[static_cast<std::size_t>(seed)] = 1;
  for (std::size_t h = 0; h < out.size(); ++h) {
    planner::MotionModel::four().for_each_neighbour(map, out[h], [&](planner::Cell c, double) {
      char& s = seen[static_cast<std::size_t>(map.index(c))];
      if (s == 0) {
        s = 1;
        out.push_back(c);
      }
    });
  }
  return out;
}

}  // namespace swarm::test
