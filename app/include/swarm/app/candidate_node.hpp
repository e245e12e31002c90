// A robot that may lead its group (comm/leadership.hpp: index 0, the first leader, and the
// standbys 1..leader_standbys): one body (RobotAgent) with a member side and a leader side.
//
// Each tick the clock names the group's leader. While that is another robot, this one is a member
// (MemberNode drives it from the leader's orders) and its leader side shadows; when the clock
// names this robot, the member side falls silent, its scans feed the leader side and that side
// takes over (LeaderNode::take_over). A leader the clock no longer names (it was lost and came
// back) stands down and is a member from then on. Both sides' endpoints exist from start-up,
// since DDS discovery must be complete before tick 0.
#pragma once

#include <string>

#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/leader/leader_node.hpp"
#include "swarm/member/member_node.hpp"
#include "swarm/member/robot_agent.hpp"

namespace swarm::app {

class CandidateNode {
 public:
  // make_task: each phase's group task (tasks::group_task, the task registry).
  CandidateNode(comm::LockstepAgent& agent, const RoleSetup& setup, int group, int index,
                const leader::GroupTaskFactory& make_task);
  void step(const msgs::Clock& clock);
  // The leader side's numbers (with its terms as leader, "led"), and the member side's under "member".
  std::string report_json() const;
  leader::LeaderNode& leader() { return leader_; }
  member::MemberNode& member() { return member_; }

 private:
  void lead();

  comm::AgentId self_;
  comm::Topology topology_;
  int group_;
  member::RobotAgent robot_;
  member::MemberNode member_;  // first: it owns the sense topic, the first subscription
  leader::LeaderNode leader_;
};

}  // namespace swarm::app
