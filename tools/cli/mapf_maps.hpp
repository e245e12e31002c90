// Maps and instances for the MAPF commands (`swarm mapf`, `swarm experiment mapf`): one place that
// turns a --map argument into a grid and knows which coordinates its files use.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/mapf/instance.hpp"
#include "swarm/planner/mapf/warehouse.hpp"

namespace swarm::tools {

struct MapfMap {
  planner::OccupancyGrid grid;
  std::string name;           // file name or built-in name
  std::string file;           // the file read ("" for warehouse-RxC)
  bool movingai_file = false; // a MovingAI .map (scenarios name it)
  bool y_down = false;        // its coordinates count rows from the top (MovingAI, warehouse)
  std::optional<planner::mapf::WarehouseSize> warehouse;  // the paper's world
};

// `spec`: warehouse-RxC, a built-in map name (config::builtin_map_names), a MovingAI `.map`, or a
// map_server YAML. Throws std::runtime_error (MapFileError, ConfigError) naming the file.
[[nodiscard]] MapfMap load_mapf_map(const std::string& spec);

// K random agents: on a warehouse, random intersections with the paper's rules (unless
// standard_rules); elsewhere random free cells. Throws std::runtime_error naming --random when
// the map cannot hold K agents.
[[nodiscard]] planner::mapf::Instance make_random_instance(const MapfMap& map, int agents, std::uint64_t seed,
                                                           bool standard_rules = false);

}  // namespace swarm::tools
