#include "swarm/tasks/cover/cover_settings.hpp"

#include "swarm/planner/grid/rng.hpp"

namespace swarm::tasks {

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

}  // namespace swarm::tasks
