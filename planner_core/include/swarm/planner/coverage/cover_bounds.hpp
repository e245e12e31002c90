// Lower bounds on the moves a team needs to cover cells, each robot covering the cell it stands on
// and moving one 4-connected cell per move: what no division, route or drive can beat, to tell how
// far a coverage makespan is from the best possible.
//
// - reach: some robot must stand on the uncovered cell farthest from every robot.
// - colour: colour the grid as a chessboard, by the parity of x + y. A 4-connected move always
//   changes colour, so in k moves a robot stands on ⌈k/2⌉ cells of the colour it did not start on
//   and ⌊k/2⌋ of its own. Every uncovered cell needs a robot to stand on it, so k must give the
//   team enough landings on each colour. Where one colour holds most of the cells (the passages
//   between the shelves of a warehouse, whose every neighbour is a crossing), this is far above
//   ⌈cells / robots⌉.
//
//   CoverBounds b = cover_bounds(map, uncovered_mask, robot_cells);
//   int best = std::max({b.reach_moves, b.colour_moves, (cells + robots - 1) / robots});
//
// Deterministic; thread-safe; O(cells).
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

struct CoverBounds {
  int reach_moves = 0;   // to the uncovered cell farthest from every robot (over free cells)
  int colour_moves = 0;  // the fewest moves each that give the team a landing on every uncovered cell
  bool reachable = true;  // false: an uncovered cell no robot can reach (then neither bound holds)
};

// `uncovered`: a mask of map.size(), 1 for every cell still to be covered (a cell under a robot
// counts as covered). Robots move on Free cells, 4-connected, all from the same tick.
[[nodiscard]] CoverBounds cover_bounds(const OccupancyGrid& map, const std::vector<std::uint8_t>& uncovered,
                                       const std::vector<Cell>& robots);

}  // namespace swarm::planner
