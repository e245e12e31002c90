// A map named on the command line or in a tour file: a built-in name (maps/, see
// config::builtin_map_names), a ROS map_server YAML file, or a MovingAI `.map` file.
//
//   OccupancyGrid room = load_named_map("clutter");                 // maps/clutter.yaml
//   OccupancyGrid m = load_named_map("maze.map", "scenarios/tour");  // relative to that folder
//
// A MovingAI map has no scale; its cells are taken as `movingai_cell_m` metres (default 0.1 m,
// the cleaning paper's cell). Throws std::runtime_error whose message names the map and what is
// accepted (or the file, line and field that is wrong, from map_io.hpp). Thread-safe.
#pragma once

#include <string>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::tools {

[[nodiscard]] planner::OccupancyGrid load_named_map(const std::string& map, const std::string& base_dir = "",
                                                    double movingai_cell_m = 0.1);

}  // namespace swarm::tools
