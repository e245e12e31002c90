// What the live experiments (experiment_tasks.cpp, experiment_mission.cpp) change in a run's
// scenario, and how they read a number a phase's task reported.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>

#include "swarm/config/scenario.hpp"
#include "swarm/record/metrics.hpp"

namespace swarm::tools {

using ScenarioChange = std::function<void(swarm::scenario::Scenario&)>;

inline ScenarioChange member_leader_delay(std::uint32_t ticks, std::uint32_t jitter) {
  return [=](swarm::scenario::Scenario& s) {
    s.mutable_links()->mutable_member_leader()->set_delay_ticks(ticks);
    s.mutable_links()->mutable_member_leader()->set_jitter_ticks(jitter);
  };
}

inline ScenarioChange every_link_loss(double loss) {
  return [=](swarm::scenario::Scenario& s) {
    for (auto* l : {s.mutable_links()->mutable_sim_robot(), s.mutable_links()->mutable_member_leader(),
                    s.mutable_links()->mutable_leader_gcs()}) {
      l->set_loss(loss);
    }
  };
}

// A number of the phase's task in metrics.json (phases[i].task[key]); NaN when it has none.
inline double task_number(const record::PhaseMetrics& p, const std::string& key) {
  const auto it = p.task.find(key);
  if (it == p.task.end() || !it->is_number()) return std::nan("");
  return it->get<double>();
}

}  // namespace swarm::tools
