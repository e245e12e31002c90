#include "swarm/comm/topology.hpp"

#include <cctype>

namespace swarm::comm {

std::vector<AgentId> Topology::leaders() const {
  std::vector<AgentId> out;
  for (int g = 0; g < groups_; ++g) out.push_back(leader(g));
  return out;
}

std::vector<AgentId> Topology::candidates(int group) const {
  std::vector<AgentId> out;
  for (int i = 0; i <= standbys_; ++i) out.push_back(robot(group, i));
  return out;
}

std::vector<AgentId> Topology::all_candidates() const {
  std::vector<AgentId> out;
  for (int g = 0; g < groups_; ++g) {
    for (AgentId a : candidates(g)) out.push_back(a);
  }
  return out;
}

std::vector<AgentId> Topology::group_except(int group, AgentId a) const {
  std::vector<AgentId> out;
  for (int i = 0; i < per_group_; ++i) {
    if (robot(group, i) != a) out.push_back(robot(group, i));
  }
  return out;
}

std::vector<AgentId> Topology::robot_ids() const {
  std::vector<AgentId> out;
  for (int r = 0; r < robots(); ++r) out.push_back(static_cast<AgentId>(r));
  return out;
}

std::vector<AgentId> Topology::all_but_sim() const {
  std::vector<AgentId> out = robot_ids();
  out.push_back(gcs());
  return out;
}

std::string Topology::name_of(AgentId a) const {
  if (a == gcs()) return "gcs";
  if (a == sim()) return "sim";
  if (!is_robot(a)) return "agent-" + std::to_string(a);
  const int g = group_of(a);
  const int i = index_of(a);
  if (i == 0) return "leader-" + std::to_string(g);
  return "member-" + std::to_string(g) + "-" + std::to_string(i);
}

std::optional<AgentId> Topology::agent_named(const std::string& name) const {
  for (int a = 0; a < agents(); ++a) {
    if (name_of(static_cast<AgentId>(a)) == name) return static_cast<AgentId>(a);
  }
  return std::nullopt;
}

namespace topic {
std::string family(const std::string& name) {
  // Strip a trailing "_<digits>" or "_g<digits>".
  std::size_t end = name.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(name[end - 1]))) --end;
  if (end == name.size()) return name;
  if (end > 0 && name[end - 1] == 'g') --end;
  if (end > 0 && name[end - 1] == '_') return name.substr(0, end - 1);
  return name;
}
}  // namespace topic

}  // namespace swarm::comm
