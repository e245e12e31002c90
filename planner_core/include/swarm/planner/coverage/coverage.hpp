// Coverage paths of one cleaning robot: what plowing (plow.hpp) and Group-k (group_k.hpp) return,
// the time model of Jeon, Jo & Noh 2006 (seeds/003, section IV.1: 0.17 m/s, one cell = 10 cm, a
// 90 degree turn costs 1 s and a 180 degree turn 2 s) and the coverage-vs-time curve.
//
// A coverage path is a 4-connected cell path (motion.hpp, MotionModel::four(), Free cells only)
// from the robot's cell; a cell is clean once the robot has stood on it, whether it was sweeping
// or passing through. A region is a CellMask: one byte per map cell (index = map.index(c)), 1 for
// the cells to clean (e.g. all Free cells, or one robot's share from a DARP division).
//
//   const CellMask all = free_cells(map);
//   const CoveragePath p = plow(map, all, start);
//   const CoverageCurve curve = coverage_curve(all, map, p.cells, {});   // the paper's model
//   double t = curve.total_time_s;  double half = *curve.time_to(0.5);
//   assert(check_coverage_path(map, all, start, p).empty());
//
// Times: a step takes cell_m / speed_m_s (0.588 s); the robot turns before a step by the change of
// heading (turns.hpp); the first step costs no turn (the robot starts facing it). 45 and 135
// degree turns (not made by 4-connected paths) cost half of 90 and half of 90 + 180.
// Pure functions; thread-safe.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/tours/turns.hpp"

namespace swarm::planner {

using CellMask = std::vector<std::uint8_t>;

// 1 for every Free cell of `map`.
[[nodiscard]] CellMask free_cells(const OccupancyGrid& map);
[[nodiscard]] int count_cells(const CellMask& mask);

struct CoveragePath {
  std::vector<Cell> cells;   // 4-connected; front = the start
  std::vector<Cell> missed;  // region cells never stood on (not Free, or cut off from the start)

  [[nodiscard]] int steps() const { return cells.empty() ? 0 : static_cast<int>(cells.size()) - 1; }
  [[nodiscard]] TurnCounts turns() const { return count_turns(cells); }
};

struct CoverageTimeModel {
  double speed_m_s = 0.17;
  double cell_m = 0.1;
  double turn_90_s = 1.0;
  double turn_180_s = 2.0;

  [[nodiscard]] double step_s() const { return cell_m / speed_m_s; }
  // The time of a turn of `eighths` eighths (0..4).
  [[nodiscard]] double turn_s(int eighths) const;
};

// Seconds to follow `cells`.
[[nodiscard]] double path_time_s(const std::vector<Cell>& cells, const CoverageTimeModel& model);

// The clean area over time: one sample each time a region cell is stood on for the first time.
struct CoverageCurve {
  struct Sample {
    double time_s = 0;
    int covered = 0;  // region cells clean at that time
  };
  int region_cells = 0;
  std::vector<Sample> samples;  // time order; the start cell (if in the region) at time 0
  double total_time_s = 0;      // of the whole path

  // The fraction of the region clean at time t (0 when the region is empty).
  [[nodiscard]] double fraction_at(double t) const;
  // The first time the clean fraction reaches `fraction`; nullopt if it never does.
  [[nodiscard]] std::optional<double> time_to(double fraction) const;
};

[[nodiscard]] CoverageCurve coverage_curve(const CellMask& region, const OccupancyGrid& map,
                                           const std::vector<Cell>& cells,
                                           const CoverageTimeModel& model);

// An independent check of a coverage path: it starts at `start`, every step is a legal
// 4-connected move on `map` (motion.hpp), every region cell is stood on or listed in `missed`,
// and every missed cell really is never stood on and is either not Free or not reachable from the
// start. Returns "" when all holds, else the first fault found.
[[nodiscard]] std::string check_coverage_path(const OccupancyGrid& map, const CellMask& region,
                                              Cell start, const CoveragePath& path);

}  // namespace swarm::planner
