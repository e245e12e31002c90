#include "swarm/member/robot_agent.hpp"

#include "swarm/planner/sensing/raycast.hpp"

namespace swarm::member {

using planner::Cell;
using planner::CellChange;

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

RobotAgent::Step RobotAgent::step(std::uint32_t tick) {
  Step out;
  if (!follow_) return out;  // no route yet: the robot stands where it is
  step_following(out, tick);
  if (out.path_changed) {
    out.route_id = ++sent_id_;
    follow_->sim_id = out.route_id;
  }
  return out;
}

}  // namespace swarm::member
