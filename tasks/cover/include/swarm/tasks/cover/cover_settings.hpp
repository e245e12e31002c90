// A cover phase's settings (idl/scenario.proto Cover) as the coverage planner's inputs: the one
// translation the GCS's and the leaders' parts both use.
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "swarm/planner/coverage/cover_routes.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::tasks {

// DARP and the coverage order for a cover phase; `seed` is the run's (mixed with `salt` so the
// GCS's and each leader's divisions draw different numbers).
[[nodiscard]] planner::CoverRoutesConfig cover_routes_config(const swarm::scenario::Cover& cover, std::uint64_t seed,
                                                             std::uint64_t salt);

// What metrics.json keeps of one division: its status (and why, when not converged), the method
// that finished it, DARP's iterations, the cells the repair moved, seconds, and the cells per
// robot with their shares and imbalance (1 - Jain).
[[nodiscard]] nlohmann::json division_json(const planner::CoverRoutes& plan);

}  // namespace swarm::tasks
