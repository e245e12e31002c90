// swarm-leader's node: the leader is a robot too (a RobotAgent for its own body) plus its group's
// side of the mission. It merges its members' map changes into the group map, forwards the group's
// new information to the GCS, relays the group map to its members, notices members the simulator
// declares lost, and runs the current phase's GroupTask (group_task.hpp), routing the phase's
// messages to it.
//
// Any candidate of the group (comm/leadership.hpp) has one: the leader of the moment steps it;
// a standby shadows (keeps the group map from what it hears, and the GCS's latest phase, round and
// orders) until the clock names it leader, then takes over: its own map joins the group map, and
// the current phase's task starts afresh from the GCS's order (candidate_node.hpp drives this).
//
// Between phases (PhaseStart.settle, gcs/gcs_node.hpp) the node, not a task, stops each living
// robot of the group where it stands (an empty route), and once the simulator has confirmed
// every stop, reports the group standing to the GCS (TaskReport Held, values [0]); the next
// phase's task starts when the GCS announces the phase without `settle`.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/leader/group_map.hpp"
#include "swarm/leader/group_task.hpp"
#include "swarm/member/robot_agent.hpp"
#include "swarm/planner/grid/map_patch.hpp"

namespace swarm::leader {

class LeaderNode {
 public:
  // `robot` is the leader's own body, owned by the caller; `index` its index in the group.
  // make_task: each phase's task (tasks::group_task, the task registry).
  LeaderNode(comm::LockstepAgent& agent, const app::RoleSetup& setup, int group, int index,
             member::RobotAgent& robot, bool leading, const GroupTaskFactory& make_task);
  void step(const msgs::Clock& clock);    // every tick while leading
  void shadow(const msgs::Clock& clock);  // every tick while another leads
  void take_over(const msgs::Clock& clock);
  void stand_down(std::uint32_t tick);
  // The own robot's scan changes (through its member side, which owns the sense topic).
  void learn_own(const std::vector<planner::CellChange>& changes);
  bool leading() const { return leading_; }
  std::string report_json() const;
  std::uint32_t phase() const { return phase_; }

 private:
  void learn(const std::vector<planner::CellChange>& fresh, bool own_observation);
  void track_members(const msgs::Clock& clock, GroupContext& ctx);
  void dispatch(GroupContext& ctx);
  void enter_phase();  // a PhaseStart that came makes its phase current
  // Between phases: stops the group's robots and reports them standing (see the header).
  void settle(GroupContext& ctx);
  void stopped(int index, const planner::RouteProgress& p);  // a robot's progress while settling

  comm::LockstepAgent& agent_;
  const app::RoleSetup& setup_;
  const comm::Topology topology_;
  int group_;
  int self_index_;
  bool leading_;
  planner::PatchEncoding encoding_;
  GroupMap map_;
  member::RobotAgent& robot_;
  std::vector<planner::CellChange> to_gcs_;
  std::vector<planner::CellChange> to_members_;
  std::vector<bool> alive_;  // per robot of the group, from the clock's shared robot states

  // The mission: one task per phase; messages for the current phase wait here for the next step.
  std::vector<std::unique_ptr<GroupTask>> tasks_;
  std::uint32_t phase_ = 0;
  bool started_ = false;
  bool taking_over_ = false;      // the next start() is a take-over's (GroupTask::took_over)
  std::uint32_t gcs_back_at_ = 0;  // the GCS's latest restart seen (Clock.counted_from)
  std::optional<std::vector<std::uint32_t>> own_carrying_;  // what the own robot held, as last told the task
  struct PhaseCall {
    std::uint32_t phase = 0;
    bool settle = false;
  };
  std::optional<PhaseCall> next_phase_;
  // Settling: whether the stops were sent, (group index, stop's route id) of the robots whose stop
  // is not yet confirmed, and whether the GCS has been told the group stands.
  bool settling_ = false;
  bool stops_sent_ = false;
  std::vector<std::pair<int, std::uint32_t>> stopping_;
  bool settle_reported_ = false;
  std::optional<std::uint32_t> round_;
  std::uint32_t last_round_ = 0;
  std::vector<msgs::TaskOrder> orders_;
  std::vector<msgs::RouteProgress> progress_;
  planner::RouteProgress own_progress_;
  GroupOutlets outlets_;
  std::uint32_t route_ids_;

  comm::Mailbox::Outlet<msgs::MapPatch>& patch_gcs_;
  comm::Mailbox::Outlet<msgs::MapPatch>* patch_down_ = nullptr;  // none in a group of one
  comm::Mailbox::Outlet<msgs::Heartbeat>& heartbeat_;
  comm::Mailbox::Outlet<msgs::MotionCommand>& motion_;

  struct MemberLoss {
    std::string name;
    std::uint32_t noticed_tick;
    std::optional<std::uint32_t> rejoined_tick;  // its link healed
  };
  std::vector<MemberLoss> members_lost_;
  struct Term {
    std::uint32_t from;
    std::optional<std::uint32_t> to;  // still leading at the end
  };
  std::vector<Term> led_;
};

// Every known cell of `map`, as changes (what a new leader hands on).
std::vector<planner::CellChange> known_cells(const planner::OccupancyGrid& map);

}  // namespace swarm::leader
