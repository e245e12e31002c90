// Headings and turns of grid paths: how much a robot rotates while it follows a cell path.
//
// A heading is a multiple of 45 degrees, counted in eighths of a full turn from +x
// (counter-clockwise, y up as in grid.hpp): 0 = right (+x), 2 = up (+y), 4 = left, 6 = down. The
// heading of a step is atan2(dy, dx) of its two cells (Kim & Lee 2025, seeds/001, eq. 5); a turn
// between two headings is the smaller of the two ways round, 0..4 eighths (0..180 degrees), so a
// path's rotation R = sum |delta theta| (eq. 4) is a whole number of eighths: exact, comparable
// without tolerance, and pi/4 times it in radians. A step from a cell to itself (a wait, or two
// stops on one cell) has no heading and turns nothing.
//
//   const std::vector<Cell> p{{0, 0}, {1, 0}, {2, 1}, {2, 2}};   // right, up-right, up
//   int r = rotation_eighths(p, kHeadingUp);    // 2 (up -> right) + 1 + 1 = 4 eighths = pi
//   double rad = eighths_to_rad(r);             // 3.14159...
//
// Pure functions; thread-safe.
#pragma once

#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

inline constexpr int kHeadingRight = 0;
inline constexpr int kHeadingUp = 2;
inline constexpr int kHeadingLeft = 4;
inline constexpr int kHeadingDown = 6;

// The heading of a step between 8-neighbours; nullopt for from == to. Asserts the cells are
// 8-neighbours (a longer jump has no grid heading and is a bug of the caller).
[[nodiscard]] std::optional<int> step_heading(Cell from, Cell to);

// The turn from heading `from` to heading `to`, in eighths: 0 (straight on) .. 4 (about-turn).
[[nodiscard]] constexpr int turn_eighths(int from, int to) {
  const int d = ((to - from) % 8 + 8) % 8;
  return d <= 4 ? d : 8 - d;
}

// The rotation of following `path`, in eighths, starting with heading `initial` (nullopt: the
// robot faces its first step, which then costs nothing). If `final_heading` is given it receives
// the heading after the last step (the initial heading if the path never moves).
[[nodiscard]] int rotation_eighths(const std::vector<Cell>& path, std::optional<int> initial,
                                   std::optional<int>* final_heading = nullptr);

// Eighths of a turn to radians (pi / 4 each).
[[nodiscard]] constexpr double eighths_to_rad(int eighths) {
  return eighths * 0.78539816339744830962;
}

// The turns a robot makes along a path, by size (a 4-connected path only turns 90 or 180
// degrees): the coverage time model (coverage.hpp) prices them.
struct TurnCounts {
  int turns_45 = 0;
  int turns_90 = 0;
  int turns_135 = 0;
  int turns_180 = 0;
  // In quarter turns (90 degrees = 1, a reversal = 2): how spanning-tree coverage and the DARP
  // reference count the turns of a 4-connected path.
  [[nodiscard]] int quarter_turns() const { return turns_90 + 2 * turns_180; }
  friend bool operator==(const TurnCounts&, const TurnCounts&) = default;
};

// Every heading change along `path`; the first step turns nothing (the robot starts facing it).
[[nodiscard]] TurnCounts count_turns(const std::vector<Cell>& path);

}  // namespace swarm::planner
