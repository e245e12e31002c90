#include "swarm/tasks/cover/cover_gcs.hpp"

#include <chrono>
#include <cstdio>

#include "swarm/config/task_config.hpp"
#include "swarm/planner/grid/deadline.hpp"
#include "swarm/tasks/cover/cover_settings.hpp"
#include "swarm/planner/explore/frontier.hpp"

namespace swarm::gcs {

using planner::Cell;

CoverGcsTask::CoverGcsTask(const swarm::scenario::Cover& config, const swarm::scenario::Mapf& paths,
                           std::uint32_t phase, bool map_given)
    : config_(config), phase_(phase), map_given_(map_given) {
  MapfGcsTask::Lifelong drive;
  drive.routes = [this](const GcsContext& ctx, const planner::OccupancyGrid&, const std::vector<int>& robots,
                        const char* why) { return MapfGcsTask::passing(divide(ctx, tracker_.uncovered(), why, robots)); };
  drive.window = static_cast<int>(config_.traffic_window_steps());
  drive_ = std::make_unique<MapfGcsTask>(paths, phase, map_given, std::move(drive));
}

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
  started_ = true;
  drive_->start(ctx);
}

std::string CoverGcsTask::given_up() const {
  if (nothing_to_drive_) return "cells left uncovered that no robot's route reaches";
  return drive_->given_up();
}

std::vector<std::vector<Cell>> CoverGcsTask::divide(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                    const char* why, const std::vector<int>& robots) {
  const comm::Topology& t = ctx.setup.topology;
  const auto t0 = std::chrono::steady_clock::now();
  const auto deadline = planner::deadline_after(config_.darp_time_limit_s(), t0);
  const auto stop = [deadline] { return std::chrono::steady_clock::now() > deadline; };
  const std::vector<int> groups = living_groups(ctx);
  ++seq_;

  // The agents DARP divides among: the living leaders, portions by living group size
  // (hierarchical), or every living robot of a living group (flat).
  std::vector<int> robot_ids;
  std::vector<double> weights;
  const bool flat = !config_.hierarchical();
  if (flat) {
    robot_ids = robots;
    weights.assign(robot_ids.size(), 1.0);
  } else {
    for (int g : groups) {
      int living = 0;
      for (int i = 0; i < t.robots_per_group(); ++i) living += ctx.alive(t.robot(g, i)) ? 1 : 0;
      robot_ids.push_back(ctx.leader_of(g));
      weights.push_back(living);
    }
  }
  std::vector<Cell> at;
  for (int r : robot_ids) at.push_back(ctx.cell_of(r));
  planner::CoverRoutesConfig cfg = tasks::cover_routes_config(config_, ctx.setup.world.scenario.seed(), seq_);
  cfg.routes = flat;
  const planner::CoverRoutes plan = planner::divide_and_route(known_, cells, at, weights, cfg, stop);

  // Each group's share: the cells DARP gave its agents.
  std::vector<std::vector<std::uint8_t>> share(static_cast<std::size_t>(t.groups()),
                                               std::vector<std::uint8_t>(known_.size(), 0));
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
    }
  }
  std::vector<std::vector<Cell>> routes;
  nlohmann::json within_groups = nlohmann::json::array();
  // Every robot's route: from the division itself (flat), or from dividing each group's share
  // among its robots (hierarchical).
  routes.resize(static_cast<std::size_t>(t.robots()));
  std::size_t goals = 0;
  const auto take = [&](int robot, const std::vector<Cell>& route, int region_cells) {
    routes[static_cast<std::size_t>(robot)] = route;
    goals += route.size();
    ctx.record.append(route_frame(ctx.tick(), phase_, robot, route, static_cast<std::uint32_t>(region_cells)));
  };
  if (flat) {
    for (std::size_t a = 0; a < robot_ids.size(); ++a) take(robot_ids[a], plan.routes[a], plan.region_cells[a]);
  } else {
    for (const int g : groups) {
      std::vector<int> members;
      std::vector<Cell> member_at;
      for (const int r : robots) {
        if (t.group_of(static_cast<comm::AgentId>(r)) != g) continue;
        members.push_back(r);
        member_at.push_back(ctx.cell_of(r));
      }
      if (members.empty()) continue;
      planner::CoverRoutesConfig group_cfg = tasks::cover_routes_config(
          config_, ctx.setup.world.scenario.seed(), (std::uint64_t{seq_} << 8) + static_cast<std::uint64_t>(g) + 1);
      group_cfg.routes = true;
      const planner::CoverRoutes sub = planner::divide_and_route(
          known_, share[static_cast<std::size_t>(g)], member_at, std::vector<double>(members.size(), 1.0), group_cfg, stop);
      for (std::size_t k = 0; k < members.size(); ++k) take(members[k], sub.routes[k], sub.region_cells[k]);
      nlohmann::json entry = tasks::division_json(sub);
      entry["group"] = g;
      entry["robots"] = members;
      within_groups.push_back(std::move(entry));
    }
  }
  nothing_to_drive_ = goals == 0 && !tracker_.complete();
  nlohmann::json cells_per_group = nlohmann::json::array();
  for (int g = 0; g < t.groups(); ++g) {
    int n = 0;
    for (std::uint8_t v : share[static_cast<std::size_t>(g)]) n += v;
    cells_per_group.push_back(n);
  }
  nlohmann::json entry = tasks::division_json(plan);
  entry["tick"] = ctx.tick();
  entry["why"] = why;
  entry["agents"] = flat ? "robots" : "leaders";
  entry["cells_per_group"] = cells_per_group;
  if (!within_groups.empty()) entry["within_groups"] = std::move(within_groups);
  divisions_.push_back(std::move(entry));
  std::fprintf(stderr, "gcs: cover division (%s) at tick %u: %s (by %s) after %d iterations, %.3f s\n", why,
               ctx.tick(), planner::to_string(plan.darp.status), plan.darp.finished_by.c_str(), plan.darp.iterations,
               plan.seconds_division);
  return routes;
}

void CoverGcsTask::on_report(const task::Report& r, GcsContext& ctx) { drive_->on_report(r, ctx); }

void CoverGcsTask::step(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  for (int r = 0; r < t.robots(); ++r) {
    if (ctx.alive(r)) tracker_.visit(ctx.cell_of(r));
  }
  if (tracker_.complete()) return;
  drive_->step(ctx);
  // Every route driven and cells still uncovered (a footprint that missed, a goal skipped):
  // those are divided again.
  if (drive_->complete() && !nothing_to_drive_) drive_->restart(ctx, "every route done, cells left");
}

ProgressLine CoverGcsTask::progress(const GcsContext&) const {
  char detail[96];
  std::snprintf(detail, sizeof detail, "cells %d/%d", tracker_.covered_cells(), tracker_.target_cells());
  return {"covered", tracker_.fraction(), detail};
}

nlohmann::json CoverGcsTask::numbers() const {
  nlohmann::json j = {{"hierarchical", config_.hierarchical()},
                      {"order", swarm::scenario::CoverOrder_Name(config_.order())},
                      {"map_given", map_given_},
                      {"target_cells_known", tracker_.target_cells()},
                      {"covered_cells_known", tracker_.covered_cells()},
                      {"divisions", divisions_}};
  j["traffic"] = drive_->numbers();
  return j;
}

}  // namespace swarm::gcs
