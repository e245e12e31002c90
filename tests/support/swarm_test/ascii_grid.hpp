// Occupancy grids drawn as ASCII art, for tests: the one helper every test suite uses.
//
// '#' Occupied, '.' Free, '?' Unknown. Any other character is a Free cell whose position is
// remembered under that character (robots, goals), see ascii_map. The FIRST string is the TOP
// row: with H strings, string r holds y = H - 1 - r (grid.hpp: y points up); x is the column.
// The grid has the default resolution (0.2 m) and origin (0, 0).
//
//   const OccupancyGrid g = swarm::test::grid_from({
//       "...",  // y = 1
//       "#.?",  // y = 0: (0, 0) Occupied, (1, 0) Free, (2, 0) Unknown
//   });
//   const auto art = swarm::test::ascii_map({"R.#", "..G"});
//   art.at.at('R');  // Cell{0, 1}, a Free cell
//
// A malformed drawing (no rows, rows of different lengths, a marker used twice) throws
// std::invalid_argument naming the row: a test with broken art fails instead of testing
// something else.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::test {

struct AsciiMap {
  planner::OccupancyGrid grid;
  std::map<char, planner::Cell> at;  // marker character -> its cell
};

inline AsciiMap ascii_map(const std::vector<std::string>& rows) {
  using planner::Cell;
  using planner::CellState;
  if (rows.empty() || rows.front().empty()) {
    throw std::invalid_argument("ascii_map: the drawing has no cells");
  }
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows.front().size());
  AsciiMap out{planner::OccupancyGrid(w, h), {}};
  for (int r = 0; r < h; ++r) {
    const std::string& row = rows[static_cast<std::size_t>(r)];
    if (static_cast<int>(row.size()) != w) {
      throw std::invalid_argument("ascii_map: row " + std::to_string(r) + " \"" + row + "\" has " +
                                  std::to_string(row.size()) + " cells, the first row has " +
                                  std::to_string(w));
    }
    for (int x = 0; x < w; ++x) {
      const Cell c{x, h - 1 - r};
      const char ch = row[static_cast<std::size_t>(x)];
      if (ch == '#') {
        out.grid.set(c, CellState::Occupied);
      } else if (ch == '?') {
        out.grid.set(c, CellState::Unknown);
      } else {
        out.grid.set(c, CellState::Free);
        if (ch != '.' && !out.at.emplace(ch, c).second) {
          throw std::invalid_argument(std::string("ascii_map: marker '") + ch + "' appears twice (row " +
                                      std::to_string(r) + ")");
        }
      }
    }
  }
  return out;
}

// Just the grid of ascii_map(rows).
inline planner::OccupancyGrid grid_from(const std::vector<std::string>& rows) { return ascii_map(rows).grid; }

}  // namespace swarm::test
