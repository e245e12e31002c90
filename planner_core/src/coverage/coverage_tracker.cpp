#include "swarm/planner/coverage/coverage_tracker.hpp"

#include <algorithm>

namespace swarm::planner {

CoverageTracker::CoverageTracker(const OccupancyGrid& map, std::vector<std::uint8_t> target, int radius)
    : width_(map.width()),
      height_(map.height()),
      free_(map.size(), 0),
      target_(std::move(target)),
      covered_(map.size(), 0),
      radius_(std::max(0, radius)) {
  target_.resize(map.size(), 0);
  for (std::size_t i = 0; i < map.size(); ++i) {
    free_[i] = map.at(static_cast<int>(i)) == CellState::Free;
    if (!free_[i]) target_[i] = 0;  // only free cells can be covered
    target_cells_ += target_[i];
  }
}

int CoverageTracker::visit(Cell c) {
  int fresh = 0;
  for (int dy = -radius_; dy <= radius_; ++dy) {
    for (int dx = -radius_; dx <= radius_; ++dx) {
      if (dx * dx + dy * dy <= radius_ * radius_) fresh += mark({c.x + dx, c.y + dy});
    }
  }
  return fresh;
}

int CoverageTracker::mark(Cell c) {
  if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return 0;
  const std::size_t i = static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x);
  if (!free_[i] || covered_[i]) return 0;
  covered_[i] = 1;
  if (!target_[i]) return 0;
  ++covered_target_;
  return 1;
}

bool CoverageTracker::is_covered(Cell c) const {
  return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_ && covered_[static_cast<std::size_t>(c.y * width_ + c.x)];
}

bool CoverageTracker::is_target(Cell c) const {
  return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_ && target_[static_cast<std::size_t>(c.y * width_ + c.x)];
}

std::vector<std::uint8_t> CoverageTracker::uncovered() const {
  std::vector<std::uint8_t> out(target_.size(), 0);
  for (std::size_t i = 0; i < target_.size(); ++i) out[i] = target_[i] && !covered_[i];
  return out;
}

}  // namespace swarm::planner
