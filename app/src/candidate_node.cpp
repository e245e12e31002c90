#include "swarm/app/candidate_node.hpp"

#include <nlohmann/json.hpp>

#include "swarm/comm/leadership.hpp"

namespace swarm::app {

CandidateNode::CandidateNode(comm::LockstepAgent& agent, const RoleSetup& setup, int group, int index,
                             const leader::GroupTaskFactory& make_task)
    : self_(agent.self()),
      topology_(setup.topology),
      group_(group),
      robot_(setup.world.frame.width, setup.world.frame.height, setup.world.frame.resolution),
      member_(agent, setup, group, robot_),
      leader_(agent, setup, group, index, robot_, agent.self() == setup.topology.leader(group), make_task) {
  // The first leader leads from tick 0: its first scans are the leader side's already.
  if (leader_.leading()) lead();
}

void CandidateNode::lead() {
  member_.lead([this](const std::vector<planner::CellChange>& changes) { leader_.learn_own(changes); });
}

void CandidateNode::step(const msgs::Clock& clock) {
  const bool named = comm::leader_in(clock, topology_, group_) == self_;
  if (named && !leader_.leading()) {
    leader_.take_over(clock);
    lead();
  } else if (!named && leader_.leading()) {
    leader_.stand_down(clock.tick());
    member_.follow();
  }
  if (leader_.leading()) {
    member_.observe(clock);
    leader_.step(clock);
  } else {
    leader_.shadow(clock);
    member_.step(clock);
  }
}

std::string CandidateNode::report_json() const {
  nlohmann::json out = nlohmann::json::parse(leader_.report_json());
  out["member"] = nlohmann::json::parse(member_.report_json());
  return out.dump();
}

}  // namespace swarm::app
