// Tour files: a collection problem (Kim & Lee 2025, planner/tours/tour.hpp) for `swarm tour` and
// `swarm experiment tour` (tools/cli/tour_command.hpp loads them with its map names). Plain text,
// one statement per line, '#' starts a comment:
//
//   size 12 12                 # an empty room of W x H cells ...
//   map clutter                # ... or a map: built-in name, map_server YAML, MovingAI .map
//   origin -6 -6               # file coordinates of the lower-left cell (default 0 0)
//   start 0 -5 up              # the robot's cell; heading up|down|left|right (default up)
//   after-drop left            # the heading after each destination (default left)
//   destination paper 5 5      # one per type; the order of these lines numbers the types
//   object paper 4 -4 fixed    # a type with a destination, a cell; `fixed`: the experiment's
//                              # re-scattered layouts keep it where it is
//   obstacle -2 0 1 2          # blocked cells x0 y0 x1 y1 (inclusive corners)
//
// Coordinates are cells: x right, y up (a map file's cell (0, 0) is its lower-left cell), shifted by
// `origin` so the paper's centred coordinates can be written as they are. Map paths are relative
// to the tour file's folder; the caller's MapLoader reads them (the parser opens no other file).
//
// Bad input throws TourFileError with "FILE:LINE: what is wrong and what was expected": an unknown
// statement, a malformed number, a missing or repeated start / size / map, an object or
// destination outside the map or on a blocked cell, an object whose type has no destination, a
// repeated destination, an obstacle reaching outside the map, a start on a blocked cell. An
// object the start cannot reach is not thrown: it is listed in `unreachable` (the caller decides,
// `swarm tour --skip-unreachable`).
//
//   const TourFile f = load_tour_file("scenarios/tour/scenario1.tour", load_named_map);
//   TourPlan plan = plan_tour(f.map, f.problem);
//   std::cout << f.type_names[plan.runs[0].type] << " first, at " << f.where(f.problem.start);
//
// Thread-safe (no shared state).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/tours/tour.hpp"

namespace swarm::planner {

class TourFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TourFile {
  std::string path;
  std::string map_text;            // "12 x 12 cells, no obstacles", "clutter, 2 obstacle blocks"
  OccupancyGrid map;      // with the obstacle lines drawn in
  Cell origin;            // file coordinates = cell + origin
  TourProblem problem;
  std::vector<std::string> type_names;  // by type number
  std::vector<bool> fixed;              // by object
  std::vector<int> object_lines;        // by object
  int start_line = 0;
  std::vector<std::string> unreachable;  // "FILE:LINE: object paper at (3, 4) cannot be reached ..."

  // "(x, y)" in the file's coordinates.
  [[nodiscard]] std::string where(Cell c) const;
};

// Reads a `map NAME` line's map: NAME as written, `folder` the tour file's folder (for relative
// paths). Throws anything derived from std::exception for a map it cannot read.
using TourMapLoader = std::function<OccupancyGrid(const std::string& name, const std::string& folder)>;

// Parses a tour file's text; `path` names it in messages and gives the folder of its map.
[[nodiscard]] TourFile parse_tour_file(const std::string& text, const std::string& path, const TourMapLoader& load_map);
// Reads and parses the file at `path`.
[[nodiscard]] TourFile load_tour_file(const std::string& path, const TourMapLoader& load_map);

}  // namespace swarm::planner
