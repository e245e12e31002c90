// A mapf phase's goals, fixed at load from the scenario and the map (its registry row's `resolve`).
#pragma once

#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::tasks {

// The goals of a mapf phase, one per robot in robot-id order: the scenario's points (metres in the
// map frame) or the first rows of its MovingAI `scen` (x = column, y = row from the top); empty
// when it gives neither (a random free cell per robot, chosen when the phase starts). Throws
// config::ConfigError naming `field` (and the file and line) for a goal outside the map, on a blocked
// cell, two robots with one goal, or a scen whose map size differs or with too few rows.
[[nodiscard]] std::vector<planner::Cell> mapf_goals(const swarm::scenario::Mapf& mapf, const planner::OccupancyGrid& map,
                                                    int robots, const std::string& field);

}  // namespace swarm::tasks
