#include "swarm/tasks/explore/explore_leader.hpp"

#include <chrono>

#include "swarm/tasks/explore/waypoint_report.hpp"

namespace swarm::leader {

using planner::Cell;

planner::ExploreConfig explore_config(const swarm::scenario::Explore& e, std::uint64_t seed) {
  planner::ExploreConfig c;
  c.use_group_frontiers = e.mode() != swarm::scenario::BASELINE;
  c.dbscan_eps_cells = e.dbscan_eps_cells();
  c.dbscan_min_points = static_cast<int>(e.dbscan_min_points());
  c.small_segment_max_cells = static_cast<int>(e.small_segment_max_cells());
  c.small_segment_radius_cells = e.small_segment_radius_cells();
  c.kmeans_max_iterations = static_cast<int>(e.kmeans_max_iterations());
  c.seed = seed;
  return c;
}

ExploreGroupTask::ExploreGroupTask(const swarm::scenario::Explore& config, std::uint64_t seed, int robots_per_group,
                                   int group, std::optional<swarm::scenario::Mapf> drive)
    : explore_(explore_config(config, seed)), arrived_(static_cast<std::size_t>(robots_per_group), true) {
  if (drive) drive_ = std::make_unique<MapfGroupTask>(*drive, group);
}

void ExploreGroupTask::start(GroupContext& ctx) {
  if (drive_) drive_->start(ctx);
  sent_waypoints_ = {};
  pending_round_.reset();
  round_ = 0;
  std::fill(arrived_.begin(), arrived_.end(), true);
  group_reported_ = true;
}

void ExploreGroupTask::on_round(std::uint32_t round, GroupContext&) { pending_round_ = round; }

void ExploreGroupTask::on_waypoint(const task::WaypointReport& s, GroupContext& ctx) {
  if (s.round != round_) return;
  arrived_[static_cast<std::size_t>(ctx.topology().index_of(static_cast<comm::AgentId>(s.robot)))] = true;
  if (s.state < 4) ++waypoints_[s.state];
}

void ExploreGroupTask::on_order(const task::Order& order, GroupContext& ctx) {
  if (drive_) drive_->on_order(order, ctx);
}

void ExploreGroupTask::on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) {
  if (drive_) drive_->on_progress(index, p, ctx);
}

void ExploreGroupTask::took_over(GroupContext& ctx) {
  if (drive_) drive_->took_over(ctx);
}

void ExploreGroupTask::member_lost(int index, GroupContext&) { arrived_[static_cast<std::size_t>(index)] = true; }
void ExploreGroupTask::member_back(int index, GroupContext&) { arrived_[static_cast<std::size_t>(index)] = true; }

void ExploreGroupTask::plan(std::uint32_t round, GroupContext& ctx) {
  const auto t0 = std::chrono::steady_clock::now();
  const comm::Topology& t = ctx.topology();
  planner::ExploreInput in;
  in.global_map = &ctx.map.global();
  in.group_map = &ctx.map.group();
  for (int g = 0; g < t.groups(); ++g) in.leader_positions.push_back(ctx.leader_cell(g));
  in.group = ctx.group;
  // Only the living robots get waypoints (K-Means with k = living members); the leader's own
  // robot is always alive.
  const std::vector<int> living = ctx.living();
  for (int i : living) in.member_positions.push_back(ctx.cell_of(i));
  in.round = static_cast<int>(round);
  planner::ExplorePlan plan = planner::plan_group_exploration(in, explore_);
  std::vector<std::optional<Cell>> waypoints(static_cast<std::size_t>(t.robots_per_group()));
  for (std::size_t j = 0; j < living.size(); ++j) waypoints[static_cast<std::size_t>(living[j])] = plan.waypoints[j];
  plan.waypoints = waypoints;
  planning_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++rounds_planned_;
  if (plan.plan_case == planner::PlanCase::GroupFrontier) ++case_a_;
  if (plan.plan_case == planner::PlanCase::GlobalAssignment) ++case_b_;

  round_ = round;
  if (drive_) {
    // The GCS drives the robots there and judges the round's arrivals.
    tasks::RoundWaypoints w;
    w.round = round;
    for (int i = 0; i < t.robots_per_group(); ++i) {
      if (!plan.waypoints[static_cast<std::size_t>(i)]) continue;
      w.robots.push_back(t.robot(ctx.group, i));
      w.cells.push_back(*plan.waypoints[static_cast<std::size_t>(i)]);
    }
    sent_waypoints_ = tasks::waypoints_report(w);
    ctx.out.report(sent_waypoints_);
  } else {
    for (int i = 0; i < t.robots_per_group(); ++i) arrived_[static_cast<std::size_t>(i)] = !plan.waypoints[static_cast<std::size_t>(i)].has_value();
    group_reported_ = false;
    ctx.own.assign(round, plan.waypoints[static_cast<std::size_t>(ctx.self)]);
    ctx.out.waypoints(round, plan.waypoints);
  }
  ctx.out.plan_telemetry({round, static_cast<std::uint8_t>(plan.plan_case), plan.waypoints, plan.group_frontiers,
                          plan.global_segments, plan.chosen_segment});
}

void ExploreGroupTask::step(GroupContext& ctx) {
  if (pending_round_) {
    plan(*pending_round_, ctx);
    pending_round_.reset();
  }
  if (drive_) drive_->step(ctx);
}

void ExploreGroupTask::finish_step(GroupContext& ctx) {
  bool all_arrived = true;
  for (bool a : arrived_) all_arrived = all_arrived && a;
  if (round_ > 0 && all_arrived && !group_reported_) {
    ctx.out.round_done(round_);
    group_reported_ = true;
  }
}

void ExploreGroupTask::gcs_back(GroupContext& ctx) {
  if (drive_) {
    // The round's waypoints, which the GCS judges the round by.
    if (round_ > 0) ctx.out.report(sent_waypoints_);
    drive_->gcs_back(ctx);
    return;
  }
  // The round's arrival, if the GCS may have missed it.
  if (round_ > 0 && group_reported_) ctx.out.round_done(round_);
}

nlohmann::json ExploreGroupTask::numbers() const {
  nlohmann::json j = {{"rounds_planned", rounds_planned_},
          {"case_a_rounds", case_a_},
          {"case_b_rounds", case_b_},
          {"planning_seconds", planning_seconds_},
          {"waypoints_reached", waypoints_[1]},
          {"waypoints_unreachable", waypoints_[2]},
          {"waypoints_blocked_near", waypoints_[3]}};
  if (drive_) j["traffic"] = drive_->numbers();
  return j;
}

}  // namespace swarm::leader
