#include "swarm/config/task_config.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::config {

planner::CoverRoutesConfig cover_routes_config(const swarm::scenario::Cover& c, std::uint64_t seed,
                                               std::uint64_t salt) {
  planner::CoverRoutesConfig out;
  switch (c.darp_init()) {
    case swarm::scenario::DARP_GIVEN: out.darp.init = planner::DarpInit::Given; break;
    case swarm::scenario::DARP_RANDOM: out.darp.init = planner::DarpInit::Random; break;
    case swarm::scenario::DARP_KMEANS: out.darp.init = planner::DarpInit::KMeans; break;
    default: out.darp.init = planner::DarpInit::BfsKMeans; break;
  }
  out.darp.distance =
      c.darp_distance() == swarm::scenario::DARP_EUCLIDEAN ? planner::DarpDistance::Euclidean : planner::DarpDistance::Geodesic;
  out.darp.max_iterations = static_cast<int>(c.darp_max_iterations());
  out.darp.seed = planner::mix_seed(seed, salt);
  switch (c.order()) {
    case swarm::scenario::ORDER_PLOW: out.order = planner::CoverOrder::Plow; break;
    case swarm::scenario::ORDER_GROUP_K: out.order = planner::CoverOrder::GroupK; break;
    default: out.order = planner::CoverOrder::Stc; break;
  }
  return out;
}

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
    if (phases[i].has_explore()) return false;
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

swarm::scenario::Mapf resolved_mapf(const swarm::scenario::Mapf& mapf, const swarm::scenario::Scenario& s) {
  swarm::scenario::Mapf m = mapf;
  if (m.execution() != swarm::scenario::MAPF_EXECUTE_AUTO) return m;
  auto undelayed = [](const swarm::scenario::Link& l) { return l.delay_ticks() == 0 && l.jitter_ticks() == 0; };
  // Any fault (a kill too: timed robots would not wait for a dead one's replanned neighbours,
  // and a route through its cell would block for good) calls for the graph.
  const bool timed = delivery_ticks_bounded(s) && s.faults_size() == 0 && undelayed(s.links().sim_robot()) &&
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

}  // namespace swarm::config
