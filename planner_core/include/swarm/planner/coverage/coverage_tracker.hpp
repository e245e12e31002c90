// Which cells of a coverage target robots have covered: a cell is covered once a robot has stood
// within `radius` cells of it (Euclidean; 0 = on it). One bookkeeping for the simulator's ground
// truth (sim/world.hpp) and for what the GCS and the leaders know from the robots' cells in the
// clock (the coverage task), so they agree on what "covered" means.
//
//   CoverageTracker t(map, target_mask, radius);   // target_mask[i] = 1: cell i must be covered
//   t.visit(robot_cell);                            // every tick, every robot
//   if (t.complete()) ...;  t.fraction();  t.uncovered();
//
// Only Free cells of `map` can be covered. Not thread-safe.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

class CoverageTracker {
 public:
  CoverageTracker() = default;
  CoverageTracker(const OccupancyGrid& map, std::vector<std::uint8_t> target, int radius);

  // Marks the cells within the radius of `c`; returns how many target cells became covered.
  int visit(Cell c);
  // Cell c itself is covered (known from elsewhere: another's tracker); returns 1 if it is a
  // target cell that was not covered yet.
  int mark(Cell c);
  bool is_covered(Cell c) const;
  bool is_target(Cell c) const;

  int target_cells() const { return target_cells_; }
  int covered_cells() const { return covered_target_; }
  double fraction() const { return target_cells_ == 0 ? 1.0 : static_cast<double>(covered_target_) / target_cells_; }
  bool complete() const { return covered_target_ >= target_cells_; }
  // Target cells not covered yet (a mask of the map's size).
  std::vector<std::uint8_t> uncovered() const;
  const std::vector<std::uint8_t>& target() const { return target_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> free_;
  std::vector<std::uint8_t> target_;
  std::vector<std::uint8_t> covered_;
  int radius_ = 0;
  int target_cells_ = 0;
  int covered_target_ = 0;
};

}  // namespace swarm::planner
