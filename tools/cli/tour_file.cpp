#include "tour_file.hpp"

#include "named_map.hpp"

namespace swarm::tools {

TourFile load_tour_file(const std::string& path) {
  return planner::load_tour_file(
      path, [](const std::string& name, const std::string& folder) { return load_named_map(name, folder); });
}

}  // namespace swarm::tools
