// A* shortest paths on an occupancy grid with the robots' motion model.
//
// Hart, Nilsson & Raphael, "A Formal Basis for the Heuristic Determination of Minimum Cost
// Paths", IEEE Trans. SSC 1968. Moves are the motion model's (motion.hpp): by default 8-connected,
// costing 1 (orthogonal) and sqrt(2) (diagonal), with the octile heuristic, never cutting a corner;
// 4-connected with the Manhattan heuristic on request. Both heuristics are admissible and
// consistent, so the first expansion of the goal is optimal.
// Occupied and out-of-bounds cells are never passable; Unknown ones are iff unknown_is_free. The
// start cell is always allowed (a robot standing on a cell its map calls Occupied can still leave).
//
//   auto path = astar(map, robot, goal);                          // optimistic: Unknown is free
//   auto safe = astar(map, robot, goal, {.unknown_is_free = false});
//   if (path) drive(*path);                                       // path->front() == robot
//
// Ties between equal f are broken towards larger g, then the smaller cell index, so the result is
// deterministic. Runs in O(N log N) for N cells and always terminates. Thread-safe.
#pragma once

#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {

struct AStarOptions {
  bool unknown_is_free = true;  // optimistic planning through unexplored space
  MotionModel motion = MotionModel::eight();
};

// The cells of a cheapest path, start and goal included; {start} when start == goal; nullopt when
// the goal is unreachable, not passable, or start/goal is out of bounds.
[[nodiscard]] std::optional<std::vector<Cell>> astar(const OccupancyGrid& map, Cell start,
                                                     Cell goal, const AStarOptions& options = {});

// Length of a path in cells: the sum of the Euclidean lengths of its steps.
[[nodiscard]] double path_length(const std::vector<Cell>& path);

}  // namespace swarm::planner
