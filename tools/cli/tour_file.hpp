// A tour file (planner/tours/tour_file.hpp) whose `map` line names a map as everywhere on the
// `swarm` line (named_map.hpp: a built-in name, a map_server YAML or a MovingAI .map).
#pragma once

#include <string>

#include "swarm/planner/tours/tour_file.hpp"

namespace swarm::tools {

using planner::TourFile;
using planner::TourFileError;

[[nodiscard]] TourFile load_tour_file(const std::string& path);

}  // namespace swarm::tools
