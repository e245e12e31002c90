// Finishing a division DARP could not (internal to planner_core; the public API is darp.hpp,
// DivisionMethod::Auto).
//
// repair_division takes any division of a DarpSpace (every cell owned by a robot of its piece)
// and makes it a goal division where it can:
//   1. Connect: each robot keeps the piece of its region that holds its start; the cells of its
//      other pieces are handed, by a breadth-first wave from every kept region at once, to the
//      region that reaches them first. Every region is then connected, and stays so: every later
//      move keeps it.
//   2. Balance, towards integer targets t_r (the shares rounded so that each piece's targets add
//      up to its cells), by the first of these that applies, repeated:
//      a. A chain: from a region over its target to the nearest region under it (fewest hops
//         between neighbouring regions), every hop hands boundary cells to the next region, as
//         many as the two ends need (a wave from the border, best first), so the regions in
//         between keep their size. A cell may leave a region only if the region stays connected
//         without it (judged from its 3 x 3 neighbourhood; when no chain exists that way,
//         exactly, from the region's articulation points) and, at first, only if it is not the
//         region's start. The cell nearer the receiving region's centroid than the giving one's
//         goes first, which keeps the regions compact. A chain that cannot finish is undone.
//      b. A branch move: a cell that would cut its region goes with everything it cuts off from
//         the region's start (a dead end, a room behind a door) to the neighbouring region.
//      c. Released starts: a region may give up its start cell (it grows from a neighbour).
//      d. A reseed (starts released): the region furthest under its target, walled in, is merged
//         into a neighbour and grown again from the cell of the region furthest over its target
//         that lies furthest from that region's start.
//      Chains lower the summed distance to the targets; branch moves lower it or only shift it,
//      and reseeds are bounded, so it ends: at the targets, or when nothing applies.
//   3. Starts: a region that no longer grows from its first start takes the cell nearest its
//      robot (breadth-first through the piece), to which the robot drives first.
// divide_areas (darp.cpp) repairs DARP's best division first and, if that does not reach the
// goal, fresh first divisions (from K-Means starts, then random ones), keeping the best.
// Why local exchanges rather than a second global method: DARP's best division is nearly right
// almost everywhere (compact regions, a few cells wrong or a few robots walled in), so moving
// only the cells that must move keeps its shapes, and each chain costs O(cells).
//
// no_balanced_division proves, where it can, that no goal division exists whatever the starts:
// for every articulation cell v of a piece, the regions other than v's own lie each inside one of
// the parts left when v is taken away, and v's region reaches into the parts by what they do not
// hold; if no count of regions per part and no reach of v's region fits every region in
// [lo, hi] cells (the smallest and largest a region may hold within tolerance), no division does.
// It returns the reason, or "" when it finds none (which proves nothing).
#pragma once

#include <string>
#include <vector>

#include "darp_engine.hpp"

namespace swarm::planner::detail {

struct RepairOutcome {
  int moves = 0;              // cells that changed hands
  bool goal = false;          // every region connected, holding its start, within tolerance
};

// `owner` (per compact cell: its robot) and `starts` (per robot: a compact cell it owns) are
// changed in place; `robots` are the robots' own cells (compact), which released starts move
// towards.
RepairOutcome repair_division(const DarpSpace& space, std::vector<int>& owner, std::vector<int>& starts,
                              const std::vector<int>& robots, double tolerance);

std::string no_balanced_division(const DarpSpace& space, double tolerance);

}  // namespace swarm::planner::detail
