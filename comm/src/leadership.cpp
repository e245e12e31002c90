#include "swarm/comm/leadership.hpp"

namespace swarm::comm {

std::vector<AgentId> next_leaders(const Topology& t, const std::vector<AgentId>& current,
                                  const std::vector<msgs::RobotState>& robots) {
  std::vector<AgentId> next = current;
  const auto alive = [&](AgentId a) { return a < robots.size() && robots[a].alive(); };
  for (int g = 0; g < t.groups(); ++g) {
    AgentId& lead = next[static_cast<std::size_t>(g)];
    if (alive(lead)) continue;
    for (AgentId c : t.candidates(g)) {
      if (alive(c)) {
        lead = c;
        break;
      }
    }
  }
  return next;
}

AgentId leader_in(const msgs::Clock& clock, const Topology& t, int group) {
  const auto g = static_cast<std::size_t>(group);
  return g < clock.leaders().size() ? clock.leaders()[g] : t.leader(group);
}

LeaderLog::LeaderLog(const Topology& t) : topology_(t), current_(t.leaders()) {}

void LeaderLog::observe(const msgs::Clock& clock) {
  if (clock.leaders().size() != current_.size() || (last_tick_ && clock.tick() <= *last_tick_)) return;
  for (std::size_t g = 0; g < current_.size(); ++g) {
    const AgentId to = clock.leaders()[g];
    if (to == current_[g]) continue;
    changes_.push_back({static_cast<int>(g), current_[g], to, clock.tick(), last_tick_.value_or(0)});
    current_[g] = to;
  }
  last_tick_ = clock.tick();
}

bool LeaderLog::led_at(AgentId robot, std::uint32_t tick) const {
  if (!topology_.is_robot(robot)) return false;
  const int g = topology_.group_of(robot);
  AgentId lead = topology_.leader(g);
  for (const Change& c : changes_) {
    if (c.group != g) continue;
    if (c.tick <= tick) {
      lead = c.to;
    } else if (tick > c.after && (robot == c.from || robot == c.to)) {
      return true;  // a skipped tick across this change: either may have led
    }
  }
  return lead == robot;
}

}  // namespace swarm::comm
