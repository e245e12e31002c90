#include "swarm/tasks/explore/explore_gcs.hpp"

#include <cstdio>

namespace swarm::gcs {

void ExploreGcsTask::start(GcsContext&) {
  complete_ = false;
  rounds_ = tasks::PlanningRounds(config_);
  first_round_.reset();
}

void ExploreGcsTask::on_round_done(int group, std::uint32_t round, GcsContext&) {
  if (first_round_ && round >= *first_round_) rounds_.group_arrived(group, round - *first_round_ + 1);
}

void ExploreGcsTask::step(GcsContext& ctx) {
  std::vector<planner::Cell> robots;
  for (const auto& r : ctx.clock.robots) robots.push_back(r.cell);
  const tasks::PlanningRounds::Decision d = rounds_.tick(ctx.tick(), ctx.fused, robots);
  if (d.start_round) {
    const std::uint32_t round = ctx.out.round(d.map_tick, *d.map);
    if (!first_round_) first_round_ = round;
    record::Frame version = map_frame(ctx.tick(), round, phase_, ctx.fused.grid());
    version.mutable_map()->set_planning_map_tick(d.map_tick);  // names the map the round carries
    ctx.record.append(version);
  }
  complete_ = d.complete;
}

ProgressLine ExploreGcsTask::progress(const GcsContext& ctx) const {
  char detail[96];
  const std::uint32_t round = first_round_ ? *first_round_ + rounds_.round() - 1 : 0;
  std::snprintf(detail, sizeof detail, "round %3u  frontier cells %zu", round, rounds_.frontier_cells());
  return {"mapped", ctx.fused.mapped_fraction(), detail};
}

nlohmann::json ExploreGcsTask::numbers() const { return {{"planning_rounds", rounds_.round()}}; }

}  // namespace swarm::gcs
