// One robot's own logic, free of DDS: it maps what its LiDAR sees, drives to its waypoint with A*
// on what it knows, and re-plans when it meets an obstacle. Used by swarm-member for its robot and
// by swarm-leader for the leader's own robot.
//
//   RobotAgent robot(map_width, map_height, resolution);
//   auto changes = robot.sense(pose, ranges, max_range);  // send these to the leader
//   robot.assign(round, waypoint);
//   RobotAgent::Step s = robot.step();                     // s.path_changed -> send s.path to the sim
//
// Unknown cells count as free for planning (optimistic), so a robot heads into unexplored space
// and re-plans once its scans show the way is blocked. Not thread-safe.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/planner/grid.hpp"

namespace swarm::member {

enum class WaypointState : std::uint8_t { Arrived = 1, Unreachable = 2 };

class RobotAgent {
 public:
  RobotAgent(int width, int height, double resolution);

  // Integrates a scan taken at `pose` (ranges in cells); returns the cells it changed.
  std::vector<planner::CellChange> sense(planner::Cell pose, const std::vector<float>& ranges, float max_range);
  // Map knowledge from elsewhere (the leader's group map); returns how many cells changed.
  int learn(const std::vector<planner::CellChange>& changes);
  // A new waypoint for `round`; nullopt = stay.
  void assign(std::uint32_t round, std::optional<planner::Cell> waypoint);

  struct Step {
    bool path_changed = false;
    std::vector<planner::Cell> path;           // the new path (empty = stop), if path_changed
    std::optional<WaypointState> report;       // the waypoint is done with
    std::uint32_t round = 0;                   // the round the report belongs to
  };
  Step step();

  const planner::OccupancyGrid& map() const { return map_; }
  planner::Cell pose() const { return pose_; }
  std::optional<planner::Cell> waypoint() const { return waypoint_; }
  std::uint64_t replans() const { return replans_; }

  // A robot that has not moved for this many ticks while it has a path tries a detour around the
  // cell in front of it (another robot, usually), and counts as arrived within 2 cells of its goal.
  static constexpr int kStuckTicks = 4;

 private:
  bool path_still_valid(std::size_t& at) const;
  bool replan(std::optional<planner::Cell> avoid);

  planner::OccupancyGrid map_;
  planner::Cell pose_{-1, -1};
  planner::Cell last_pose_{-1, -1};
  int stuck_ticks_ = 0;
  std::optional<planner::Cell> waypoint_;
  std::uint32_t round_ = 0;
  std::vector<planner::Cell> path_;
  bool stop_sent_ = true;
  std::uint64_t replans_ = 0;
};

}  // namespace swarm::member
