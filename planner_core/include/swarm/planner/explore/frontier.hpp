// Frontier detection and reachability on an occupancy grid.
//
// A frontier cell is a Free cell with at least one 4-neighbour that is Unknown (in bounds).
// Reachability uses the robots' motion model (motion.hpp; by default exploration's: 8-connected
// moves through Free cells that never cut a corner). Unknown cells are not passable.
//
//   auto all = find_frontiers(map);                       // row-major order (y, then x)
//   auto mine = reachable_frontiers(map, {robot_cell});   // only those a robot can drive to
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {

bool is_frontier(const OccupancyGrid& map, Cell c);

// Every frontier cell, in row-major order.
std::vector<Cell> find_frontiers(const OccupancyGrid& map);

// dist[index] = the fewest moves under `motion` from the nearest of `from` to that Free cell, -1
// where none reaches it (cells that are not Free are skipped as seeds). Deterministic.
std::vector<int> step_distances(const OccupancyGrid& map, const std::vector<Cell>& from, const MotionModel& motion);

// mask[index] = 1 for every Free cell reachable from any of `from` (step_distances >= 0).
std::vector<std::uint8_t> reachable_mask(const OccupancyGrid& map, const std::vector<Cell>& from,
                                         const MotionModel& motion = MotionModel::eight());

// The frontier cells reachable from any of `from`, in row-major order.
std::vector<Cell> reachable_frontiers(const OccupancyGrid& map, const std::vector<Cell>& from);

}  // namespace swarm::planner
