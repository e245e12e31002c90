#include "swarm/member/robot_agent.hpp"

#include <algorithm>
#include <cstdlib>

#include "swarm/planner/grid/astar.hpp"
#include "swarm/planner/sensing/raycast.hpp"

namespace swarm::member {

using planner::Cell;
using planner::CellChange;
using planner::CellState;

RobotAgent::RobotAgent(int width, int height, double resolution) : map_(width, height, resolution) {}

std::vector<CellChange> RobotAgent::sense(Cell pose, const std::vector<float>& ranges, float max_range,
                                         const planner::RouteProgress& route) {
  pose_ = pose;
  report_ = route;
  std::vector<CellChange> changes;
  planner::integrate_scan(map_, pose, ranges.data(), static_cast<int>(ranges.size()), max_range, &changes);
  return changes;
}

int RobotAgent::learn(const std::vector<CellChange>& changes) { return map_.apply(changes); }

void RobotAgent::assign(std::uint32_t round, std::optional<Cell> waypoint) {
  follow_.reset();
  follow_progress_ = {};
  round_ = round;
  waypoint_ = waypoint;
  path_.clear();
  stuck_ticks_ = 0;
}

bool RobotAgent::path_still_valid(std::size_t& at) const {
  // The simulator says where along the route the robot is; a rejected or abandoned route (a wall
  // stop) is not valid any more.
  if (path_.empty() || report_.id != sent_id_) return false;
  if (report_.state != planner::RouteState::Active && report_.state != planner::RouteState::Finished) return false;
  at = report_.step;
  if (at >= path_.size() || path_[at] != pose_) return false;
  for (std::size_t i = at; i < path_.size(); ++i) {
    if (map_.is_occupied(path_[i])) return false;
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

RobotAgent::Step RobotAgent::step(std::uint32_t tick) {
  Step out;
  out.round = round_;
  if (follow_) {
    step_following(out, tick);
    if (out.path_changed) {
      out.route_id = ++sent_id_;
      follow_->sim_id = out.route_id;
      stop_sent_ = out.path.empty();
    }
    return out;
  }
  stuck_ticks_ = (pose_ == last_pose_ && !path_.empty()) ? stuck_ticks_ + 1 : 0;
  last_pose_ = pose_;

  auto finish = [&](WaypointState state) {
    out.report = state;
    waypoint_.reset();
    path_.clear();
  };
  if (waypoint_) {
    const int chebyshev = std::max(std::abs(pose_.x - waypoint_->x), std::abs(pose_.y - waypoint_->y));
    if (pose_ == *waypoint_) {
      finish(WaypointState::Arrived);
    } else if (stuck_ticks_ >= kStuckTicks && chebyshev <= 2) {
      finish(WaypointState::BlockedNear);
    } else if (map_.is_occupied(*waypoint_)) {
      finish(WaypointState::Unreachable);
    } else if (path_.empty() || !in_flight()) {
      // A route still in flight is judged once the simulator has applied it.
      std::size_t at = 0;
      std::optional<Cell> avoid;
      if (stuck_ticks_ >= kStuckTicks && path_still_valid(at) && at + 1 < path_.size()) avoid = path_[at + 1];
      if (avoid || !path_still_valid(at)) {
        const std::vector<Cell> before = path_;
        // The simulator no longer follows a rejected or abandoned route: resend even the same cells.
        const bool followed = report_.id == sent_id_ && report_.state == planner::RouteState::Active;
        if (replan(avoid)) {
          if (avoid) stuck_ticks_ = 0;
          out.path_changed = path_ != before || !followed;
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
  if (out.path_changed) out.route_id = ++sent_id_;
  return out;
}

}  // namespace swarm::member
