// From a phase's settings in the scenario (idl/scenario.proto: Cover, Mapf, Collect) to the plain
// config structs of the planners in planner_core: the one translation both the GCS's and the
// leaders' side of a task use.
#pragma once

#include <cstdint>

#include "swarm/planner/cover_routes.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::config {

// DARP and the coverage order for a cover phase; `seed` is the run's (mixed with `salt` so the
// GCS's and each leader's divisions draw different numbers).
[[nodiscard]] planner::CoverRoutesConfig cover_routes_config(const swarm::scenario::Cover& cover, std::uint64_t seed,
                                                             std::uint64_t salt);

}  // namespace swarm::config
