// swarm-leader's node: the leader is a robot too (a RobotAgent for its own body) plus the group's
// planner. It merges its members' map changes into the group map, forwards the group's new
// information to the GCS, relays the group map to its members, and at every planning round the
// GCS announces it plans the group's waypoints (planner/explore.hpp) and assigns them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "swarm/comm/lockstep.hpp"
#include "swarm/comm/role.hpp"
#include "swarm/leader/group_map.hpp"
#include "swarm/member/robot_agent.hpp"
#include "swarm/planner/explore.hpp"
#include "swarm/planner/map_patch.hpp"

namespace swarm::leader {

class LeaderNode {
 public:
  LeaderNode(comm::LockstepAgent& agent, const comm::RoleSetup& setup, int group);
  void step(const msgs::Clock& clock);
  std::string report_json() const;

 private:
  void learn(const std::vector<planner::CellChange>& fresh, bool own_observation);
  void plan(std::uint32_t round, const msgs::Clock& clock);

  comm::LockstepAgent& agent_;
  const comm::Topology topology_;
  int group_;
  planner::ExploreConfig explore_;
  planner::PatchEncoding encoding_;
  GroupMap map_;
  member::RobotAgent robot_;
  std::vector<planner::CellChange> to_gcs_;
  std::vector<planner::CellChange> to_members_;
  std::optional<std::uint32_t> pending_round_;
  std::uint32_t round_ = 0;
  std::vector<bool> arrived_;
  std::vector<bool> alive_;  // per robot of the group, from the clock's shared robot states
  bool group_reported_ = true;

  comm::Mailbox::Outlet<msgs::MapPatch>& patch_gcs_;
  comm::Mailbox::Outlet<msgs::MapPatch>* patch_down_ = nullptr;  // none in a group of one
  comm::Mailbox::Outlet<msgs::Assignment>* assign_ = nullptr;
  comm::Mailbox::Outlet<msgs::GroupStatus>& group_status_;
  comm::Mailbox::Outlet<msgs::PlanReport>& plan_report_;
  comm::Mailbox::Outlet<msgs::Heartbeat>& heartbeat_;
  comm::Mailbox::Outlet<msgs::MotionCommand>& motion_;

  // Numbers for the run's metrics (wall-clock planning time is not part of the deterministic record).
  std::uint64_t rounds_planned_ = 0;
  std::uint64_t case_a_ = 0;
  std::uint64_t case_b_ = 0;
  double planning_seconds_ = 0;
  struct MemberLoss {
    std::string name;
    std::uint32_t noticed_tick;
    std::optional<std::uint32_t> rejoined_tick;  // its link healed
  };
  std::vector<MemberLoss> members_lost_;
};

}  // namespace swarm::leader
