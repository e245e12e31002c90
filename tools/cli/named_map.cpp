#include "named_map.hpp"

#include <filesystem>
#include <stdexcept>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/grid/map_io.hpp"

namespace swarm::tools {

planner::OccupancyGrid load_named_map(const std::string& map, const std::string& base_dir,
                                      double movingai_cell_m) {
  namespace fs = std::filesystem;
  fs::path path(map);
  if (path.extension() == ".map") {
    if (path.is_relative() && !base_dir.empty()) path = fs::path(base_dir) / path;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw std::runtime_error("no MovingAI map file " + path.string());
    return planner::load_movingai_map(path.string(), movingai_cell_m);
  }
  try {
    return planner::load_map_yaml(config::resolve_map_path(map, base_dir));
  } catch (const config::ConfigError& e) {
    throw std::runtime_error(std::string(e.what()) + "; or a MovingAI .map file");
  }
}

}  // namespace swarm::tools
