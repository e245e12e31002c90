#include "swarm/gcs/fused_map.hpp"

namespace swarm::gcs {

using planner::CellState;

FusedMap::FusedMap(int width, int height, double resolution, int groups)
    : grid_(width, height, resolution), seen_group_(static_cast<std::size_t>(groups), false) {}

void FusedMap::fuse(int group, const std::vector<planner::CellChange>& changes) {
  for (const auto& c : changes) {
    if (grid_.at(c.index) == CellState::Unknown && c.state != CellState::Unknown) ++known_;
    grid_.set(c.index, c.state);
  }
  if (group >= 0 && static_cast<std::size_t>(group) < seen_group_.size() && !seen_group_[group]) {
    seen_group_[group] = true;
    ++heard_;
  }
}

double FusedMap::mapped_fraction() const {
  return grid_.size() == 0 ? 0.0 : static_cast<double>(known_) / static_cast<double>(grid_.size());
}

}  // namespace swarm::gcs
