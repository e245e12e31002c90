#include "swarm/tasks/cover/cover_leader.hpp"

#include <chrono>
#include <cstdio>

#include "swarm/config/task_config.hpp"
#include "swarm/planner/grid/deadline.hpp"
#include "swarm/tasks/cover/cover_settings.hpp"

namespace swarm::leader {

using planner::Cell;
using planner::RouteState;

namespace {
}  // namespace

CoverGroupTask::CoverGroupTask(const swarm::scenario::Cover& config, const app::RoleSetup& setup, int group)
    : config_(config),
      seed_(setup.world.scenario.seed()),
      group_(group),
      footprint_(static_cast<int>(setup.world.scenario.footprint_radius())),
      robots_(static_cast<std::size_t>(setup.topology.robots_per_group())) {}

void CoverGroupTask::start(GroupContext&) {
  have_share_ = false;
  reported_done_ = false;
  for (Robot& r : robots_) r = Robot{};
}

void CoverGroupTask::send(GroupContext& ctx, int index, std::vector<Cell> route) {
  Robot& r = robots_[static_cast<std::size_t>(index)];
  task::Route m;
  m.path = route;
  m.release = static_cast<std::uint32_t>(route.size() - 1);
  r.route_id = ctx.out.route(index, m);
  r.step = 0;
  r.state = route.size() > 1 ? RouteState::Active : RouteState::Finished;
  r.moved_tick = tick_;
  r.route = std::move(route);
}

void CoverGroupTask::on_order(const task::Order& o, GroupContext& ctx) {
  if (o.seq <= order_seq_ && have_share_) return;  // an older order
  if (!o.known_map || o.cells.empty()) throw std::runtime_error("a cover order without its map and share");
  order_seq_ = o.seq;
  tick_ = ctx.clock.tick;
  known_ = *o.known_map;
  share_ = o.cells;
  tracker_ = planner::CoverageTracker(known_, share_, footprint_);
  for (const task::RobotAt& s : ctx.clock.robots) tracker_.visit(s.cell);
  have_share_ = true;
  reported_done_ = false;
  if (o.routes.empty()) {
    divide(ctx, "order");
    return;
  }
  // Flat: the GCS planned every robot's route.
  const comm::Topology& t = ctx.topology();
  for (const task::PlannedRoute& r : o.routes) {
    const int index = t.index_of(static_cast<comm::AgentId>(r.robot));
    if (ctx.alive[static_cast<std::size_t>(index)]) send(ctx, index, r.path);
  }
}

void CoverGroupTask::divide(GroupContext& ctx, const char* why) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto deadline = planner::deadline_after(config_.darp_time_limit_s(), t0);
  const std::vector<int> living = ctx.living();
  std::vector<Cell> at;
  for (int i : living) at.push_back(ctx.cell_of(i));
  ++divisions_count_;
  const planner::CoverRoutesConfig cfg =
      tasks::cover_routes_config(config_, seed_, static_cast<std::uint64_t>(1000 + group_ * 100 + divisions_count_));
  const planner::CoverRoutes plan = planner::divide_and_route(
      known_, tracker_.uncovered(), at, {}, cfg, [deadline] { return std::chrono::steady_clock::now() > deadline; });
  nlohmann::json cells = nlohmann::json::array(), lengths = nlohmann::json::array(), turns = nlohmann::json::array();
  for (std::size_t k = 0; k < living.size(); ++k) {
    send(ctx, living[k], plan.routes[k]);
    cells.push_back(plan.region_cells[k]);
    lengths.push_back(plan.routes[k].size() - 1);
    turns.push_back(plan.turns[k]);
  }
  nlohmann::json entry = tasks::division_json(plan);
  entry["tick"] = ctx.clock.tick;
  entry["why"] = why;
  entry["robots"] = living.size();
  entry["cells"] = cells;
  entry["path_length"] = lengths;
  entry["turns"] = turns;
  divisions_.push_back(std::move(entry));
}

void CoverGroupTask::on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) {
  Robot& r = robots_[static_cast<std::size_t>(index)];
  if (p.id != r.route_id) return;  // about a route replaced since
  if (p.step != r.step) r.moved_tick = ctx.clock.tick;
  r.step = p.step;
  r.state = p.state;
}

void CoverGroupTask::member_lost(int index, GroupContext& ctx) {
  robots_[static_cast<std::size_t>(index)].state = RouteState::None;
  if (have_share_ && !tracker_.complete()) divide(ctx, "member lost");
}

void CoverGroupTask::member_back(int, GroupContext& ctx) {
  if (have_share_ && !tracker_.complete()) divide(ctx, "member back");
}

void CoverGroupTask::gcs_back(GroupContext& ctx) {
  // The GCS judges coverage from the robots' cells in the clocks it heard: the share's cells
  // covered while it was down, and the group's done, again.
  if (!have_share_) return;
  const std::vector<std::uint8_t> left = tracker_.uncovered();
  std::vector<Cell> covered;
  const auto& target = tracker_.target();
  for (std::size_t i = 0; i < target.size(); ++i) {
    if (target[i] && !left[i]) covered.push_back(ctx.map.group().cell_of(static_cast<int>(i)));
  }
  task::Report report;
  report.state = task::GroupState::Working;
  report.cells = std::move(covered);
  ctx.out.report(report);
  reported_done_ = false;
}

void CoverGroupTask::step(GroupContext& ctx) {
  tick_ = ctx.clock.tick;
  if (!have_share_) return;
  for (const task::RobotAt& s : ctx.clock.robots) tracker_.visit(s.cell);
  if (tracker_.complete()) {
    if (!reported_done_) {
      task::Report report;
      report.state = task::GroupState::Done;  // the share is covered
      ctx.out.report(report);
      reported_done_ = true;
    }
    return;
  }
  const std::vector<int> living = ctx.living();
  // A robot whose route has not advanced for stall_ticks: another robot is in its way (robots of
  // other groups cross the share, and regions touch). Go around it.
  std::vector<Cell> others;
  for (const task::RobotAt& s : ctx.clock.robots) others.push_back(s.cell);
  bool idle = true;
  for (int i : living) {
    Robot& r = robots_[static_cast<std::size_t>(i)];
    if (!r.busy()) continue;
    idle = false;
    if (tick_ < r.moved_tick + config_.stall_ticks()) continue;
    std::vector<Cell> blocked;
    const Cell here = ctx.cell_of(i);
    for (const Cell& c : others) {
      if (c != here) blocked.push_back(c);
    }
    std::vector<Cell> around = planner::detour(known_, r.route, r.step, blocked);
    const bool same = around.size() + r.step == r.route.size() &&
                      std::equal(around.begin(), around.end(), r.route.begin() + static_cast<std::ptrdiff_t>(r.step));
    if (!around.empty() && around.front() == here && !same) {
      ++detours_;
      send(ctx, i, std::move(around));
    } else if (r.step < r.route.size() && r.route[r.step] == here) {
      // No way around: the robot is in a conflict over a free cell (two robots, often of different
      // groups, meaning to enter it each tick; the simulator refuses both). Back off for a number
      // of ticks unique to the robot, so that one of them goes first.
      const int backoff = 1 + static_cast<int>(ctx.topology().robot(group_, i));
      std::vector<Cell> wait(static_cast<std::size_t>(backoff), here);
      wait.insert(wait.end(), r.route.begin() + static_cast<std::ptrdiff_t>(r.step), r.route.end());
      ++backoffs_;
      send(ctx, i, std::move(wait));
    } else {
      r.moved_tick = tick_;  // nothing better now; look again later
    }
  }
  // Every route ended with cells uncovered (missed by a failed division, or pieces cut off): the
  // nearest robots cover what is left.
  if (idle && !living.empty() && tick_ >= last_leftover_tick_ + config_.stall_ticks()) {
    last_leftover_tick_ = tick_;
    std::vector<Cell> from;
    for (int i : living) from.push_back(ctx.cell_of(i));
    const auto routes = planner::cover_leftovers(known_, tracker_.uncovered(), from);
    bool any = false;
    for (std::size_t k = 0; k < living.size(); ++k) {
      if (routes[k].size() <= 1) continue;
      send(ctx, living[k], routes[k]);
      any = true;
    }
    if (any) ++leftover_rounds_;
  }
}

nlohmann::json CoverGroupTask::numbers() const {
  return {{"share_cells", tracker_.target_cells()},
          {"divisions", divisions_},
          {"detours", detours_},
          {"backoffs", backoffs_},
          {"leftover_rounds", leftover_rounds_}};
}

}  // namespace swarm::leader
