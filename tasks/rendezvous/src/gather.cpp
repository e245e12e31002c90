#include "swarm/tasks/rendezvous/gather.hpp"

#include <Eigen/Core>
#include <cstddef>
#include <limits>

#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/explore/hungarian.hpp"
#include "swarm/planner/grid/start_cells.hpp"

namespace swarm::tasks::rendezvous {

using planner::Cell;
using planner::MotionModel;
using planner::OccupancyGrid;

std::vector<int> steps_from(const OccupancyGrid& map, Cell from, const MotionModel& motion) {
  return planner::step_distances(map, {from}, motion);
}

namespace {

// The free cell nearest `point` (Euclidean, then lowest index) among those some robot reaches.
Cell centre_near(const OccupancyGrid& map, Cell point, const std::vector<Cell>& robots) {
  std::vector<std::uint8_t> reach(map.size(), 0);
  for (const Cell r : robots) {
    if (reach[static_cast<std::size_t>(map.index(r))]) continue;
    const auto steps = steps_from(map, r, MotionModel::four());
    for (std::size_t i = 0; i < steps.size(); ++i) reach[i] |= steps[i] >= 0 ? 1 : 0;
  }
  Cell best{-1, -1};
  long long best_d2 = std::numeric_limits<long long>::max();
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      if (!reach[static_cast<std::size_t>(map.index({x, y}))]) continue;
      const long long dx = x - point.x, dy = y - point.y;
      if (dx * dx + dy * dy < best_d2) {
        best_d2 = dx * dx + dy * dy;
        best = {x, y};
      }
    }
  }
  return best;
}

}  // namespace

Gathering gather(const OccupancyGrid& map, Cell point, const std::vector<Cell>& robots) {
  Gathering g;
  g.goals.assign(robots.size(), Cell{-1, -1});
  for (const Cell r : robots) {
    if (!map.is_free(r)) return g;  // a robot's cell must be free: the caller's map is wrong
  }
  g.centre = centre_near(map, point, robots);
  if (g.centre.x < 0) return g;
  // Who reaches the centre, and every cell's path length to it (the same both ways on a grid).
  const auto to_centre = steps_from(map, g.centre, MotionModel::four());
  std::vector<int> coming;
  for (std::size_t i = 0; i < robots.size(); ++i) {
    if (to_centre[static_cast<std::size_t>(map.index(robots[i]))] >= 0) coming.push_back(static_cast<int>(i));
  }
  g.cells = planner::start_cells(map, g.centre, static_cast<int>(coming.size()));
  // cost(robot, cell) = the 4-connected path length, from one search per cell.
  const auto n = static_cast<Eigen::Index>(coming.size());
  Eigen::MatrixXd cost(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto steps = steps_from(map, g.cells[static_cast<std::size_t>(j)], MotionModel::four());
    for (Eigen::Index i = 0; i < n; ++i) {
      cost(i, j) = steps[static_cast<std::size_t>(map.index(robots[static_cast<std::size_t>(coming[i])]))];
    }
  }
  const planner::Assignment a = planner::hungarian(cost);
  for (Eigen::Index i = 0; i < n; ++i) {
    g.goals[static_cast<std::size_t>(coming[i])] = g.cells[static_cast<std::size_t>(a.row_to_col[i])];
  }
  g.path_sum = a.total_cost;
  return g;
}

Packing packing(const OccupancyGrid& map, Cell centre, const std::vector<Cell>& robots) {
  Packing p;
  const auto steps = steps_from(map, centre, MotionModel::eight());
  for (const Cell r : robots) {
    const int s = map.in_bounds(r) ? steps[static_cast<std::size_t>(map.index(r))] : -1;
    if (s < 0) {
      ++p.unreachable;
      continue;
    }
    p.step_sum += s;
    p.max_steps = std::max(p.max_steps, s);
  }
  return p;
}

}  // namespace swarm::tasks::rendezvous
