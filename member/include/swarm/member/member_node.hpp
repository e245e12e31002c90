// swarm-member's node: a RobotAgent wired to its topics. Scans come from the simulator, map
// changes go up to the group leader, the leader's group map changes and its orders come down:
// routes to follow exactly (the traffic layer's, in every task), with releases and the watches
// that open a route further as the robots in the clock move (watched_releases.hpp); the member
// reports its progress along a route. A member knows no task.
//
// It obeys only its group's leader of the moment (comm/leadership.hpp): orders from a robot that
// did not lead the group at the tick they were sent are dropped and counted. A standby leader's
// member side (app/candidate_node.hpp) is switched off while that robot leads: its scans then
// go to the leader side (lead()), and it takes no orders.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "swarm/comm/leadership.hpp"

#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/member/robot_agent.hpp"
#include "swarm/member/watched_releases.hpp"
#include "swarm/planner/grid/map_patch.hpp"

namespace swarm::member {

class MemberNode {
 public:
  // `robot`: the robot's body and map, owned by the caller (a standby shares it with its leader side).
  MemberNode(comm::LockstepAgent& agent, const app::RoleSetup& setup, int group, RobotAgent& robot);
  // Every tick: step() while a member (it observes the clock's leaders too), observe() alone while
  // this robot leads.
  void observe(const msgs::Clock& clock) { leaders_.observe(clock); }
  void step(const msgs::Clock& clock);
  // While this robot leads its group: scans go to `to_leader` (with what was not sent up yet).
  void lead(std::function<void(const std::vector<planner::CellChange>&)> to_leader);
  void follow();  // a member again
  std::string report_json() const;

  static constexpr std::uint32_t kProgressRefreshTicks = 16;  // progress sent again, this often

 private:
  comm::LockstepAgent& agent_;
  int group_;
  // Whether `sender` led this group at `tick` (orders from anyone else are dropped).
  bool from_leader(const msgs::Stamp& stamp);

  RobotAgent& robot_;
  WatchedReleases watched_;  // the leader's release watches, followed in the clock
  comm::LeaderLog leaders_;
  std::function<void(const std::vector<planner::CellChange>&)> to_leader_;  // set while leading
  std::uint64_t not_from_leader_ = 0;
  std::vector<planner::CellChange> pending_up_;
  comm::Mailbox::Outlet<msgs::MapPatch>& patch_up_;
  comm::Mailbox::Outlet<msgs::MotionCommand>& motion_;
  comm::Mailbox::Outlet<msgs::RouteProgress>& progress_;
  planner::RouteProgress reported_;  // the last progress sent to the leader
  std::vector<std::uint32_t> reported_carrying_;  // and what the robot held then
  comm::AgentId reported_to_ = 0;                 // and which leader it went to
  planner::PatchEncoding encoding_;
  std::uint64_t routes_ = 0;
};

// Sends a changed part of the robot's route to the simulator. Shared by the member and the
// leader's own robot.
void publish_motion(comm::Mailbox::Outlet<msgs::MotionCommand>& motion, comm::AgentId robot,
                    const RobotAgent::Step& step);
// The group's candidate leaders but `self`: who reads what a member sends up.
std::vector<comm::AgentId> leaders_except_self(const comm::Topology& t, int group, comm::AgentId self);
// The robot follows the route message's cells (shared by the member and the leader's own robot).
void follow_route(RobotAgent& robot, const msgs::Route& route);

}  // namespace swarm::member
