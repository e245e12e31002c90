// From a DARP division (darp.hpp) to every robot's coverage path: the way to its region, then
// spanning-tree coverage of the region (stc.hpp). The one call the live coverage task needs.
//
// With DarpInit::Given every region holds its robot and the approach is empty. With the other
// initialisations a region grows from a start the robot may not stand on (the paper's relocated
// initial positions), so the robot first drives, by a shortest 4-connected path through Free cells
// of the map (other robots' regions included), to the nearest cell of its own region, and covers
// the region from there.
//
//   DarpResult d = divide_areas(map, request, config);
//   std::vector<CoveragePlan> plans = plan_coverage(map, d, request.robots);
//   for (const Cell& c : plans[r].path()) drive(c);   // approach, then coverage
//
// Deterministic; thread-safe (no shared state).
#pragma once

#include <vector>

#include "swarm/planner/coverage/darp.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/coverage/stc.hpp"

namespace swarm::planner {

struct CoveragePlan {
  std::vector<Cell> approach;  // robot's cell first, ends on the region's first cell; empty when
                               // the robot stands in its region or cannot reach it
  bool reachable = true;       // false: no 4-connected way from the robot to its region
  StcPath coverage;            // from approach.back() (or the robot's cell)

  // The whole drive: approach then coverage, the joining cell once. Empty if !reachable.
  [[nodiscard]] std::vector<Cell> path() const;
};

// The region of robot r as a grid: Free where assignment == r, Occupied elsewhere.
[[nodiscard]] OccupancyGrid region_of(const OccupancyGrid& map, const std::vector<int>& assignment, int robot);

// One plan per robot (robots[r] is robot r's current cell; usually the request's robots).
[[nodiscard]] std::vector<CoveragePlan> plan_coverage(const OccupancyGrid& map, const DarpResult& division,
                                                      const std::vector<Cell>& robots,
                                                      const StcConfig& config = {});

}  // namespace swarm::planner
