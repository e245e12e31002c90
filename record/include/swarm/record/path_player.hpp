// A self-contained HTML page that plays robots' paths over a picture of their map: discs moving
// cell to cell, play/pause, step and a time slider (the picture embedded as a PNG, so the one file
// is all a browser needs). `swarm mapf` writes one for its plan.
//
//   PathPlayer p;
//   p.background_png = read_file("map.png");   // drawn by GridCanvas at `scale` px per cell
//   p.scale = 8; p.band = kBandPx; p.height = map.height();
//   p.paths = {{{0, 0}, {1, 0}}, {{3, 2}, {3, 1}}};   // per robot, one cell per time step
//   p.colours = {palette_colour(0), palette_colour(1)};
//   write_path_player("animation.html", "my plan", p);
#pragma once

#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/record/grid_canvas.hpp"

namespace swarm::record {

struct PathPlayer {
  std::string background_png;  // the picture's bytes
  int scale = 1;               // pixels per cell in it
  int band = 0;                // pixels of title band above the cells
  int height = 0;              // the map's height in cells (y points up)
  bool vanish = false;         // a robot leaves the picture once its path ends
  std::vector<Rgb> colours;    // per robot
  std::vector<std::vector<planner::Cell>> paths;  // per robot, one cell per time step
};

// Writes the page; throws std::runtime_error when the file cannot be written.
void write_path_player(const std::string& path, const std::string& title, const PathPlayer& player);

// The bytes of a file (empty if it cannot be read).
[[nodiscard]] std::string read_file(const std::string& path);
// RFC 4648 base64 of `bytes`.
[[nodiscard]] std::string base64(const std::string& bytes);

}  // namespace swarm::record
