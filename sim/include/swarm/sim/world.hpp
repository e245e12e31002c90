// The simulated world, free of DDS: ground truth, robot bodies and their motion, LiDAR, and the
// ground-truth coverage the run is judged by. The simulator process is the only holder of it.
//
// Motion: each tick each robot moves at most one cell along its commanded path (8-connected, no
// corner cutting). Robots move in id order; a robot whose next cell holds another robot waits and
// the wait is counted. A path into a wall (planned through unknown space) stops the robot; its
// agent re-plans when its scan shows the wall.
//
//   World w(truth, robot_cells, {.beams = 360, .range_cells = 15});
//   w.command(robot, path);  // when a motion command is due
//   w.move();                // once per tick, before scanning
//   w.scan(robot, ranges);   // ranges in cells
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid.hpp"

namespace swarm::sim {

struct LidarConfig {
  int beams = 360;
  float range_cells = 15.0f;
};

class World {
 public:
  World(planner::OccupancyGrid truth, std::vector<planner::Cell> robot_cells, LidarConfig lidar);

  // A new path for `robot`; it continues from its current cell's place in the path. A path that
  // does not contain the robot's cell and does not start next to it is ignored (the agent sees it
  // did not move and re-plans).
  void command(int robot, const std::vector<planner::Cell>& path);
  void move();
  // Scans from the robot's cell and records what it saw in the coverage map.
  void scan(int robot, std::vector<float>& ranges);

  const std::vector<planner::Cell>& robots() const { return robots_; }
  const planner::OccupancyGrid& truth() const { return truth_; }
  const LidarConfig& lidar() const { return lidar_; }
  // Share of the free cells reachable from the start that some scan has seen.
  double explored_fraction() const;
  int reachable_free_cells() const { return reachable_free_; }
  std::uint64_t blocked_moves() const { return blocked_moves_; }
  std::uint64_t wall_stops() const { return wall_stops_; }
  std::uint64_t moves() const { return moves_; }

 private:
  bool can_step(planner::Cell from, planner::Cell to) const;

  planner::OccupancyGrid truth_;
  LidarConfig lidar_;
  std::vector<planner::Cell> robots_;
  std::vector<std::vector<planner::Cell>> paths_;
  std::vector<std::size_t> next_;  // index of the next path cell per robot
  planner::OccupancyGrid seen_;    // union of every scan
  std::vector<std::uint8_t> reachable_;  // ground truth: free cells reachable from the start
  int reachable_free_ = 0;
  int reachable_seen_ = 0;
  std::uint64_t blocked_moves_ = 0;
  std::uint64_t wall_stops_ = 0;
  std::uint64_t moves_ = 0;
};

}  // namespace swarm::sim
