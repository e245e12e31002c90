#include "swarm/tasks/cover/cover_gcs.hpp"

#include <chrono>
#include <cstdio>

#include "swarm/config/task_config.hpp"
#include "swarm/planner/grid/deadline.hpp"
#include "swarm/tasks/cover/cover_settings.hpp"
#include "swarm/planner/explore/frontier.hpp"

namespace swarm::gcs {

using planner::Cell;

namespace {
// Re-dividing is not repeated faster than this (ticks): orders need time to travel and act.
constexpr std::uint32_t kRedivideCooldown = 10;
}  // namespace

CoverGcsTask::CoverGcsTask(const swarm::scenario::Cover& config, const swarm::scenario::Mapf& paths,
                           std::uint32_t phase, bool map_given)
    : config_(config), phase_(phase), map_given_(map_given) {
  if (config_.traffic()) {
    MapfGcsTask::Lifelong drive;
    drive.routes = [this](const GcsContext& ctx, const planner::OccupancyGrid&, const std::vector<int>& robots,
                          const char* why) { return MapfGcsTask::passing(divide(ctx, tracker_.uncovered(), why, &robots)); };
    drive.window = static_cast<int>(config_.traffic_window_steps());
    drive_ = std::make_unique<MapfGcsTask>(paths, phase, map_given, std::move(drive));
  }
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
  group_of_cell_.assign(known_.size(), -1);
  group_alive_.assign(static_cast<std::size_t>(t.groups()), false);
  group_done_.assign(static_cast<std::size_t>(t.groups()), false);
  started_ = true;
  if (drive_) {
    drive_->start(ctx);
  } else {
    divide(ctx, tracker_.uncovered(), "start");
  }
}

std::string CoverGcsTask::given_up() const {
  if (nothing_to_drive_) return "cells left uncovered that no robot's route reaches";
  return drive_ ? drive_->given_up() : std::string();
}

std::vector<std::vector<Cell>> CoverGcsTask::divide(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                    const char* why, const std::vector<int>* robots) {
  const comm::Topology& t = ctx.setup.topology;
  const auto t0 = std::chrono::steady_clock::now();
  const auto deadline = planner::deadline_after(config_.darp_time_limit_s(), t0);
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
  const bool flat = !config_.hierarchical();
  if (robots != nullptr && flat) {
    robot_ids = *robots;
    weights.assign(robot_ids.size(), 1.0);
  }
  for (int g : robots != nullptr && flat ? std::vector<int>{} : groups) {
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
  cfg.routes = flat;
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
  std::vector<std::vector<Cell>> routes;
  nlohmann::json within_groups = nlohmann::json::array();
  if (robots != nullptr) {
    // Every robot's route: from the division itself (flat), or from dividing each group's share
    // among its robots as its leader would (hierarchical).
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
        for (const int r : *robots) {
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
  }
  for (int g : robots != nullptr ? std::vector<int>{} : groups) {
    task::Order o;
    o.group = static_cast<std::uint16_t>(g);
    o.seq = seq_;
    o.known_map = known_;
    o.cells = share[static_cast<std::size_t>(g)];
    if (flat) {
      for (std::size_t a = 0; a < robot_ids.size(); ++a) {
        if (t.group_of(static_cast<comm::AgentId>(robot_ids[a])) != g) continue;
        o.routes.push_back({robot_ids[a], plan.routes[a]});
      }
    }
    ctx.out.order(o);
    for (std::size_t a = 0; a < robot_ids.size() && flat; ++a) {
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

void CoverGcsTask::on_report(const task::Report& r, GcsContext& ctx) {
  if (drive_) {
    drive_->on_report(r, ctx);
    return;
  }
  if (r.group < group_done_.size() && r.state == task::GroupState::Done) group_done_[r.group] = true;
  // Cells a leader knows covered (after a restart of the GCS, which missed the clocks meanwhile).
  for (const planner::Cell c : r.cells) tracker_.mark(c);
}

void CoverGcsTask::step(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  for (int r = 0; r < t.robots(); ++r) {
    if (ctx.alive(r)) tracker_.visit(ctx.cell_of(r));
  }
  if (drive_) {
    if (tracker_.complete()) return;
    drive_->step(ctx);
    // Every route driven and cells still uncovered (a footprint that missed, a goal skipped):
    // those are divided again.
    if (drive_->complete() && !nothing_to_drive_) drive_->restart(ctx, "every route done, cells left");
    return;
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
  nlohmann::json j = {{"hierarchical", config_.hierarchical()},
                      {"order", swarm::scenario::CoverOrder_Name(config_.order())},
                      {"map_given", map_given_},
                      {"target_cells_known", tracker_.target_cells()},
                      {"covered_cells_known", tracker_.covered_cells()},
                      {"divisions", divisions_}};
  if (drive_) j["traffic"] = drive_->numbers();
  return j;
}

}  // namespace swarm::gcs
