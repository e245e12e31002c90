#include "swarm/tasks/explore/planning_rounds.hpp"

#include <algorithm>

#include "swarm/planner/explore/frontier.hpp"

namespace swarm::tasks {

PlanningRounds::PlanningRounds(PlanningRoundsConfig config)
    : config_(std::move(config)), arrived_(static_cast<std::size_t>(config_.groups), false) {}

void PlanningRounds::group_arrived(int group, std::uint32_t round) {
  if (round == round_ && group >= 0 && group < config_.groups) arrived_[group] = true;
}

PlanningRounds::Decision PlanningRounds::tick(std::uint32_t k, const gcs::FusedMap& fused,
                                              const std::vector<planner::Cell>& robots) {
  Decision d;
  bool start = false;
  if (round_ == 0) {
    start = fused.heard_from_every_group();
  } else {
    const bool all_arrived = std::all_of(arrived_.begin(), arrived_.end(), [](bool b) { return b; });
    start = all_arrived || k - round_start_ >= config_.replan_threshold;
  }
  if (round_ > 0) {
    std::vector<planner::Cell> seeds = config_.start_cells;
    seeds.insert(seeds.end(), robots.begin(), robots.end());
    frontier_cells_ = planner::reachable_frontiers(fused.grid(), seeds).size();
    d.complete = frontier_cells_ == 0;
  }
  if (start && !d.complete) {
    ++round_;
    round_start_ = k;
    round_ticks_.push_back(k);
    std::fill(arrived_.begin(), arrived_.end(), false);
    snapshots_[round_] = {k, fused.grid()};
    const std::uint32_t use = round_ > config_.map_delay_rounds ? round_ - config_.map_delay_rounds : 1;
    // Only the snapshots a later round can still use are kept.
    while (!snapshots_.empty() && snapshots_.begin()->first < use) snapshots_.erase(snapshots_.begin());
    d.start_round = round_;
    d.map = &snapshots_.at(use).second;
    d.map_tick = snapshots_.at(use).first;
  }
  return d;
}

}  // namespace swarm::tasks
