#include "swarm/tasks/explore/explore_gcs.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "swarm/tasks/explore/waypoint_report.hpp"

namespace swarm::gcs {

using planner::Cell;

namespace {
// A waypoint the fused map does not know as free yet (a leader plans on its group map, which is
// ahead of the GCS's by a link): the nearest free cell within this many cells stands in for it.
constexpr int kStandInRadius = 3;

std::optional<Cell> standing_cell(const planner::OccupancyGrid& map, Cell w) {
  if (map.is_free(w)) return w;
  std::optional<Cell> best;
  int best_d = 0;
  for (int dy = -kStandInRadius; dy <= kStandInRadius; ++dy) {
    for (int dx = -kStandInRadius; dx <= kStandInRadius; ++dx) {
      const Cell c{w.x + dx, w.y + dy};
      const int d = std::max(std::abs(dx), std::abs(dy)) * 8 + std::abs(dx) + std::abs(dy);  // ring, then axis first
      if (map.is_free(c) && (!best || d < best_d)) {
        best = c;
        best_d = d;
      }
    }
  }
  return best;
}
}  // namespace

ExploreGcsTask::ExploreGcsTask(std::uint32_t phase, tasks::PlanningRoundsConfig config, const Drive& drive)
    : phase_(phase), config_(std::move(config)), rounds_(config_) {
  MapfGcsTask::Lifelong lifelong;
  lifelong.routes = [this](const GcsContext& ctx, const planner::OccupancyGrid& map, const std::vector<int>& robots,
                           const char*) { return targets(ctx, map, robots); };
  lifelong.done = [this](int robot, const MapfGcsTask::Stop& stop, bool reached) { target_done(robot, stop, reached); };
  lifelong.window = drive.window;
  lifelong.motion = planner::MotionModel::eight();  // the paper's 8-connected robots
  lifelong.map_grows = true;
  drive_ = std::make_unique<MapfGcsTask>(drive.paths, phase, false, std::move(lifelong));
}

void ExploreGcsTask::start(GcsContext& ctx) {
  complete_ = false;
  rounds_ = tasks::PlanningRounds(config_);
  first_round_.reset();
  driving_ = false;
  new_targets_ = false;
  const comm::Topology& t = ctx.setup.topology;
  target_.assign(static_cast<std::size_t>(t.robots()), std::nullopt);
  group_round_.assign(static_cast<std::size_t>(t.groups()), 0);
  group_arrived_.assign(static_cast<std::size_t>(t.groups()), true);
}

void ExploreGcsTask::on_report(const task::Report& r, GcsContext& ctx) {
  const std::optional<tasks::RoundWaypoints> w = tasks::read_waypoints_report(r);
  if (!w) {
    if (driving_) drive_->on_report(r, ctx);
    return;
  }
  const comm::Topology& t = ctx.setup.topology;
  const auto g = static_cast<std::size_t>(r.group);
  // The group's newest round's, about its own robots. A round older than the GCS's current one
  // still counts when it is the newest the group has sent: with a leader<->GCS delay as long as
  // half the replanning interval, every report arrives after the next round has begun, and taking
  // only the current round's left every robot standing (maze1, 10 ticks each way: 5.4 % explored
  // in 1,000 ticks).
  if (!first_round_ || g >= group_round_.size() || w->round < *first_round_ ||
      w->round - *first_round_ + 1 > rounds_.round() || w->round <= group_round_[g]) {
    return;
  }
  for (int i = 0; i < t.robots_per_group(); ++i) target_[static_cast<std::size_t>(t.robot(static_cast<int>(g), i))].reset();
  for (std::size_t k = 0; k < w->robots.size(); ++k) {
    const int robot = w->robots[k];
    if (robot < 0 || robot >= t.robots() || t.group_of(static_cast<comm::AgentId>(robot)) != static_cast<int>(g)) continue;
    target_[static_cast<std::size_t>(robot)] = w->cells[k];
  }
  group_round_[g] = w->round;
  group_arrived_[g] = false;
  new_targets_ = true;  // taken up in step(), once every report of the tick is in
  note_arrivals();
}

std::vector<std::vector<MapfGcsTask::Stop>> ExploreGcsTask::targets(const GcsContext& ctx,
                                                                    const planner::OccupancyGrid& map,
                                                                    const std::vector<int>& robots) {
  std::vector<std::vector<MapfGcsTask::Stop>> out(target_.size());
  std::vector<bool> may_move(target_.size(), false);
  for (const int r : robots) may_move[static_cast<std::size_t>(r)] = true;
  for (std::size_t r = 0; r < target_.size(); ++r) {
    if (!target_[r]) continue;
    // A robot that is lost, or whose leader is, is not driven: its waypoint is given up.
    if (!may_move[r] || !ctx.alive(static_cast<int>(r))) {
      target_[r].reset();
      ++targets_skipped_;
      continue;
    }
    const std::optional<Cell> c = standing_cell(map, *target_[r]);
    if (!c) {
      target_[r].reset();
      ++targets_skipped_;
      continue;
    }
    if (*c != *target_[r]) ++targets_moved_;
    target_[r] = *c;
    out[r].push_back({*c, MapfGcsTask::Stop::Act::kNone});
  }
  note_arrivals();
  return out;
}

void ExploreGcsTask::target_done(int robot, const MapfGcsTask::Stop& stop, bool reached) {
  auto& target = target_[static_cast<std::size_t>(robot)];
  // A stop of an earlier round, replaced meanwhile, says nothing of the new one.
  if (!target || *target != stop.cell) return;
  target.reset();
  ++(reached ? targets_reached_ : targets_skipped_);
  note_arrivals();
}

void ExploreGcsTask::note_arrivals() {
  if (!first_round_) return;
  const int groups = static_cast<int>(group_round_.size());
  const int per_group = groups > 0 ? static_cast<int>(target_.size()) / groups : 0;
  for (int g = 0; g < groups; ++g) {
    const auto ug = static_cast<std::size_t>(g);
    if (group_arrived_[ug] || group_round_[ug] == 0) continue;
    bool left = false;
    for (int i = 0; i < per_group; ++i) left = left || target_[static_cast<std::size_t>(g * per_group + i)].has_value();
    if (left) continue;
    group_arrived_[ug] = true;
    if (group_round_[ug] >= *first_round_) rounds_.group_arrived(g, group_round_[ug] - *first_round_ + 1);
  }
}

void ExploreGcsTask::step(GcsContext& ctx) {
  if (new_targets_ && !driving_) {
    new_targets_ = false;
    driving_ = true;
    drive_->start(ctx);
  } else if (driving_) {
    // A round's waypoints go into the next window in the tick they come, not a tick later.
    if (new_targets_) drive_->repick(ctx, "round");
    new_targets_ = false;
    drive_->step(ctx);
  }
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
  // Done exploring, the robots may still be on their way: a rotation ordered goes first.
  if (d.complete) drive_->wind_down();
  complete_ = d.complete && !drive_->rotating(ctx.tick());
}

ProgressLine ExploreGcsTask::progress(const GcsContext& ctx) const {
  char detail[96];
  const std::uint32_t round = first_round_ ? *first_round_ + rounds_.round() - 1 : 0;
  std::snprintf(detail, sizeof detail, "round %3u  frontier cells %zu", round, rounds_.frontier_cells());
  return {"mapped", ctx.fused.mapped_fraction(), detail};
}

nlohmann::json ExploreGcsTask::numbers() const {
  return {{"planning_rounds", rounds_.round()},
          {"traffic", drive_->numbers()},
          {"waypoints_reached", targets_reached_},
          {"waypoints_skipped", targets_skipped_},
          {"waypoints_moved_to_a_known_cell", targets_moved_}};
}

}  // namespace swarm::gcs
