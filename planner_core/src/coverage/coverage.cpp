#include "swarm/planner/coverage/coverage.hpp"

#include <algorithm>
#include <cassert>

#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {

CellMask free_cells(const OccupancyGrid& map) {
  CellMask mask(map.size(), 0);
  for (std::size_t i = 0; i < map.size(); ++i) mask[i] = map.at(static_cast<int>(i)) == CellState::Free;
  return mask;
}

int count_cells(const CellMask& mask) {
  return static_cast<int>(std::count_if(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; }));
}

double CoverageTimeModel::turn_s(int eighths) const {
  switch (eighths) {
    case 0: return 0.0;
    case 1: return turn_90_s / 2;
    case 2: return turn_90_s;
    case 3: return (turn_90_s + turn_180_s) / 2;
    default: return turn_180_s;
  }
}

namespace {

// Calls f(index of the cell reached, time it is reached) for every step of `cells`.
template <class F>
double walk_timed(const std::vector<Cell>& cells, const CoverageTimeModel& model, F&& f) {
  double t = 0;
  std::optional<int> heading;
  for (std::size_t i = 1; i < cells.size(); ++i) {
    const std::optional<int> h = step_heading(cells[i - 1], cells[i]);
    if (!h) continue;  // a wait: no time in this model
    if (heading) t += model.turn_s(turn_eighths(*heading, *h));
    heading = h;
    t += model.step_s();
    f(i, t);
  }
  return t;
}

}  // namespace

double path_time_s(const std::vector<Cell>& cells, const CoverageTimeModel& model) {
  return walk_timed(cells, model, [](std::size_t, double) {});
}

double CoverageCurve::fraction_at(double t) const {
  if (region_cells == 0) return 0.0;
  // The last sample at or before t.
  const auto it = std::upper_bound(samples.begin(), samples.end(), t,
                                   [](double v, const Sample& s) { return v < s.time_s; });
  if (it == samples.begin()) return 0.0;
  return static_cast<double>(std::prev(it)->covered) / region_cells;
}

std::optional<double> CoverageCurve::time_to(double fraction) const {
  for (const Sample& s : samples) {
    if (static_cast<double>(s.covered) >= fraction * region_cells - 1e-9) return s.time_s;
  }
  return std::nullopt;
}

CoverageCurve coverage_curve(const CellMask& region, const OccupancyGrid& map,
                             const std::vector<Cell>& cells, const CoverageTimeModel& model) {
  assert(region.size() == map.size());
  CoverageCurve curve;
  curve.region_cells = count_cells(region);
  CellMask seen(region.size(), 0);
  int covered = 0;
  const auto visit = [&](Cell c, double t) {
    if (!map.in_bounds(c)) return;
    const auto i = static_cast<std::size_t>(map.index(c));
    if (!region[i] || seen[i]) return;
    seen[i] = 1;
    curve.samples.push_back({t, ++covered});
  };
  if (!cells.empty()) visit(cells.front(), 0.0);
  curve.total_time_s = walk_timed(cells, model, [&](std::size_t i, double t) { visit(cells[i], t); });
  return curve;
}

std::string check_coverage_path(const OccupancyGrid& map, const CellMask& region, Cell start,
                                const CoveragePath& path) {
  if (region.size() != map.size()) return "the region mask does not fit the map";
  if (path.cells.empty() || path.cells.front() != start) return "the path does not start at the start";
  const MotionModel four = MotionModel::four();
  CellMask stood(map.size(), 0);
  if (map.in_bounds(start)) stood[static_cast<std::size_t>(map.index(start))] = 1;
  for (std::size_t i = 1; i < path.cells.size(); ++i) {
    const MoveCheck c = four.check(map, path.cells[i - 1], path.cells[i]);
    if (c != MoveCheck::Ok && c != MoveCheck::Wait) {
      return "step " + std::to_string(i) + " is " + to_string(c);
    }
    stood[static_cast<std::size_t>(map.index(path.cells[i]))] = 1;
  }
  // A robot on a blocked cell can still step off it: seed with its neighbours too.
  std::vector<Cell> seeds{start};
  four.for_each_neighbour(map, start, [&](Cell n, double) { seeds.push_back(n); });
  const std::vector<std::uint8_t> reach = reachable_mask(map, seeds, four);
  CellMask missed(map.size(), 0);
  for (const Cell c : path.missed) {
    if (!map.in_bounds(c) || !region[static_cast<std::size_t>(map.index(c))]) return "a missed cell is not in the region";
    const auto i = static_cast<std::size_t>(map.index(c));
    if (stood[i]) return "a missed cell was stood on";
    if (map.is_free(c) && reach[i]) return "a reachable cell is listed as missed";
    missed[i] = 1;
  }
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (region[i] && !stood[i] && !missed[i]) {
      const Cell c = map.cell_of(static_cast<int>(i));
      return "region cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) + ") is never covered";
    }
  }
  return "";
}

}  // namespace swarm::planner
