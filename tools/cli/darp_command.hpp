// `swarm darp`: DARP area division and spanning-tree coverage paths on a map, offline: a map and
// robots in, a picture and numbers out (planner/coverage/darp.hpp, planner/coverage/stc.hpp, planner/coverage/coverage_plan.hpp).
//
//   swarm darp --map terminal --count 6 --placement bunched --seed 3 --init bfs-kmeans
//   swarm darp --map data/darp/terminal-6.map --robots-file data/darp/terminal-6.robots
//   swarm darp --map my_building.yaml --robots "10,12;40,30" --distance geodesic --out runs/d
//
// Coordinates (robots in, paths and assignment out) are the input file's own: x = column, y = row
// counted from the top row of the file (MovingAI `.map` rows; for a map_server map, rows of its
// image, first row = top), 0-based. Writes DIR/division.png (regions in colours, robots as discs,
// relocated starts as rings, paths as lines) and DIR/result.json (see write_darp_json).
// Exit status: 0 converged, 1 not converged (failed or stopped; the best division is still
// written), 2 bad input (one message naming the flag, file and line, or field), 3 no division
// within one cell exists (the reason is printed; the most balanced connected one found is written).
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "swarm/planner/coverage/coverage_plan.hpp"
#include "swarm/planner/coverage/darp.hpp"
#include "swarm/planner/grid/grid.hpp"

namespace swarm::tools {

struct DarpOptions {
  std::string map;                  // built-in name, map_server YAML, or MovingAI .map
  std::string robots;               // "x,y;x,y"
  std::string robots_file;          // one "x y" line per robot
  std::optional<int> count;         // with placement and seed
  std::string placement = "spread";  // spread | bunched
  std::uint64_t seed = 1;           // placement and DARP's random factors
  std::string weights;              // "1,2,1": unequal portions; "" = equal
  std::string method = "auto";      // auto | darp (planner::DivisionMethod)
  std::string init = "given";       // given | random | kmeans | bfs-kmeans
  std::string reinit = "selective";  // bfs-kmeans: selective | always
  std::string distance = "euclidean";  // euclidean | geodesic
  int max_iterations = 10000;
  double time_limit_s = 0;          // 0 = none
  std::string out_dir;              // "" = runs/darp-<YYYYmmdd-HHMMSS>
};

int darp_command(const DarpOptions& options, std::ostream& out, std::ostream& err);

// A bad command line, map or robots file: the message says which and what was expected.
struct DarpInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A map by built-in name, map_server YAML or MovingAI .map. Throws DarpInputError.
struct LoadedMap {
  planner::OccupancyGrid grid;
  std::string path;
};
[[nodiscard]] LoadedMap load_darp_map(const std::string& spec);

// File coordinates (x = column, y = row from the top) <-> grid cells (y up).
[[nodiscard]] inline planner::Cell from_file_xy(const planner::OccupancyGrid& map, int x, int y) {
  return {x, map.height() - 1 - y};
}
[[nodiscard]] inline planner::Cell to_file_xy(const planner::OccupancyGrid& map, planner::Cell c) {
  return {c.x, map.height() - 1 - c.y};
}

// Parses "x,y;x,y" (`source` names it in messages). Throws DarpInputError.
[[nodiscard]] std::vector<planner::Cell> parse_robot_list(const std::string& text, const planner::OccupancyGrid& map);
// Reads a robots file (one "x y" line per robot; blank lines and lines starting with '#' are
// skipped). Throws DarpInputError naming FILE:LINE.
[[nodiscard]] std::vector<planner::Cell> read_robots_file(const std::string& path, const planner::OccupancyGrid& map);

// The picture: regions in colours, unreachable cells grey, paths, robots and starts.
void draw_division(const planner::OccupancyGrid& map, const std::vector<planner::Cell>& robots,
                   const planner::DarpResult& division, const std::vector<planner::CoveragePlan>& plans,
                   const std::string& title, const std::string& png_path);

}  // namespace swarm::tools
