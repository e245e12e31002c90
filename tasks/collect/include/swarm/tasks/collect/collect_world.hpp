// A collect phase's objects and destinations, fixed at load from the scenario and the map (its
// registry row's `resolve`).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/tours/tour.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::tasks {

// The objects and destinations of a collect phase: the scenario's (metres in the map frame) or,
// none listed, `scatter` objects of each of `types` types at distinct free cells reachable from
// the start (8-connected, not a robot's start cell), drawn from the run's seed; destinations the
// scenario's or, none listed, `types` free cells beside a wall spread over the map. The simulator,
// the GCS and the leaders all compute it from the scenario, so object i is the same everywhere.
// Throws config::ConfigError naming `field` for an object or destination outside the map, on a blocked or
// unreachable cell, or a type with no destination.
struct CollectWorld {
  std::vector<planner::TourObject> objects;
  std::vector<planner::Cell> destinations;  // per type
};
[[nodiscard]] CollectWorld collect_world(const swarm::scenario::Collect& collect, const planner::OccupancyGrid& map,
                                         const std::vector<planner::Cell>& robot_cells, std::uint64_t seed,
                                         const std::string& field);

}  // namespace swarm::tasks
