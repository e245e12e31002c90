#include "swarm/gcs/mission.hpp"

#include <algorithm>

#include "swarm/planner/explore/frontier.hpp"

namespace swarm::gcs {

using planner::CellState;

Mission::Mission(int width, int height, double resolution, MissionConfig config)
    : config_(config),
      fused_(width, height, resolution),
      seen_group_(config.groups, false),
      arrived_(config.groups, false) {}

void Mission::fuse(int group, const std::vector<planner::CellChange>& changes) {
  for (const auto& c : changes) {
    if (fused_.at(c.index) == CellState::Unknown && c.state != CellState::Unknown) ++known_;
    fused_.set(c.index, c.state);
  }
  if (group >= 0 && group < config_.groups) seen_group_[group] = true;
}

void Mission::group_arrived(int group, std::uint32_t round) {
  if (round == round_ && group >= 0 && group < config_.groups) arrived_[group] = true;
}

double Mission::mapped_fraction() const {
  return fused_.size() == 0 ? 0.0 : static_cast<double>(known_) / static_cast<double>(fused_.size());
}

Mission::Decision Mission::tick(std::uint32_t k, const std::vector<planner::Cell>& robots) {
  Decision d;
  bool start = false;
  if (round_ == 0) {
    start = std::all_of(seen_group_.begin(), seen_group_.end(), [](bool b) { return b; });
  } else {
    const bool all_arrived = std::all_of(arrived_.begin(), arrived_.end(), [](bool b) { return b; });
    start = all_arrived || k - round_start_ >= config_.replan_threshold;
  }
  if (round_ > 0) {
    std::vector<planner::Cell> seeds = config_.start_cells;
    seeds.insert(seeds.end(), robots.begin(), robots.end());
    frontier_cells_ = planner::reachable_frontiers(fused_, seeds).size();
    d.complete = frontier_cells_ == 0;
  }
  if (start && !d.complete) {
    ++round_;
    round_start_ = k;
    round_ticks_.push_back(k);
    std::fill(arrived_.begin(), arrived_.end(), false);
    snapshots_[round_] = {k, fused_};
    const std::uint32_t use = round_ > config_.map_delay_rounds ? round_ - config_.map_delay_rounds : 1;
    // Only the snapshots a later round can still use are kept.
    while (!snapshots_.empty() && snapshots_.begin()->first < use) snapshots_.erase(snapshots_.begin());
    d.start_round = round_;
    d.map = &snapshots_.at(use).second;
    d.map_tick = snapshots_.at(use).first;
  }
  return d;
}

}  // namespace swarm::gcs
