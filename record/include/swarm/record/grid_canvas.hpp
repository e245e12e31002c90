// A picture of a grid with things drawn on it: the one drawing surface of the offline tools
// (`swarm darp`, `swarm mapf`, `swarm tour`, `swarm clean`) and the live tasks' pictures.
//
// Layout as in render.hpp: a band on top with a title and legend entries, then the map with
// `scale` pixels per cell and y up (cell row 0 is the bottom row of the image). Free cells are
// white, occupied black, unknown grey. Everything else is drawn in cell coordinates.
//
//   GridCanvas c(map, 8);
//   c.fill_cell({3, 4}, palette_colour(2), 0.5);           // half-transparent fill
//   c.polyline(path, palette_colour(0), 2);                // through cell centres
//   c.marker({3, 4}, palette_colour(0), Marker::Disc);
//   c.label({3, 4}, "r0", kInk);
//   c.set_title("DARP: 6 robots, converged after 412 iterations");
//   c.add_legend("robot 0", palette_colour(0));
//   c.write_png("division.png");                          // throws std::runtime_error on failure
//
// Not thread-safe (one canvas per thread).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/record/render.hpp"

namespace swarm::record {

inline constexpr Rgb kInk{20, 20, 20};

// Colour i of a palette of distinguishable colours (Okabe-Ito first, then further hues); repeats
// only after 20 entries.
Rgb palette_colour(int i);

enum class Marker { Disc, Ring, Square, Cross, Triangle };

class GridCanvas {
 public:
  GridCanvas(const planner::OccupancyGrid& map, int scale);
  ~GridCanvas();
  GridCanvas(const GridCanvas&) = delete;
  GridCanvas& operator=(const GridCanvas&) = delete;

  int scale() const { return scale_; }
  const RenderGeometry& geometry() const { return geo_; }

  // alpha 1 = opaque; the fill keeps a wall's or cell's colour underneath blended in.
  void fill_cell(planner::Cell c, Rgb colour, double alpha = 1.0);
  // A line through the centres of consecutive cells; `thickness` in pixels.
  void polyline(const std::vector<planner::Cell>& cells, Rgb colour, int thickness = 1);
  // An arrow from one cell centre to another.
  void arrow(planner::Cell from, planner::Cell to, Rgb colour, int thickness = 1);
  // A marker centred on a cell, about `size_cells` cells across.
  void marker(planner::Cell c, Rgb colour, Marker kind, double size_cells = 0.8);
  // Small text next to a cell.
  void label(planner::Cell c, const std::string& text, Rgb colour = kInk);
  // A rectangle around cells [x0, x1] x [y0, y1], outline only.
  void outline(planner::Cell lo, planner::Cell hi, Rgb colour, int thickness = 1);

  void set_title(const std::string& title);
  void add_legend(const std::string& text, Rgb colour);

  void write_png(const std::string& path) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int scale_;
  RenderGeometry geo_;
};

}  // namespace swarm::record
