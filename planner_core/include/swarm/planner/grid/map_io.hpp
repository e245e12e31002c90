// Map files in and out: ROS map_server maps (YAML + PGM) and MovingAI `.map` benchmark maps.
//
// ROS map_server format (https://wiki.ros.org/map_server, "YAML format"): a YAML file with
//   image: lab.pgm            # relative to the YAML file's folder, or absolute
//   resolution: 0.05          # metres per cell, > 0
//   origin: [-10.0, -10.0, 0] # map frame pose of the lower-left corner of cell (0, 0): x, y, yaw
//   negate: 0                 # optional, 0/1 or true/false; default 0
//   occupied_thresh: 0.65     # optional, default 0.65
//   free_thresh: 0.196        # optional, default 0.196
//   mode: trinary             # optional; only trinary is supported
// A pixel value v of a PGM with maximum value M gives the occupancy probability p = (M - v) / M
// (v / M if negate); p > occupied_thresh is Occupied, p < free_thresh is Free, anything else is
// Unknown. For M = 255 that is exactly map_server's (255 - v) / 255. The PGM's first row is the
// top of the map (largest y), as in grid.hpp. Like map_server, the yaw is read but not applied.
// Images other than PGM (.png, ...) are read through OpenCV as 8-bit grey.
//
// MovingAI format (Sturtevant, "Benchmarks for Grid-Based Pathfinding", IEEE TCIAIG 2012; the maps
// of the MAPF benchmark, Stern et al., SoCS 2019): `type octile`, `height H`, `width W`, `map`,
// then H rows of W characters; '.', 'G' and 'S' are passable (Free), every other character is
// Occupied. The first row is the top, so MovingAI's (x, y) (y down, as in `.scen` files) is
// Cell{x, H - 1 - y} here: use from_movingai_xy.
//
// Errors are process-edge failures and throw MapFileError; the message names the file, the line
// (or PGM header field) and what was expected, e.g.
//   maps/x.yaml:3: resolution must be a positive number (got "abc")
//
//   OccupancyGrid lab = load_map_yaml("maps/lab.yaml");
//   save_map_yaml("/tmp/explored.yaml", lab);            // writes /tmp/explored.pgm beside it
//   OccupancyGrid maze = load_movingai_map("maze-32-32-2.map");
//   save_movingai_map("/tmp/maze.map", maze);
//
// All functions are thread-safe (no shared state).
#pragma once

#include <stdexcept>
#include <string>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

class MapFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Metres per cell a map may have: a millimetre to a kilometre. Past these a map's extent in
// metres (cells x resolution) loses its precision or overflows to inf.
inline constexpr double kMinResolutionM = 1e-3;
inline constexpr double kMaxResolutionM = 1e3;
// How far from (0, 0) a map's origin may lie, in metres.
inline constexpr double kMaxOriginM = 1e9;

// Reads a map_server YAML file and the image it names. Throws MapFileError.
[[nodiscard]] OccupancyGrid load_map_yaml(const std::string& yaml_path);

// Writes `yaml_path` and a binary PGM beside it (same name, extension .pgm) with free 254,
// occupied 0 and unknown 205, thresholds 0.65 / 0.196. load_map_yaml of the result gives back the
// same cells, resolution and origin (numbers are written in shortest round-trip form).
// Throws MapFileError if a file cannot be written.
void save_map_yaml(const std::string& yaml_path, const OccupancyGrid& map);

// Reads a MovingAI `.map` file; each character is one cell of `resolution_m` metres, origin (0, 0).
// Throws MapFileError (also for rows past `height`, and a resolution outside the range above).
[[nodiscard]] OccupancyGrid load_movingai_map(const std::string& path, double resolution_m = 0.2);

// Writes a MovingAI `.map` (`type octile`, height, width, `map`, rows from the top): Free cells
// '.', Occupied '@', Unknown 'T' (not passable either: the format has no "unknown").
// load_movingai_map of the result gives back the same Free/blocked cells.
// Throws MapFileError if the file cannot be written.
void save_movingai_map(const std::string& path, const OccupancyGrid& map);

// MovingAI coordinates (x right, y down from the top row, as in `.scen` files) to a grid cell.
inline Cell from_movingai_xy(const OccupancyGrid& map, int x, int y) {
  return {x, map.height() - 1 - y};
}

}  // namespace swarm::planner
