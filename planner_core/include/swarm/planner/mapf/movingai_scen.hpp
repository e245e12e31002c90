// MovingAI MAPF scenario files (`.scen`), in and out.
//
// Format (Stern et al., SoCS 2019; https://movingai.com/benchmarks/mapf.html): a first line
// `version 1`, then one agent a line, tab-separated:
//   bucket  map-file  map-width  map-height  start-x  start-y  goal-x  goal-y  optimal-length
// with x = column and y = row counted from the TOP of the map (grid.hpp's y points up: use
// from_movingai_xy / to_movingai_xy). An instance with k agents takes the first k lines.
// The optimal length is the octile (8-connected) distance; it is written, never trusted.
//
// Errors are process-edge failures: MapFileError (map_io.hpp) naming the file, the line and what
// was expected, e.g. "x.scen:7: start (40, 3) is outside the 32 x 32 map".
//
//   const OccupancyGrid map = load_movingai_map("random-32-32-20.map");
//   const Scenario scen = load_movingai_scen("random-32-32-20-random-1.scen");
//   Instance in = instance_from_scen(map, scen, 20, "random-32-32-20.map");   // first 20 agents
//   save_movingai_scen("/tmp/mine.scen", in, "random-32-32-20.map");
//
// Thread-safe (no shared state).
#pragma once

#include <string>
#include <vector>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf {

struct ScenarioRow {
  int line = 0;  // 1-based line in the file
  int bucket = 0;
  std::string map_name;
  int map_width = 0;
  int map_height = 0;
  int start_x = 0, start_y = 0;  // MovingAI coordinates (y from the top)
  int goal_x = 0, goal_y = 0;
  double optimal_length = 0;
};

struct Scenario {
  std::string path;  // the file it was read from
  std::vector<ScenarioRow> rows;
};

// Reads a `.scen` file. Throws MapFileError (bad header, a short or malformed row).
[[nodiscard]] Scenario load_movingai_scen(const std::string& path);

// The instance of the first k rows on `map` (standard rules, 4-connected). Throws MapFileError
// naming the scenario file and line when k is larger than the number of rows (or < 1), when a
// row's map name differs from `map_file_name` (compared by file name, when both are given) or its
// size from the map's, or a start/goal is outside the map or blocked, or two agents share one.
[[nodiscard]] Instance instance_from_scen(const OccupancyGrid& map, const Scenario& scen, int k,
                                          const std::string& map_file_name = "");

// MovingAI coordinates of a cell (x = column, y = row from the top).
inline Cell to_movingai_xy(const OccupancyGrid& map, Cell c) { return {c.x, map.height() - 1 - c.y}; }

// Writes the instance's agents as a `.scen` (bucket = optimal length / 4, as the benchmark does).
// Throws MapFileError when the file cannot be written.
void save_movingai_scen(const std::string& path, const Instance& in, const std::string& map_file_name);

}  // namespace swarm::planner::mapf
