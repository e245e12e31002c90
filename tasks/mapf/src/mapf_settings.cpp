#include "swarm/tasks/mapf/mapf_settings.hpp"

#include "swarm/config/task_config.hpp"

namespace swarm::tasks {

swarm::scenario::Mapf resolved_mapf(const swarm::scenario::Mapf& mapf, const swarm::scenario::Scenario& s) {
  swarm::scenario::Mapf m = mapf;
  if (m.execution() != swarm::scenario::MAPF_EXECUTE_AUTO) return m;
  auto undelayed = [](const swarm::scenario::Link& l) { return l.delay_ticks() == 0 && l.jitter_ticks() == 0; };
  // Any fault (a kill too: timed robots would not wait for a dead one's replanned neighbours,
  // and a route through its cell would block for good) calls for the graph.
  const bool timed = config::delivery_ticks_bounded(s) && s.faults_size() == 0 && undelayed(s.links().sim_robot()) &&
                     undelayed(s.links().member_leader()) && undelayed(s.links().leader_gcs());
  m.set_execution(timed ? swarm::scenario::MAPF_EXECUTE_TIMED : swarm::scenario::MAPF_EXECUTE_ADG);
  return m;
}

planner::mapf::SolverConfig mapf_solver_config(const swarm::scenario::Mapf& m, std::uint64_t seed) {
  planner::mapf::SolverConfig c;
  switch (m.solver()) {
    case swarm::scenario::MAPF_CBS: c.kind = planner::mapf::SolverKind::Cbs; break;
    case swarm::scenario::MAPF_LACAM: c.kind = planner::mapf::SolverKind::Lacam; break;
    default: c.kind = planner::mapf::SolverKind::Ecbs; break;
  }
  c.ecbs.w = m.w();
  c.lacam.seed = seed;
  return c;
}

swarm::scenario::Mapf traffic_driving() {
  swarm::scenario::Mapf m;
  m.set_execution(swarm::scenario::MAPF_EXECUTE_ADG);
  return m;
}

}  // namespace swarm::tasks
