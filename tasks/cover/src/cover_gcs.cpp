#include "swarm/tasks/cover/cover_gcs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <compare>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "swarm/config/task_config.hpp"
#include "swarm/planner/coverage/cover_tours.hpp"
#include "swarm/planner/coverage/region_graph.hpp"
#include "swarm/planner/grid/deadline.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm/planner/traffic/rehearsal.hpp"
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

namespace {

// Between the last route's end and the robots' first move on a second plan: the Done reports'
// way to the GCS and the new routes' way to the members, 2 ticks each with exact links.
constexpr int kSecondPlanTicks = 4;

// What a division costs to drive, compared in this order: the ticks its drive is estimated to take
// (a rehearsal of the traffic layer's plan for it, driven by the plan's dependencies, each robot
// setting off the tick after the robots it waits on have gone, docs/traffic.md; the mean over
// draws of the routes' arrivals, which link jitter and loss spread; and when its routes miss cells
// to cover, the second division and plan those wait for once every route is driven:
// kSecondPlanTicks, the way from the nearest route's end to the farthest of them and an even share
// of them per robot, which a second plan cannot beat); the cells
// missed; the steps the plan takes (the longest route plus whatever the robots wait or step aside
// for one another); its moves onto cells of another group's part; the moves of all its routes.
// Its longest route and the estimate's range over the draws are kept to show (they break the
// last ties too: ordered, so that the ranking is total and deterministic).
struct DriveCost {
  double driven = 0;
  std::size_t missed = 0;
  int planned = 0;
  std::size_t foreign = 0, all = 0, longest = 0;
  int fastest = 0, slowest = 0;  // the drive's estimate in the draw of arrivals it is fastest / slowest in
  auto operator<=>(const DriveCost&) const = default;
};

DriveCost drive_cost(const std::vector<std::vector<Cell>>& routes, const std::vector<int>& group_of_cell,
                     const std::vector<std::uint8_t>& cells, const comm::Topology& t, const planner::OccupancyGrid& map,
                     const std::function<CoverGcsTask::Rehearsed(const std::vector<std::vector<Cell>>&)>& rehearse) {
  DriveCost c;
  std::vector<std::uint8_t> passed(map.size(), 0);
  for (const auto& route : routes) {
    for (const Cell& cell : route) passed[static_cast<std::size_t>(map.index(cell))] = 1;
  }
  std::vector<std::size_t> missed;  // cells to cover that no route passes
  for (std::size_t i = 0; i < cells.size() && i < passed.size(); ++i) {
    if (cells[i] && !passed[i]) missed.push_back(i);
  }
  c.missed = missed.size();
  for (std::size_t r = 0; r < routes.size(); ++r) {
    const std::size_t moves = routes[r].empty() ? 0 : routes[r].size() - 1;
    c.longest = std::max(c.longest, moves);
    c.all += moves;
    const int own = t.group_of(static_cast<comm::AgentId>(r));
    for (std::size_t k = 1; k < routes[r].size(); ++k) {
      const int g = group_of_cell[static_cast<std::size_t>(map.index(routes[r][k]))];
      c.foreign += g >= 0 && g != own ? 1 : 0;
    }
  }
  const CoverGcsTask::Rehearsed r = rehearse(routes);
  c.driven = r.mean_ticks;
  c.fastest = r.fastest;
  c.slowest = r.slowest;
  c.planned = r.planned;
  if (c.missed > 0) {
    std::vector<Cell> ends;
    for (const auto& route : routes) {
      if (!route.empty()) ends.push_back(route.back());
    }
    const std::vector<int> moves = planner::step_distances(map, ends, planner::MotionModel::four());
    int farthest = 0;
    for (const std::size_t i : missed) farthest = std::max(farthest, moves[i]);
    const std::size_t robots = std::max<std::size_t>(ends.size(), 1);
    const int share = static_cast<int>((missed.size() + robots - 1) / robots);
    const int second_plan = kSecondPlanTicks + farthest + share;
    c.driven += second_plan;
    c.fastest += second_plan;
    c.slowest += second_plan;
  }
  return c;
}

nlohmann::json to_json(const DriveCost& c) {
  return {{"cells_missed", c.missed},
          {"estimated_ticks", std::round(c.driven * 10) / 10},
          {"estimated_ticks_range", {c.fastest, c.slowest}},
          {"planned_steps", c.planned},
          {"moves_in_other_groups_parts", c.foreign},
          {"route_moves", c.all},
          {"longest_route_moves", c.longest}};
}

// Per grid cell, the group of the robot (or leader) whose DARP agent it went to; -1: none.
std::vector<int> groups_of_cells(const planner::CoverRoutes& plan, const std::vector<int>& agents,
                                 const comm::Topology& t, std::size_t cells) {
  std::vector<int> group_of_agent;  // the agents DARP started, in order
  for (std::size_t a = 0; a < agents.size(); ++a) {
    if (plan.starts[a].x >= 0) group_of_agent.push_back(t.group_of(static_cast<comm::AgentId>(agents[a])));
  }
  std::vector<int> out(cells, -1);
  for (std::size_t i = 0; i < out.size() && i < plan.darp.assignment.size(); ++i) {
    const int k = plan.darp.assignment[i];
    if (k >= 0) out[i] = group_of_agent[static_cast<std::size_t>(k)];
  }
  return out;
}

}  // namespace

void CoverGcsTask::Division::describe(const planner::CoverRoutes& plan, const char* agents) {
  json = tasks::division_json(plan);
  json["agents"] = agents;
  char line[160];
  std::snprintf(line, sizeof line, "among %s: %s (by %s) after %d iterations, %.3f s", agents,
                planner::to_string(plan.darp.status), plan.darp.finished_by.c_str(), plan.darp.iterations,
                plan.seconds_division);
  summary = line;
}

CoverGcsTask::Division CoverGcsTask::divide_among_groups(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                         const std::vector<int>& robots,
                                                         const std::function<bool()>& stop) const {
  const comm::Topology& t = ctx.setup.topology;
  const std::vector<int> groups = living_groups(ctx);
  // The agents DARP divides among: the living leaders, portions by living group size.
  std::vector<int> leaders;
  std::vector<double> weights;
  for (int g : groups) {
    int living = 0;
    for (int i = 0; i < t.robots_per_group(); ++i) living += ctx.alive(t.robot(g, i)) ? 1 : 0;
    leaders.push_back(ctx.leader_of(g));
    weights.push_back(living);
  }
  std::vector<Cell> at;
  for (int r : leaders) at.push_back(ctx.cell_of(r));
  planner::CoverRoutesConfig cfg = tasks::cover_routes_config(config_, ctx.setup.world.scenario.seed(), seq_);
  cfg.routes = false;
  const planner::CoverRoutes plan = planner::divide_and_route(known_, cells, at, weights, cfg, stop);

  // Each group's share: the cells DARP gave its leader.
  Division out;
  out.group_of_cell = groups_of_cells(plan, leaders, t, known_.size());
  std::vector<std::vector<std::uint8_t>> share(static_cast<std::size_t>(t.groups()),
                                               std::vector<std::uint8_t>(known_.size(), 0));
  for (std::size_t i = 0; i < out.group_of_cell.size(); ++i) {
    if (out.group_of_cell[i] >= 0) share[static_cast<std::size_t>(out.group_of_cell[i])][i] = 1;
  }
  out.routes.resize(static_cast<std::size_t>(t.robots()));
  out.region_cells.assign(static_cast<std::size_t>(t.robots()), 0);
  nlohmann::json within_groups = nlohmann::json::array();
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
    for (std::size_t k = 0; k < members.size(); ++k) {
      out.routes[static_cast<std::size_t>(members[k])] = sub.routes[k];
      out.region_cells[static_cast<std::size_t>(members[k])] = sub.region_cells[k];
    }
    nlohmann::json entry = tasks::division_json(sub);
    entry["group"] = g;
    entry["robots"] = members;
    within_groups.push_back(std::move(entry));
  }
  nlohmann::json cells_per_group = nlohmann::json::array();
  for (int g = 0; g < t.groups(); ++g) {
    int n = 0;
    for (std::uint8_t v : share[static_cast<std::size_t>(g)]) n += v;
    cells_per_group.push_back(n);
  }
  out.describe(plan, "leaders");
  out.json["cells_per_group"] = cells_per_group;
  if (!within_groups.empty()) out.json["within_groups"] = std::move(within_groups);
  return out;
}

CoverGcsTask::Division CoverGcsTask::divide_among_robots(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                         const std::vector<int>& robots,
                                                         const std::function<bool()>& stop) const {
  const comm::Topology& t = ctx.setup.topology;
  std::vector<Cell> at;
  for (int r : robots) at.push_back(ctx.cell_of(r));
  planner::CoverRoutesConfig cfg = tasks::cover_routes_config(config_, ctx.setup.world.scenario.seed(), seq_);
  cfg.routes = true;
  const planner::CoverRoutes plan =
      planner::divide_and_route(known_, cells, at, std::vector<double>(robots.size(), 1.0), cfg, stop);
  Division out;
  out.group_of_cell = groups_of_cells(plan, robots, t, known_.size());
  out.routes.resize(static_cast<std::size_t>(t.robots()));
  out.region_cells.assign(static_cast<std::size_t>(t.robots()), 0);
  for (std::size_t a = 0; a < robots.size(); ++a) {
    out.routes[static_cast<std::size_t>(robots[a])] = plan.routes[a];
    out.region_cells[static_cast<std::size_t>(robots[a])] = plan.region_cells[a];
  }
  out.describe(plan, "robots");
  return out;
}

CoverGcsTask::Division CoverGcsTask::divide_by_tours(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                     const std::vector<int>& robots,
                                                     const std::function<bool()>& stop, std::uint32_t variant) const {
  const comm::Topology& t = ctx.setup.topology;
  std::vector<Cell> at;
  for (int r : robots) at.push_back(ctx.cell_of(r));
  planner::CoverToursConfig cfg;
  cfg.max_targets = config_.tour_candidate_cells();
  cfg.seed = planner::mix_seed(ctx.setup.world.scenario.seed(), seq_ + (std::uint64_t{variant} << 32));
  // Every other seed plans the members' later start in: their routes shorter by it, for the
  // mean arrival, then for the latest.
  if (variant % 2 == 1) {
    const std::vector<int> arrivals = route_arrivals(ctx, variant % 4 == 3);
    for (const int r : robots) cfg.starts.push_back(arrivals[static_cast<std::size_t>(r)]);
  }
  const planner::CoverTours tours = planner::cover_tours(known_, cells, at, cfg, stop);
  Division out;
  if (!tours.solved) return out;
  out.routes.resize(static_cast<std::size_t>(t.robots()));
  out.region_cells.assign(static_cast<std::size_t>(t.robots()), 0);
  out.group_of_cell.assign(known_.size(), -1);
  for (std::size_t i = 0; i < tours.owner.size(); ++i) {
    const int k = tours.owner[i];
    if (k >= 0) out.group_of_cell[i] = t.group_of(static_cast<comm::AgentId>(robots[static_cast<std::size_t>(k)]));
  }
  std::vector<int> cells_per_robot;
  for (std::size_t a = 0; a < robots.size(); ++a) {
    out.routes[static_cast<std::size_t>(robots[a])] = tours.routes[a];
    out.region_cells[static_cast<std::size_t>(robots[a])] = tours.region_cells[a];
    cells_per_robot.push_back(tours.region_cells[a]);
  }
  out.json = {{"agents", "robots"},
              {"method", "tours"},
              {"targets", tours.targets},
              {"unreachable_cells", tours.unreachable},
              {"improvements", tours.improvements},
              {"stopped", tours.stopped},
              {"cells", cells_per_robot},
              {"seconds", tours.seconds}};
  char line[160];
  std::snprintf(line, sizeof line, "as tours among robots: %zu cells, longest route %zu moves, %.3f s", tours.targets,
                planner::longest_moves(tours.routes), tours.seconds);
  out.summary = line;
  return out;
}

std::vector<int> CoverGcsTask::route_arrivals(const GcsContext& ctx, bool latest) {
  // A leader drives its own robot from the tick the routes reach it; a member's route has the
  // member<->leader link still to go: a tick, and the link's delay and jitter in lockstep.
  const auto& link = ctx.setup.world.scenario.links().member_leader();
  const int member = 1 + static_cast<int>(link.delay_ticks() + (latest ? link.jitter_ticks() : link.jitter_ticks() / 2));
  std::vector<int> out(static_cast<std::size_t>(ctx.setup.topology.robots()), member);
  for (int g = 0; g < ctx.setup.topology.groups(); ++g) {
    const int leader = ctx.leader_of(g);
    if (leader >= 0 && leader < static_cast<int>(out.size())) out[static_cast<std::size_t>(leader)] = 0;
  }
  return out;
}

std::vector<std::vector<int>> CoverGcsTask::arrival_draws(const GcsContext& ctx) const {
  // From the GCS's order on: the order's way to each leader (its jitter is one draw for all
  // leaders, so only a loss sets one apart), a member's route's way from its leader, and every
  // robot's command's way to the simulator (a jitter draw and losses of its own), each loss
  // costing the link's retransmission.
  const auto& links = ctx.setup.world.scenario.links();
  const auto& order = links.leader_gcs();
  const auto& route = links.member_leader();
  const auto& command = links.sim_robot();
  const comm::Topology& t = ctx.setup.topology;
  const bool spread = route.jitter_ticks() > 0 || command.jitter_ticks() > 0 || order.loss() > 0 || route.loss() > 0 ||
                      command.loss() > 0;
  planner::Rng rng(planner::mix_seed(ctx.setup.world.scenario.seed(), phase_, seq_, 0xa771ULL));
  const auto retransmissions = [&rng](const swarm::scenario::Link& link) {
    int ticks = 0;
    while (link.loss() > 0 && rng.uniform01() < link.loss()) ticks += static_cast<int>(link.retransmit_ticks());
    return ticks;
  };
  const auto jitter = [&rng](const swarm::scenario::Link& link) {
    return static_cast<int>(rng.below(std::uint64_t{link.jitter_ticks()} + 1));
  };
  std::vector<std::vector<int>> draws(spread ? kArrivalDraws : 1);
  for (std::vector<int>& at : draws) {
    at.assign(static_cast<std::size_t>(t.robots()), 0);
    for (int g = 0; g < t.groups(); ++g) {
      const int leader = ctx.leader_of(g);
      const int group_order = spread ? retransmissions(order) : 0;
      for (int i = 0; i < t.robots_per_group(); ++i) {
        const int r = t.robot(g, i);
        int ticks = group_order;
        if (r != leader) ticks += 1 + static_cast<int>(route.delay_ticks()) + (spread ? jitter(route) + retransmissions(route) : 0);
        if (spread) ticks += jitter(command) + retransmissions(command);
        at[static_cast<std::size_t>(r)] = ticks;
      }
    }
  }
  return draws;
}

CoverGcsTask::Rehearsed CoverGcsTask::rehearsed_ticks(const GcsContext& ctx, const std::vector<std::vector<Cell>>& routes,
                                                      const std::vector<int>& robots) const {
  // As the layer plans (tasks/mapf/mapf_windows.cpp): every route cell a goal, the same windows and seed.
  std::size_t longest = 0;
  for (const int r : robots) longest = std::max(longest, routes[static_cast<std::size_t>(r)].size());
  const int window = static_cast<int>(config_.traffic_window_steps());
  const planner::traffic::Rehearsal plan =
      planner::traffic::rehearse(layer_map(ctx, known_), planner::MotionModel::four(), layer_agents(ctx, robots, routes), window,
                                 traffic_config(ctx.setup.world.scenario.seed(), phase_), 4 * static_cast<int>(longest) + 4 * window);
  if (!plan.finished) return {static_cast<double>(plan.makespan), plan.makespan, plan.makespan, plan.makespan};
  // A dependency's cost, from the robot waited for leaving to the other entering: one tick, the
  // step itself. Robot positions are shared in real time, and the waiting robot's member sees the
  // cell left in that tick's clock and sets off (its release's watch, tasks/mapf/mapf_leader.hpp),
  // whatever the group and whatever the member<->leader link's delay.
  const auto lag = [](int, int) { return 1; };
  std::vector<int> ticks;
  try {
    ticks = planner::traffic::driven_ticks_per_start(plan.paths, lag, arrival_draws(ctx));
  } catch (const std::invalid_argument&) {
    return {static_cast<double>(plan.makespan), plan.makespan, plan.makespan, plan.makespan};  // never: the layer's plans are free of conflicts
  }
  Rehearsed out{0, *std::min_element(ticks.begin(), ticks.end()), *std::max_element(ticks.begin(), ticks.end()), plan.makespan};
  for (const int k : ticks) out.mean_ticks += k;
  out.mean_ticks /= static_cast<double>(ticks.size());
  return out;
}

std::vector<std::vector<Cell>> CoverGcsTask::divide(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                    const char* why, const std::vector<int>& robots) {
  const auto deadline = planner::deadline_after(config_.darp_time_limit_s(), std::chrono::steady_clock::now());
  const std::function<bool()> stop = [deadline] { return std::chrono::steady_clock::now() > deadline; };
  ++seq_;
  // The candidates, in the order ties go: the groups' division (hierarchical), the division among
  // all robots (flat, or hierarchical with flat_candidate: a share grown from the leader's cell
  // can lie far from the group's other robots, while this one starts every region at its robot),
  // the tours (few cells left; one from each of `tour_seeds` seeds, every other one planning the
  // members' later start in). The one cheapest to drive (DriveCost) is driven.
  // When the cells lie in pieces (robots standing in a one-cell door split off the room behind
  // it), a division of them as they lie may give a piece to a robot whose route never leaves its
  // own, and those cells wait for a second plan; each division is made of them joined into one
  // piece too ("leaders-joined", "robots-joined": the joining cells are revisits, not targets),
  // and the costs, which count only the cells to cover, choose.
  int pieces = 0;
  const std::vector<std::uint8_t> joined = planner::join_pieces(known_, cells, &pieces);
  std::vector<std::pair<std::string, Division>> candidates;
  if (config_.hierarchical()) {
    candidates.emplace_back("leaders", divide_among_groups(ctx, cells, robots, stop));
    if (pieces > 1) candidates.emplace_back("leaders-joined", divide_among_groups(ctx, joined, robots, stop));
  }
  if (!config_.hierarchical() || config_.flat_candidate()) {
    candidates.emplace_back("robots", divide_among_robots(ctx, cells, robots, stop));
    if (pieces > 1) candidates.emplace_back("robots-joined", divide_among_robots(ctx, joined, robots, stop));
  }
  // The tours from each seed are a candidate each: "tours", then "tours-2", "tours-3", ...
  for (std::uint32_t v = 0; config_.tour_candidate_cells() > 0 && v < std::max(1u, config_.tour_seeds()); ++v) {
    Division tours = divide_by_tours(ctx, cells, robots, stop, v);
    if (tours.json.is_null()) break;  // too many cells: so for every seed
    candidates.emplace_back(v == 0 ? std::string("tours") : "tours-" + std::to_string(v + 1), std::move(tours));
  }
  std::size_t best = 0;
  nlohmann::json compared = nlohmann::json::object();
  std::vector<DriveCost> costs;
  const auto rehearse = [&](const std::vector<std::vector<Cell>>& routes) { return rehearsed_ticks(ctx, routes, robots); };
  for (const auto& [name, d] : candidates) {
    costs.push_back(drive_cost(d.routes, d.group_of_cell, cells, ctx.setup.topology, known_, rehearse));
    compared[name] = to_json(costs.back());
    if (costs.back() < costs[best]) best = costs.size() - 1;
  }
  Division chosen = std::move(candidates[best].second);
  chosen.json["driven"] = candidates[best].first;
  if (candidates.size() > 1) chosen.json["compared"] = std::move(compared);
  std::size_t goals = 0;
  for (std::size_t r = 0; r < chosen.routes.size(); ++r) {
    if (chosen.routes[r].empty()) continue;
    goals += chosen.routes[r].size();
    ctx.record.append(route_frame(ctx.tick(), phase_, static_cast<int>(r), chosen.routes[r],
                                  static_cast<std::uint32_t>(chosen.region_cells[r])));
  }
  nothing_to_drive_ = goals == 0 && !tracker_.complete();
  chosen.json["tick"] = ctx.tick();
  chosen.json["why"] = why;
  chosen.json["pieces"] = pieces;
  std::size_t joining = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) joining += joined[i] && !cells[i] ? 1 : 0;
  chosen.json["joining_cells"] = joining;
  divisions_.push_back(std::move(chosen.json));
  std::fprintf(stderr, "gcs: cover division (%s) at tick %u: %s\n", why, ctx.tick(), chosen.summary.c_str());
  return chosen.routes;
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
