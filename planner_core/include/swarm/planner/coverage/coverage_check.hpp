// Independent checks of a DARP division (darp.hpp) and of coverage paths (stc.hpp): what the
// tests, `swarm darp` and the live coverage task use to trust a result. Written apart from the
// algorithms on purpose (their own flood fills, MotionModel::four() for every step), so a bug in
// the planners is not repeated here.
//
//   std::vector<std::string> problems = check_division(map, request, result);
//   problems = check_coverage_path(region_of(map, result.assignment, r), start, path);
//   if (!problems.empty()) { /* each names the robot, cell or step */ }
//
// Deterministic; thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarm/planner/coverage/darp.hpp"
#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

// A division must: mark cells outside the region (blocked, or not in request.region) -1, region
// cells no robot can reach -2, every other region cell with one robot; agree with result.cells,
// result.unreachable_cells and result.split_regions; give every robot its start cell (the robot's
// own cell when `given_starts`: DarpInit::Given with DivisionMethod::Darp); when converged or
// impossible, have every region 4-connected; and, when converged, every region within
// `tolerance_cells` of result.shares, the shares adding up to the cells divided.
[[nodiscard]] std::vector<std::string> check_division(const OccupancyGrid& map, const DarpRequest& request,
                                                      const DarpResult& result, bool given_starts,
                                                      double tolerance_cells = 1.0);

// A coverage path must start at `start`, move by legal 4-connected steps (no waits, no jumps)
// through Free cells of `region` only, and visit every cell of the region's 4-connected piece
// holding `start`.
[[nodiscard]] std::vector<std::string> check_coverage_path(const OccupancyGrid& region, Cell start,
                                                           const std::vector<Cell>& path);

// Several robots' routes over a set of cells (cover_tours.hpp, or any division's routes): one
// route per robot, starting at its cell, moving by legal 4-connected steps through Free cells of
// `map` (anywhere, not only the set), and together visiting every cell of the set that some
// robot can reach.
[[nodiscard]] std::vector<std::string> check_cover_routes(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                                                          const std::vector<Cell>& robots,
                                                          const std::vector<std::vector<Cell>>& routes);

}  // namespace swarm::planner
