#include "swarm/config/task_config.hpp"


#include "swarm/config/scenario.hpp"

namespace swarm::config {

bool delivery_ticks_bounded(const swarm::scenario::Scenario& s) {
  auto bounded = [](const swarm::scenario::Link& l) {
    return l.loss() == 0 && l.delay_ms() == 0 && l.bandwidth_bytes_per_s() == 0;
  };
  return !s.realtime() && bounded(s.links().sim_robot()) && bounded(s.links().member_leader()) &&
         bounded(s.links().leader_gcs());
}

bool map_given(const swarm::scenario::Scenario& s, std::size_t index) {
  const auto phases = mission_phases(s);
  for (std::size_t i = 0; i <= index && i < phases.size(); ++i) {
    if (task_field(phases[i]).options().GetExtension(swarm::scenario::learns_map)) return false;
  }
  return index < phases.size();
}

bool any_map_given(const swarm::scenario::Scenario& s) {
  const std::size_t phases = mission_phases(s).size();
  for (std::size_t i = 0; i < phases; ++i) {
    if (map_given(s, i)) return true;
  }
  return false;
}


}  // namespace swarm::config
