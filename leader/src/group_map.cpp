#include "swarm/leader/group_map.hpp"

namespace swarm::leader {

using planner::CellChange;
using planner::CellState;

GroupMap::GroupMap(int width, int height, double resolution)
    : global_(width, height, resolution), group_(width, height, resolution) {}

std::vector<CellChange> GroupMap::observe(const std::vector<CellChange>& changes) {
  std::vector<CellChange> fresh;
  for (const CellChange& c : changes) {
    if (group_.at(c.index) != c.state) {
      group_.set(c.index, c.state);
      fresh.push_back(c);
    }
  }
  return fresh;
}

std::vector<CellChange> GroupMap::adopt_global(const planner::OccupancyGrid& global) {
  global_ = global;
  std::vector<CellChange> fresh;
  const int n = static_cast<int>(group_.size());
  for (int i = 0; i < n; ++i) {
    const CellState g = global_.at(i);
    if (g != CellState::Unknown && group_.at(i) == CellState::Unknown) {
      group_.set(i, g);
      fresh.push_back({i, g});
    }
  }
  return fresh;
}

}  // namespace swarm::leader
