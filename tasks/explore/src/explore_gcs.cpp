#include "swarm/tasks/explore/explore_gcs.hpp"

#include <cstdio>

#include "swarm/app/convert.hpp"

namespace swarm::gcs {

void ExploreGcsTask::start(GcsContext& ctx) {
  complete_ = false;
  rounds_at_start_ = ctx.mission.round();
}

void ExploreGcsTask::on_group_status(const msgs::GroupStatus& s, GcsContext& ctx) {
  ctx.mission.group_arrived(s.group(), s.round());
}

void ExploreGcsTask::step(GcsContext& ctx) {
  std::vector<planner::Cell> robots;
  for (const auto& r : ctx.clock.robots()) robots.push_back({r.x(), r.y()});
  const Mission::Decision d = ctx.mission.tick(ctx.tick(), robots);
  if (d.start_round) {
    const planner::PatchEncoding encoding = map_encoding(ctx.setup);
    msgs::RoundStart rs;
    rs.round(*d.start_round);
    rs.fused_tick(d.map_tick);
    rs.width(static_cast<std::uint16_t>(d.map->width()));
    rs.height(static_cast<std::uint16_t>(d.map->height()));
    rs.encoding(static_cast<std::uint8_t>(encoding));
    rs.map_rle(app::encode_map(*d.map, encoding));
    ctx.out.round(rs);
    record::Frame version = map_frame(ctx.tick(), *d.start_round, phase_, ctx.mission.fused());
    version.mutable_map()->set_planning_map_tick(d.map_tick);  // names the map rs carries
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
