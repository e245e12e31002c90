// swarm-member's node: a RobotAgent wired to its topics. Scans come from the simulator, map
// changes go up to the group leader, the leader's group map changes and its orders come down:
// waypoints (exploration: the robot plans its own way) or routes to follow exactly (every other
// task), with releases; the member reports its progress along a route. A member knows no task.
#pragma once

#include <string>

#include "swarm/comm/lockstep.hpp"
#include "swarm/comm/role.hpp"
#include "swarm/member/robot_agent.hpp"
#include "swarm/planner/map_patch.hpp"

namespace swarm::member {

class MemberNode {
 public:
  MemberNode(comm::LockstepAgent& agent, const comm::RoleSetup& setup, int group, int index);
  void step(const msgs::Clock& clock);
  std::string report_json() const;

 private:
  comm::LockstepAgent& agent_;
  int group_;
  int index_;
  RobotAgent robot_;
  std::vector<planner::CellChange> pending_up_;
  comm::Mailbox::Outlet<msgs::MapPatch>& patch_up_;
  comm::Mailbox::Outlet<msgs::MemberStatus>& status_;
  comm::Mailbox::Outlet<msgs::MotionCommand>& motion_;
  comm::Mailbox::Outlet<msgs::RouteProgress>& progress_;
  planner::RouteProgress reported_;  // the last progress sent to the leader
  planner::PatchEncoding encoding_;
  std::uint64_t assignments_ = 0;
  std::uint64_t routes_ = 0;
};

// Sends the robot's outputs of one step: a changed path to the simulator, a waypoint report to
// the leader (through `report`). Shared by the member and the leader's own robot.
void publish_motion(comm::Mailbox::Outlet<msgs::MotionCommand>& motion, comm::AgentId robot,
                    const RobotAgent::Step& step);
// The robot follows the route message's cells (shared by the member and the leader's own robot).
void follow_route(RobotAgent& robot, const msgs::Route& route);

}  // namespace swarm::member
