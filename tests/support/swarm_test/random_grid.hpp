// Random maps for property tests: a grid of random size with random cells walled off.
//
//   Rng rng(11);
//   OccupancyGrid g = swarm::test::random_walls(rng, 12, 28, 12);  // 12..28 a side, 1 wall per 12 cells
//
// The draws, in order: width, height, then (x, y) per wall (a cell may be drawn twice).
#pragma once

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::test {

inline planner::OccupancyGrid random_walls(planner::Rng& rng, int min_side, int max_side, int cells_per_wall) {
  const int w = rng.uniform_int(min_side, max_side), h = rng.uniform_int(min_side, max_side);
  planner::OccupancyGrid g(w, h, 0.2, 0, 0, planner::CellState::Free);
  for (int k = 0; k < w * h / cells_per_wall; ++k) {
    g.set({rng.uniform_int(0, w - 1), rng.uniform_int(0, h - 1)}, planner::CellState::Occupied);
  }
  return g;
}

}  // namespace swarm::test
