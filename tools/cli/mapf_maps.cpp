#include "mapf_maps.hpp"

#include <filesystem>
#include <stdexcept>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/grid/map_io.hpp"

namespace swarm::tools {

namespace pm = swarm::planner::mapf;

MapfMap load_mapf_map(const std::string& spec) {
  MapfMap m;
  m.name = std::filesystem::path(spec).filename().string();
  if (const auto size = pm::parse_warehouse_name(spec)) {
    m.grid = pm::warehouse_map(size->rows, size->cols);
    m.warehouse = size;
    m.y_down = true;
    return m;
  }
  const std::string ext = std::filesystem::path(spec).extension().string();
  if (ext == ".map") {
    m.file = spec;
    m.grid = swarm::planner::load_movingai_map(spec);
    m.movingai_file = true;
    m.y_down = true;
  } else {
    m.file = swarm::config::resolve_map_path(spec, "");  // a built-in name or a YAML file
    m.grid = swarm::planner::load_map_yaml(m.file);
  }
  m.warehouse = pm::warehouse_size_of(m.grid);
  return m;
}

pm::Instance make_random_instance(const MapfMap& map, int agents, std::uint64_t seed, bool standard_rules) {
  if (agents < 1) throw std::runtime_error("--random: the number of agents must be at least 1");
  if (map.warehouse) {
    const int n = map.warehouse->rows * map.warehouse->cols;
    if (agents > n || n < 2) {
      throw std::runtime_error("--random: " + std::to_string(agents) + " robots do not fit on the " + std::to_string(n) +
                               " intersections of " + map.name);
    }
    pm::Instance in = pm::random_warehouse_instance(map.warehouse->rows, map.warehouse->cols, agents, seed);
    in.map = map.grid;  // same cells; keeps the file's resolution
    if (standard_rules) in.rules = pm::Rules::standard();
    return in;
  }
  auto in = pm::random_instance(map.grid, agents, seed);
  if (!in) {
    throw std::runtime_error("--random: " + (map.file.empty() ? map.name : map.file) + " has too few free cells for " +
                             std::to_string(agents) + " agents");
  }
  return *in;
}

}  // namespace swarm::tools
