// Where the robots of a team start: the n Free cells nearest a start cell.
//
// Breadth-first search (Moore, "The shortest path through a maze", 1959) from `start` with the
// robots' motion model: 8-connected through Free cells, a diagonal step only when both orthogonal
// cells it sweeps are Free (no corner cutting, as in astar.hpp and frontier.hpp). Cells come in
// BFS order (fewest steps first; within a step count, discovery order with neighbours visited as
// kNeighbourDx/Dy list them), so every robot gets a distinct cell connected to all the others.
//
//   std::vector<Cell> cells = start_cells(truth, {10, 10}, 8);   // cells[0] == {10, 10}
//   if (cells.size() < 8) { /* fewer reachable Free cells than robots */ }
//
// Deterministic and thread-safe.
#pragma once

#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

// Up to n cells, start first; empty if start is not a Free cell or n <= 0.
[[nodiscard]] std::vector<Cell> start_cells(const OccupancyGrid& truth, Cell start, int n);

}  // namespace swarm::planner
