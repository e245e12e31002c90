#include "swarm/sim/world.hpp"

#include <algorithm>
#include <cstdlib>

#include "swarm/planner/frontier.hpp"
#include "swarm/planner/raycast.hpp"

namespace swarm::sim {

using planner::Cell;
using planner::CellChange;
using planner::CellState;

World::World(planner::OccupancyGrid truth, std::vector<Cell> robot_cells, LidarConfig lidar)
    : truth_(std::move(truth)),
      lidar_(lidar),
      robots_(std::move(robot_cells)),
      paths_(robots_.size()),
      next_(robots_.size(), 0),
      seen_(truth_.width(), truth_.height(), truth_.resolution()) {
  reachable_ = planner::reachable_mask(truth_, {robots_.front()});
  reachable_free_ = static_cast<int>(std::count(reachable_.begin(), reachable_.end(), 1));
}

void World::command(int robot, const std::vector<Cell>& path) {
  auto& p = paths_[robot];
  p = path;
  next_[robot] = p.size();  // no motion unless the robot's place in the path is found
  const Cell here = robots_[robot];
  for (std::size_t i = p.size(); i-- > 0;) {
    if (p[i] == here) {
      next_[robot] = i + 1;
      return;
    }
  }
  if (!p.empty() && std::max(std::abs(p[0].x - here.x), std::abs(p[0].y - here.y)) == 1) next_[robot] = 0;
}

bool World::can_step(Cell from, Cell to) const {
  const int dx = to.x - from.x;
  const int dy = to.y - from.y;
  if (std::max(std::abs(dx), std::abs(dy)) != 1) return false;
  if (!truth_.is_free(to)) return false;
  if (dx != 0 && dy != 0) {
    // No corner cutting: both orthogonal cells must be free.
    if (!truth_.is_free({from.x + dx, from.y}) || !truth_.is_free({from.x, from.y + dy})) return false;
  }
  return true;
}

void World::move() {
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    if (next_[r] >= paths_[r].size()) continue;
    const Cell to = paths_[r][next_[r]];
    if (!can_step(robots_[r], to)) {
      ++wall_stops_;
      next_[r] = paths_[r].size();
      continue;
    }
    const bool taken = std::any_of(robots_.begin(), robots_.end(), [&](const Cell& c) { return c == to; });
    if (taken) {
      ++blocked_moves_;
      continue;
    }
    robots_[r] = to;
    ++next_[r];
    ++moves_;
  }
}

void World::scan(int robot, std::vector<float>& ranges) {
  ranges.resize(lidar_.beams);
  planner::scan(truth_, robots_[robot], lidar_.beams, lidar_.range_cells, ranges.data());
  std::vector<CellChange> changes;
  planner::integrate_scan(seen_, robots_[robot], ranges.data(), lidar_.beams, lidar_.range_cells, &changes);
  for (const CellChange& c : changes) {
    if (c.state == CellState::Free && reachable_[c.index]) ++reachable_seen_;
  }
}

double World::explored_fraction() const {
  return reachable_free_ == 0 ? 1.0 : static_cast<double>(reachable_seen_) / reachable_free_;
}

}  // namespace swarm::sim
