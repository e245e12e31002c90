// Who is who in a run: agent ids and topic names, derived from groups x robots_per_group.
//
// Robots are agents 0..N-1 (robot = group * robots_per_group + index; index 0 is the group's
// first leader), the GCS is agent N and the simulator agent N+1. Every process derives the same
// numbering from the scenario, so no discovery of roles is needed.
//
// Candidates: indices 0..standbys of a group may lead it (leadership.hpp). Index 0 leads from the
// start; indices 1..standbys are standbys, members that keep a leader's endpoints ready so that
// one of them can take the group over when its leader is lost. Every topic a leader reads or
// writes therefore has all the group's candidates as readers or writers from tick 0 on.
//
// Topics are named per recipient (sense_3, patch_up_g1, ...) rather than keyed: each process
// then receives only its own data, instead of every member deserialising all nine scans a tick.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarm::comm {

using AgentId = std::uint16_t;

class Topology {
 public:
  Topology(int groups, int robots_per_group, int standbys = 0)
      : groups_(groups), per_group_(robots_per_group), standbys_(standbys < robots_per_group ? standbys : robots_per_group - 1) {}

  int groups() const { return groups_; }
  int robots_per_group() const { return per_group_; }
  int robots() const { return groups_ * per_group_; }
  int agents() const { return robots() + 2; }
  AgentId gcs() const { return static_cast<AgentId>(robots()); }
  AgentId sim() const { return static_cast<AgentId>(robots() + 1); }

  AgentId robot(int group, int index) const { return static_cast<AgentId>(group * per_group_ + index); }
  AgentId leader(int group) const { return robot(group, 0); }  // the first leader (see leadership.hpp)
  int standbys() const { return standbys_; }
  bool is_candidate(AgentId a) const { return is_robot(a) && index_of(a) <= standbys_; }
  int group_of(AgentId robot_id) const { return robot_id / per_group_; }
  int index_of(AgentId robot_id) const { return robot_id % per_group_; }
  bool is_robot(AgentId a) const { return a < robots(); }

  std::vector<AgentId> leaders() const;
  std::vector<AgentId> candidates(int group) const;  // indices 0..standbys
  std::vector<AgentId> all_candidates() const;       // every group's, group by group
  // The robots of `group` except `a` (a candidate's readers and writers leave out itself).
  std::vector<AgentId> group_except(int group, AgentId a) const;
  std::vector<AgentId> robot_ids() const;
  std::vector<AgentId> all_but_sim() const;  // robots and the GCS: who receives the clock

  // "gcs", "sim", "leader-1", "member-1-2": the names used for logs and reports.
  std::string name_of(AgentId a) const;
  // The inverse of name_of; nullopt for a name that is not an agent of this topology.
  std::optional<AgentId> agent_named(const std::string& name) const;

 private:
  int groups_;
  int per_group_;
  int standbys_ = 0;
};

// Topic names. Families (the name without the per-recipient suffix) key the traffic accounts.
namespace topic {
inline const std::string kClock = "clock";
inline const std::string kDone = "done";
inline const std::string kMotion = "motion";
inline const std::string kPatchGcs = "patch_gcs";
inline const std::string kRound = "round";
inline const std::string kHeartbeat = "heartbeat";
inline const std::string kPlanReport = "plan_report";
inline const std::string kPlanned = "planned";  // GCS -> watchers only (msgs::PlannedRoute)
inline const std::string kReport = "report";
inline const std::string kPhase = "phase";
// The same announcement to the simulator, on the unemulated control link: the simulator is the
// world, not a radio node, and must move the robots by a phase's motion model before any robot
// acts on that phase's orders (a lost and repeated announcement would come after them).
inline const std::string kPhaseSim = "phase_sim";
inline const std::string kTaskOrder = "task_order";
inline const std::string kTaskReport = "task_report";
inline std::string sense(AgentId robot) { return "sense_" + std::to_string(robot); }
inline std::string patch_up(int group) { return "patch_up_g" + std::to_string(group); }
inline std::string patch_down(int group) { return "patch_down_g" + std::to_string(group); }
inline std::string route(int group) { return "route_g" + std::to_string(group); }
inline std::string release(int group) { return "release_g" + std::to_string(group); }
inline std::string progress(int group) { return "progress_g" + std::to_string(group); }
// "sense_3" -> "sense", "patch_up_g1" -> "patch_up".
std::string family(const std::string& topic_name);
}  // namespace topic

}  // namespace swarm::comm
