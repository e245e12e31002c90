#include "swarm/tasks/cover/cover_settings.hpp"

#include <algorithm>
#include <cmath>

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
  out.candidates = static_cast<int>(std::max<std::uint32_t>(1, c.route_candidates()));
  out.balance_rounds = static_cast<int>(c.route_balance_rounds());
  switch (c.order()) {
    case swarm::scenario::ORDER_PLOW: out.order = planner::CoverOrder::Plow; break;
    case swarm::scenario::ORDER_GROUP_K: out.order = planner::CoverOrder::GroupK; break;
    default: out.order = planner::CoverOrder::Stc; break;
  }
  return out;
}

nlohmann::json division_json(const planner::CoverRoutes& plan) {
  const planner::DarpResult& d = plan.darp;
  nlohmann::json j = {{"darp_status", planner::to_string(d.status)},
                      {"finished_by", d.finished_by},
                      {"darp_iterations", d.iterations},
                      {"candidates_tried", plan.candidates_tried},
                      {"balance_rounds", plan.balance_rounds},
                      {"chosen", plan.chosen},
                      {"repair_moves", d.repair_moves},
                      {"darp_seconds", plan.seconds_division},
                      {"route_seconds", plan.seconds_routes},
                      {"cells", d.cells},
                      {"shares", d.shares},
                      {"final_imbalance", std::isfinite(d.final_imbalance) ? nlohmann::json(d.final_imbalance)
                                                                           : nlohmann::json()},
                      {"alpha0", std::isfinite(d.alpha0) ? nlohmann::json(d.alpha0) : nlohmann::json()}};
  if (!d.message.empty()) j["message"] = d.message;
  return j;
}

}  // namespace swarm::tasks
