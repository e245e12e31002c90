#include "swarm/tasks/cover/cover_gcs.hpp"

#include <chrono>
#include <cstdio>

#include "swarm/config/task_config.hpp"
#include "swarm/tasks/cover/cover_settings.hpp"
#include "swarm/planner/explore/frontier.hpp"

namespace swarm::gcs {

using planner::Cell;

namespace {
// Re-dividing is not repeated faster than this (ticks): orders need time to travel and act.
constexpr std::uint32_t kRedivideCooldown = 10;
}  // namespace

CoverGcsTask::CoverGcsTask(const swarm::scenario::Cover& config, std::uint32_t phase, bool map_given)
    : config_(config), phase_(phase), map_given_(map_given) {}

std::vector<int> CoverGcsTask::living_groups(const GcsContext& ctx) const {
  std::vector<int> out;
  const comm::Topology& t = ctx.setup.topology;
  for (int g = 0; g < t.groups(); ++g) {
    if (ctx.alive(ctx.leader_of(g))) out.push_back(g);  // a group without its leader cannot act
  }
  return out;
}

void CoverGcsTask::start(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  // The map to cover: the map file when the robots are given it, else what the GCS has fused.
  known_ = map_given_ ? ctx.setup.given_map : ctx.fused.grid();
  std::vector<Cell> robots;
  for (int r = 0; r < t.robots(); ++r) {
    if (ctx.alive(r)) robots.push_back(ctx.cell_of(r));
  }
  tracker_ = planner::CoverageTracker(known_, planner::reachable_mask(known_, robots, planner::MotionModel::four()),
                                      static_cast<int>(ctx.setup.world.scenario.footprint_radius()));
  for (int r = 0; r < t.robots(); ++r) tracker_.visit(ctx.cell_of(r));
  group_of_cell_.assign(known_.size(), -1);
  group_alive_.assign(static_cast<std::size_t>(t.groups()), false);
  group_done_.assign(static_cast<std::size_t>(t.groups()), false);
  started_ = true;
  divide(ctx, tracker_.uncovered(), "start");
}

void CoverGcsTask::divide(GcsContext& ctx, const std::vector<std::uint8_t>& cells, const char* why) {
  const comm::Topology& t = ctx.setup.topology;
  const auto t0 = std::chrono::steady_clock::now();
  const auto deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(config_.darp_time_limit_s()));
  const auto stop = [deadline] { return std::chrono::steady_clock::now() > deadline; };
  const std::vector<int> groups = living_groups(ctx);
  std::fill(group_alive_.begin(), group_alive_.end(), false);
  for (int g : groups) group_alive_[static_cast<std::size_t>(g)] = true;
  std::fill(group_done_.begin(), group_done_.end(), false);
  last_division_tick_ = ctx.tick();
  ++seq_;

  // The agents DARP divides among: the living leaders, portions by living group size
  // (hierarchical), or every living robot of a living group (flat).
  std::vector<int> robot_ids;
  std::vector<double> weights;
  for (int g : groups) {
    int living = 0;
    for (int i = 0; i < t.robots_per_group(); ++i) living += ctx.alive(t.robot(g, i)) ? 1 : 0;
    if (config_.hierarchical()) {
      robot_ids.push_back(ctx.leader_of(g));
      weights.push_back(living);
    } else {
      for (int i = 0; i < t.robots_per_group(); ++i) {
        if (ctx.alive(t.robot(g, i))) {
          robot_ids.push_back(t.robot(g, i));
          weights.push_back(1.0);
        }
      }
    }
  }
  std::vector<Cell> at;
  for (int r : robot_ids) at.push_back(ctx.cell_of(r));
  planner::CoverRoutesConfig cfg = tasks::cover_routes_config(config_, ctx.setup.world.scenario.seed(), seq_);
  cfg.routes = !config_.hierarchical();
  const planner::CoverRoutes plan = planner::divide_and_route(known_, cells, at, weights, cfg, stop);

  // Each group's share: the cells DARP gave its agents.
  std::vector<std::vector<std::uint8_t>> share(static_cast<std::size_t>(t.groups()),
                                               std::vector<std::uint8_t>(known_.size(), 0));
  std::fill(group_of_cell_.begin(), group_of_cell_.end(), -1);
  std::vector<int> agent_of_robot(static_cast<std::size_t>(t.robots()), -1);
  {
    int k = 0;
    for (std::size_t a = 0; a < robot_ids.size(); ++a) {
      if (plan.starts[a].x < 0) continue;  // reaches nothing: not a DARP agent
      agent_of_robot[static_cast<std::size_t>(robot_ids[a])] = k++;
    }
  }
  for (std::size_t i = 0; i < known_.size(); ++i) {
    const int k = plan.darp.assignment.empty() ? -1 : plan.darp.assignment[i];
    if (k < 0) continue;
    for (std::size_t a = 0; a < robot_ids.size(); ++a) {
      if (agent_of_robot[static_cast<std::size_t>(robot_ids[a])] != k) continue;
      const int g = t.group_of(static_cast<comm::AgentId>(robot_ids[a]));
      share[static_cast<std::size_t>(g)][i] = 1;
      group_of_cell_[i] = g;
    }
  }
  for (int g : groups) {
    task::Order o;
    o.group = static_cast<std::uint16_t>(g);
    o.seq = seq_;
    o.known_map = known_;
    o.cells = share[static_cast<std::size_t>(g)];
    if (!config_.hierarchical()) {
      for (std::size_t a = 0; a < robot_ids.size(); ++a) {
        if (t.group_of(static_cast<comm::AgentId>(robot_ids[a])) != g) continue;
        o.routes.push_back({robot_ids[a], plan.routes[a]});
      }
    }
    ctx.out.order(o);
    for (std::size_t a = 0; a < robot_ids.size() && !config_.hierarchical(); ++a) {
      if (t.group_of(static_cast<comm::AgentId>(robot_ids[a])) != g) continue;
      ctx.record.append(route_frame(ctx.tick(), phase_, robot_ids[a], plan.routes[a],
                                    static_cast<std::uint32_t>(plan.region_cells[a])));
    }
  }
  nlohmann::json cells_per_group = nlohmann::json::array();
  for (int g = 0; g < t.groups(); ++g) {
    int n = 0;
    for (std::uint8_t v : share[static_cast<std::size_t>(g)]) n += v;
    cells_per_group.push_back(n);
  }
  divisions_.push_back({{"tick", ctx.tick()},
                        {"why", why},
                        {"agents", config_.hierarchical() ? "leaders" : "robots"},
                        {"darp_status", planner::to_string(plan.darp.status)},
                        {"darp_iterations", plan.darp.iterations},
                        {"darp_seconds", plan.seconds_division},
                        {"alpha0", plan.darp.alpha0},
                        {"route_seconds", plan.seconds_routes},
                        {"cells_per_group", cells_per_group}});
  std::fprintf(stderr, "gcs: cover division (%s) at tick %u: %s after %d iterations, %.3f s\n", why, ctx.tick(),
               planner::to_string(plan.darp.status), plan.darp.iterations, plan.seconds_division);
}

void CoverGcsTask::on_report(const task::Report& r, GcsContext&) {
  if (r.group < group_done_.size() && r.state == task::GroupState::Done) group_done_[r.group] = true;
  // Cells a leader knows covered (after a restart of the GCS, which missed the clocks meanwhile).
  for (const planner::Cell c : r.cells) tracker_.mark(c);
}

void CoverGcsTask::step(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  for (int r = 0; r < t.robots(); ++r) {
    if (ctx.alive(r)) tracker_.visit(ctx.cell_of(r));
  }
  if (tracker_.complete() || ctx.tick() < last_division_tick_ + kRedivideCooldown) return;
  // A group that held uncovered cells and lost its leader: what is left goes to the others.
  const std::vector<std::uint8_t> left = tracker_.uncovered();
  bool orphaned = false, all_done = true;
  for (int g = 0; g < t.groups(); ++g) {
    if (!group_alive_[static_cast<std::size_t>(g)]) continue;
    if (!ctx.alive(ctx.leader_of(g))) {
      for (std::size_t i = 0; i < left.size() && !orphaned; ++i) orphaned = left[i] && group_of_cell_[i] == g;
    } else {
      all_done = all_done && group_done_[static_cast<std::size_t>(g)];
    }
  }
  if (orphaned) {
    divide(ctx, left, "a group lost its leader");
  } else if (all_done && !living_groups(ctx).empty()) {
    divide(ctx, left, "every group done, cells left");
  }
}

ProgressLine CoverGcsTask::progress(const GcsContext&) const {
  int done = 0;
  for (bool d : group_done_) done += d ? 1 : 0;
  char detail[96];
  std::snprintf(detail, sizeof detail, "cells %d/%d  groups done %d", tracker_.covered_cells(), tracker_.target_cells(),
                done);
  return {"covered", tracker_.fraction(), detail};
}

nlohmann::json CoverGcsTask::numbers() const {
  return {{"hierarchical", config_.hierarchical()},
          {"order", swarm::scenario::CoverOrder_Name(config_.order())},
          {"map_given", map_given_},
          {"target_cells_known", tracker_.target_cells()},
          {"covered_cells_known", tracker_.covered_cells()},
          {"divisions", divisions_}};
}

}  // namespace swarm::gcs
