#include "swarm/member/robot_agent.hpp"

#include <algorithm>
#include <cstdlib>

#include "swarm/planner/astar.hpp"
#include "swarm/planner/raycast.hpp"

namespace swarm::member {

using planner::Cell;
using planner::CellChange;
using planner::CellState;

RobotAgent::RobotAgent(int width, int height, double resolution) : map_(width, height, resolution) {}

std::vector<CellChange> RobotAgent::sense(Cell pose, const std::vector<float>& ranges, float max_range) {
  pose_ = pose;
  std::vector<CellChange> changes;
  planner::integrate_scan(map_, pose, ranges.data(), static_cast<int>(ranges.size()), max_range, &changes);
  return changes;
}

int RobotAgent::learn(const std::vector<CellChange>& changes) { return map_.apply(changes); }

void RobotAgent::assign(std::uint32_t round, std::optional<Cell> waypoint) {
  round_ = round;
  waypoint_ = waypoint;
  path_.clear();
  stuck_ticks_ = 0;
}

bool RobotAgent::path_still_valid(std::size_t& at) const {
  auto it = std::find(path_.begin(), path_.end(), pose_);
  if (it == path_.end()) return false;  // pushed off the path (a late command, a blocked move)
  at = static_cast<std::size_t>(it - path_.begin());
  for (auto c = it; c != path_.end(); ++c) {
    if (map_.is_occupied(*c)) return false;
  }
  return true;
}

bool RobotAgent::replan(std::optional<Cell> avoid) {
  ++replans_;
  std::optional<std::vector<Cell>> path;
  if (avoid && *avoid != *waypoint_) {
    planner::OccupancyGrid detour = map_;
    detour.set(*avoid, CellState::Occupied);
    path = planner::astar(detour, pose_, *waypoint_);
  } else {
    path = planner::astar(map_, pose_, *waypoint_);
  }
  if (!path) return false;
  path_ = std::move(*path);
  return true;
}

RobotAgent::Step RobotAgent::step() {
  Step out;
  out.round = round_;
  stuck_ticks_ = (pose_ == last_pose_ && !path_.empty()) ? stuck_ticks_ + 1 : 0;
  last_pose_ = pose_;

  auto finish = [&](WaypointState state) {
    out.report = state;
    waypoint_.reset();
    path_.clear();
  };
  if (waypoint_) {
    const int chebyshev = std::max(std::abs(pose_.x - waypoint_->x), std::abs(pose_.y - waypoint_->y));
    if (pose_ == *waypoint_ || (stuck_ticks_ >= kStuckTicks && chebyshev <= 2)) {
      finish(WaypointState::Arrived);
    } else if (map_.is_occupied(*waypoint_)) {
      finish(WaypointState::Unreachable);
    } else {
      std::size_t at = 0;
      std::optional<Cell> avoid;
      if (stuck_ticks_ >= kStuckTicks && path_still_valid(at) && at + 1 < path_.size()) avoid = path_[at + 1];
      if (avoid || !path_still_valid(at)) {
        const std::vector<Cell> before = path_;
        if (replan(avoid)) {
          if (avoid) stuck_ticks_ = 0;
          out.path_changed = path_ != before;
          out.path = path_;
        } else if (!avoid) {
          finish(WaypointState::Unreachable);
        }
      }
    }
  }
  if (!waypoint_ && !stop_sent_) {
    out.path_changed = true;  // tell the simulator to stop this robot
    out.path.clear();
    stop_sent_ = true;
  } else if (out.path_changed) {
    stop_sent_ = false;
  }
  return out;
}

}  // namespace swarm::member
