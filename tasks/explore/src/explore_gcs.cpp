#include "swarm/tasks/explore/explore_gcs.hpp"

#include <cstdio>


namespace swarm::gcs {

void ExploreGcsTask::start(GcsContext& ctx) {
  complete_ = false;
  rounds_at_start_ = ctx.mission.round();
}

void ExploreGcsTask::on_round_done(int group, std::uint32_t round, GcsContext& ctx) {
  ctx.mission.group_arrived(group, round);
}

void ExploreGcsTask::step(GcsContext& ctx) {
  std::vector<planner::Cell> robots;
  for (const auto& r : ctx.clock.robots) robots.push_back(r.cell);
  const Mission::Decision d = ctx.mission.tick(ctx.tick(), robots);
  if (d.start_round) {
    ctx.out.round(*d.start_round, d.map_tick, *d.map);
    record::Frame version = map_frame(ctx.tick(), *d.start_round, phase_, ctx.mission.fused());
    version.mutable_map()->set_planning_map_tick(d.map_tick);  // names the map the round carries
    ctx.record.append(version);
  }
  complete_ = d.complete;
  rounds_ = ctx.mission.round() - rounds_at_start_;
}

ProgressLine ExploreGcsTask::progress(const GcsContext& ctx) const {
  char detail[96];
  std::snprintf(detail, sizeof detail, "round %3u  frontier cells %zu", ctx.mission.round(),
                ctx.mission.frontier_cells());
  return {"mapped", ctx.mission.mapped_fraction(), detail};
}

nlohmann::json ExploreGcsTask::numbers() const { return {{"planning_rounds", rounds_}}; }

}  // namespace swarm::gcs
