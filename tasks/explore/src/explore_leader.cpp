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

ExploreGroupTask::ExploreGroupTask(const swarm::scenario::Explore& config, std::uint64_t seed, int group,
                                   const swarm::scenario::Mapf& drive)
    : explore_(explore_config(config, seed)), drive_(drive, group) {}

void ExploreGroupTask::start(GroupContext& ctx) {
  drive_.start(ctx);
  sent_waypoints_ = {};
  pending_round_.reset();
  round_ = 0;
}

void ExploreGroupTask::on_round(std::uint32_t round, GroupContext&) { pending_round_ = round; }

void ExploreGroupTask::on_order(const task::Order& order, GroupContext& ctx) { drive_.on_order(order, ctx); }

void ExploreGroupTask::on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) {
  drive_.on_progress(index, p, ctx);
}

void ExploreGroupTask::took_over(GroupContext& ctx) { drive_.took_over(ctx); }

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
  ctx.out.plan_telemetry({round, static_cast<std::uint8_t>(plan.plan_case), plan.waypoints, plan.group_frontiers,
                          plan.global_segments, plan.chosen_segment});
}

void ExploreGroupTask::step(GroupContext& ctx) {
  if (pending_round_) {
    plan(*pending_round_, ctx);
    pending_round_.reset();
  }
  drive_.step(ctx);
}

void ExploreGroupTask::gcs_back(GroupContext& ctx) {
  // The round's waypoints, which the GCS judges the round by.
  if (round_ > 0) ctx.out.report(sent_waypoints_);
  drive_.gcs_back(ctx);
}

nlohmann::json ExploreGroupTask::numbers() const {
  return {{"rounds_planned", rounds_planned_},
          {"case_a_rounds", case_a_},
          {"case_b_rounds", case_b_},
          {"planning_seconds", planning_seconds_},
          {"traffic", drive_.numbers()}};
}

}  // namespace swarm::leader
