#include "swarm/tasks/mapf/mapf_gcs.hpp"

#include <any>
#include <algorithm>
#include <cstdio>
#include <utility>

#include "swarm/comm/link.hpp"
#include "swarm/config/task_config.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::gcs {

using planner::Cell;

MapfGcsTask::MapfGcsTask(const swarm::scenario::Mapf& config, std::uint32_t phase, bool map_given, GoalPicker goals)
    : config_(config), phase_(phase), map_given_(map_given), pick_goals_(std::move(goals)) {}

std::vector<Cell> MapfGcsTask::random_goals(const GcsContext& ctx) const {
  // A distinct free cell per robot, reachable from where it stands, drawn from the run's seed.
  const comm::Topology& t = ctx.setup.topology;
  planner::Rng rng(planner::mix_seed(ctx.setup.world.scenario.seed(), 9000 + phase_));
  std::vector<std::uint8_t> taken(known_.size(), 0);
  std::vector<Cell> goals(static_cast<std::size_t>(t.robots()), Cell{-1, -1});
  for (int r = 0; r < t.robots(); ++r) taken[known_.index(ctx.cell_of(r))] = ctx.alive(r) ? 0 : 1;
  for (int r = 0; r < t.robots(); ++r) {
    if (!ctx.alive(r)) continue;
    const auto reach = planner::reachable_mask(known_, {ctx.cell_of(r)}, planner::MotionModel::four());
    std::vector<int> options;
    for (std::size_t i = 0; i < reach.size(); ++i) {
      if (reach[i] && !taken[i]) options.push_back(static_cast<int>(i));
    }
    if (options.empty()) continue;
    const int pick = options[rng.below(options.size())];
    taken[static_cast<std::size_t>(pick)] = 1;
    goals[static_cast<std::size_t>(r)] = known_.cell_of(pick);
  }
  return goals;
}

void MapfGcsTask::start(GcsContext& ctx) {
  known_ = map_given_ ? ctx.setup.given_map : ctx.fused.grid();
  start_tick_ = ctx.tick();
  winding_down_ = false;
  if (window_ > 0) {
    goals_.assign(static_cast<std::size_t>(ctx.setup.topology.robots()), Cell{-1, -1});
  } else if (!pick_goals_) {
    goals_ = std::any_cast<const std::vector<Cell>&>(ctx.setup.world.phase_data.at(phase_));
    if (goals_.empty()) goals_ = random_goals(ctx);
  }
  const auto groups = static_cast<std::size_t>(ctx.setup.topology.groups());
  group_in_plan_.assign(groups, false);
  group_done_.assign(groups, false);
  group_held_.assign(groups, false);
  // Every robot stands still (a phase after another starts so: gcs/gcs_node.hpp).
  plan(ctx, "start");
}

void MapfGcsTask::begin_plan(const GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  ++seq_;
  holding_ = false;
  std::fill(group_in_plan_.begin(), group_in_plan_.end(), false);
  std::fill(group_done_.begin(), group_done_.end(), false);
  std::fill(group_held_.begin(), group_held_.end(), false);
  for (int r : planned_) group_in_plan_[static_cast<std::size_t>(t.group_of(static_cast<comm::AgentId>(r)))] = true;
  plan_leaders_.clear();
  for (int g = 0; g < t.groups(); ++g) plan_leaders_.push_back(ctx.leader_of(g));
}

void MapfGcsTask::begin_chain(const GcsContext& ctx) {
  begin_plan(ctx);
  chain_first_ = seq_;
  relay_.clear();
}

void MapfGcsTask::plan(GcsContext& ctx, const char* why) {
  if (window_ > 0) {
    plan_window(ctx, why);
    return;
  }
  const comm::Topology& t = ctx.setup.topology;
  // Who is planned for: the living robots of groups whose leader lives, with a goal. Everyone else
  // stands where it is: an obstacle.
  planned_.clear();
  planner::mapf::Instance in;
  in.map = known_;
  const std::vector<int> may_move = MapfGcsTask::may_move(ctx);
  for (int r = 0; r < t.robots(); ++r) {
    if (!std::binary_search(may_move.begin(), may_move.end(), r)) in.map.set(ctx.cell_of(r), planner::CellState::Occupied);
  }
  if (pick_goals_) goals_ = pick_goals_(ctx, in.map, may_move);
  for (const int r : may_move) {
    if (goals_[static_cast<std::size_t>(r)].x >= 0) {
      planned_.push_back(r);
      in.starts.push_back(ctx.cell_of(r));
      in.goals.push_back(goals_[static_cast<std::size_t>(r)]);
    } else {
      in.map.set(ctx.cell_of(r), planner::CellState::Occupied);
    }
  }
  begin_chain(ctx);

  planner::mapf::SolverConfig solver = tasks::mapf_solver_config(config_, ctx.setup.world.scenario.seed());
  planner::mapf::Result res = planner::mapf::solve(in, solver, planner::mapf::StopCondition::after(config_.time_limit_s()));
  if (res.status == planner::mapf::Status::Timeout && solver.kind != planner::mapf::SolverKind::Lacam) {
    // A (bounded-)optimal search that runs out of time leaves nothing safe to drive; LaCAM is
    // complete and fast: it finds a plan, or proves there is none, within another such limit.
    note_plan(ctx, why, res);
    std::fprintf(stderr, "gcs: mapf plan timed out after %.3f s; trying LaCAM\n", res.seconds);
    solver.kind = planner::mapf::SolverKind::Lacam;
    res = planner::mapf::solve(in, solver, planner::mapf::StopCondition::after(config_.time_limit_s()));
    why = "LaCAM after a timeout";
  }
  note_plan(ctx, why, res);
  if (!have_first_) first_ = res;  // the plan the phase's planned numbers describe (after any fallback)
  have_first_ = true;
  failed_ = res.status != planner::mapf::Status::Solved;
  if (failed_) {
    // Nothing safe to drive, and planning the same instance again gives the same answer: the
    // phase is given up (given_up(); metrics.json says why).
    failure_ = std::string("no plan for ") + std::to_string(planned_.size()) + " robots (" + why +
               "): " + planner::mapf::to_string(res.status) + (res.message.empty() ? "" : ", " + res.message);
    return;
  }
  send_plan(ctx, res);
}

void MapfGcsTask::note_plan(GcsContext& ctx, const char* why, const planner::mapf::Result& res) {
  plans_.push_back({{"tick", ctx.tick()},
                    {"why", why},
                    {"robots", planned_.size()},
                    {"status", planner::mapf::to_string(res.status)},
                    {"seconds", res.seconds},
                    {"soc", res.soc},
                    {"makespan", res.makespan},
                    {"lower_bound", res.lower_bound},
                    {"conflicts", res.conflicts},
                    {"message", res.message}});
  std::fprintf(stderr, "gcs: mapf plan (%s) at tick %u for %zu robots: %s in %.3f s, soc %lld, makespan %d%s%s\n", why,
               ctx.tick(), planned_.size(), planner::mapf::to_string(res.status), res.seconds, res.soc, res.makespan,
               res.message.empty() ? "" : ": ", res.message.c_str());
}

void MapfGcsTask::send_plan(GcsContext& ctx, const planner::mapf::Result& res, std::optional<int> continues) {
  by_graph_ = config_.execution() != swarm::scenario::MAPF_EXECUTE_TIMED;
  if (!continues) {
    progress_.assign(res.paths.size(), 0);
    acted_.assign(res.paths.size(), 0);
    // A plan's first window is released whole (tasks/mapf/mapf_leader.hpp); a plan not made in
    // windows has no other.
    limit_ = planner::mapf::last_time(res.paths);
  }
  if (by_graph_) {
    // A grown plan keeps its steps' needs and its rotations' numbers (planner/mapf/adg.hpp).
    adg_ = planner::mapf::dependencies(res.paths);
    if (!continues) rotation_ordered_.clear();
    rotation_ordered_.resize(adg_.rotations.size(), false);
  }
  route_steps_ = 0;
  for (std::size_t k = 0; k < res.paths.size(); ++k) {
    const std::size_t cells = by_graph_ ? adg_.routes[k].size() : res.paths[k].size();
    route_steps_ += cells > 0 ? cells - 1 : 0;
  }
  task::Order o;
  o.group = task::kAllGroups;
  o.kind = task::OrderKind::Work;
  o.seq = seq_;
  if (continues) {
    o.values = {kContinues, static_cast<std::int32_t>(chain_first_), *continues};
  } else if (config_.execution() == swarm::scenario::MAPF_EXECUTE_TIMED) {
    // One start tick for every robot: late enough for the order to reach every leader and its
    // routes every member, with the configured delays, jitter and loss.
    o.values.push_back(static_cast<std::int32_t>(start_tick(ctx)));
  }
  const auto from = static_cast<std::ptrdiff_t>(continues.value_or(0));
  for (std::size_t k = 0; k < planned_.size(); ++k) {
    planner::mapf::Path path(res.paths[k].begin() + from, res.paths[k].end());
    o.routes.push_back({planned_[k], path, {}, {}});
    if (window_ > 0) add_acts(planned_[k], o.routes.back(), static_cast<int>(from));
    ctx.record.append(route_frame(ctx.tick(), phase_, planned_[k], path));
  }
  ctx.out.order(o);
}

std::uint32_t MapfGcsTask::start_tick(const GcsContext& ctx) const {
  // The order reaches the last leader by then, the routes it forwards at once the last member, and
  // each robot's command (sent at once, to set off in this tick) the simulator, lost transmissions
  // repeated: a robot that set off without the others would run into them.
  const comm::LinkTable& links = ctx.setup.links;
  const std::uint32_t at_leaders = comm::sure_arrival_tick(links[comm::LinkClass::LeaderGcs], ctx.tick());
  const std::uint32_t at_members = comm::sure_arrival_tick(links[comm::LinkClass::MemberLeader], at_leaders);
  return comm::sure_arrival_tick(links[comm::LinkClass::SimRobot], at_members);
}

void MapfGcsTask::order_rotations(GcsContext& ctx) {
  if (winding_down_) return;
  for (const int q : planner::mapf::ready_rotations(adg_, progress_)) {
    const auto qu = static_cast<std::size_t>(q);
    if (rotation_ordered_[qu]) continue;
    // Not past the limit: the plan may be cut there.
    const planner::mapf::Need& m = adg_.rotations[qu].front();
    if (static_cast<std::uint32_t>(adg_.planned_time[static_cast<std::size_t>(m.robot)][m.step]) > limit_) continue;
    rotation_ordered_[qu] = true;
    ++rotations_ordered_;
    const std::uint32_t at = start_tick(ctx);
    last_rotation_tick_ = std::max(last_rotation_tick_, at);
    send_order(ctx, task::OrderKind::Rotate, {static_cast<std::int32_t>(seq_), q, static_cast<std::int32_t>(at)});
  }
}

void MapfGcsTask::send_order(GcsContext& ctx, task::OrderKind kind, std::vector<std::int32_t> values) {
  task::Order o;
  o.group = task::kAllGroups;
  o.kind = kind;
  o.seq = seq_;
  o.values = std::move(values);
  ctx.out.order(o);
}

void MapfGcsTask::on_report(const task::Report& r, GcsContext& ctx) {
  const auto& v = r.values;
  if (!v.empty() && v[0] == kPickResults) {
    for (std::size_t i = 1; i + 3 < v.size();) {
      const auto n = static_cast<std::size_t>(std::max(v[i + 3], 0));
      if (i + 4 + n > v.size()) break;  // malformed: the rest is dropped
      std::vector<std::uint32_t> objects;
      for (std::size_t j = 0; j < n; ++j) objects.push_back(static_cast<std::uint32_t>(v[i + 4 + j]));
      const bool robot = v[i] >= 0 && v[i] < ctx.setup.topology.robots();  // a report may be hostile
      if (picked_ && robot) picked_(v[i], planner::Cell{v[i + 1], v[i + 2]}, objects);
      i += 4 + n;
    }
    return;
  }
  // Progress along any window of the current plan counts along the plan as it is now.
  const bool in_plan = !v.empty() && static_cast<std::uint32_t>(v[0]) >= chain_first_ &&
                       static_cast<std::uint32_t>(v[0]) <= seq_;
  if (in_plan && v.size() % 4 == 1) {
    relay_.insert(relay_.end(), v.begin() + 1, v.end());
    for (std::size_t i = 1; i + 3 < v.size(); i += 4) {
      const auto it = std::find(planned_.begin(), planned_.end(), v[i]);
      if (it == planned_.end()) continue;
      const auto k = static_cast<std::size_t>(it - planned_.begin());
      progress_[k] = std::max(progress_[k], static_cast<std::uint32_t>(v[i + 1]));
      acted_[k] = std::max(acted_[k], static_cast<std::uint32_t>(v[i + 3]));
    }
  }
  if (r.group >= group_done_.size() || v.empty() || static_cast<std::uint32_t>(v[0]) != seq_) return;
  if (r.state == task::GroupState::Done) group_done_[r.group] = true;
  if (r.state == task::GroupState::Held) group_held_[r.group] = true;
}

void MapfGcsTask::step(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  const bool raised = window_ > 0 && raise_limit(ctx);
  if (!relay_.empty() || raised) {
    std::vector<std::int32_t> values{static_cast<std::int32_t>(seq_), static_cast<std::int32_t>(limit_)};
    values.insert(values.end(), relay_.begin(), relay_.end());
    relay_.clear();
    send_order(ctx, task::OrderKind::Progress, std::move(values));
  }
  // A planned robot lost (or its group's leader): the others may wait for it for ever. Hold, and
  // plan again once every group stands still.
  // A group whose leader changed (a standby took over, leader/leader_node.hpp) is held too: the new
  // leader stops its robots where they stand and reports them held (tasks/mapf/mapf_leader.hpp).
  bool lost = false;
  for (int r : planned_) {
    const int g = t.group_of(static_cast<comm::AgentId>(r));
    lost = lost || !ctx.alive(r) || !ctx.alive(ctx.leader_of(g)) ||
           ctx.leader_of(g) != plan_leaders_[static_cast<std::size_t>(g)];
  }
  if (by_graph_ && !holding_ && !failed_ && !lost) order_rotations(ctx);
  arrived_ = 0;
  for (int r : planned_) arrived_ += ctx.alive(r) && ctx.cell_of(r) == goals_[static_cast<std::size_t>(r)] ? 1 : 0;
  if (failed_) return;
  bool all_done = true, all_held = true;
  for (int g = 0; g < t.groups(); ++g) {
    if (!group_in_plan_[static_cast<std::size_t>(g)] || !ctx.alive(ctx.leader_of(g))) continue;
    all_done = all_done && group_done_[static_cast<std::size_t>(g)];
    all_held = all_held && (group_held_[static_cast<std::size_t>(g)] || group_done_[static_cast<std::size_t>(g)]);
  }
  if (lost && !holding_ && !all_done && !rotating(ctx.tick())) {
    holding_ = true;
    send_order(ctx, task::OrderKind::Hold, {static_cast<std::int32_t>(seq_)});
    std::fprintf(stderr, "gcs: mapf: a planned robot was lost at tick %u; holding plan %u\n", ctx.tick(), seq_);
    return;
  }
  if (holding_ && all_held) {
    if (window_ > 0) credit_window(ctx, true);
    const char* why = hold_why_ != nullptr ? hold_why_ : "robot lost";
    hold_why_ = nullptr;
    plan(ctx, why);
    return;
  }
  if (window_ > 0) {
    if (!holding_ && !complete_) credit_window(ctx, false);  // the stops reported passed, at once
    cut_for_repick(ctx);
    if (!all_done && time_to_extend(ctx)) extend_window(ctx);
    if (!holding_ && all_done && !complete_) window_done(ctx);
    return;
  }
  complete_ = !holding_ && all_done;
}

ProgressLine MapfGcsTask::progress(const GcsContext&) const {
  char detail[96];
  if (window_ > 0) {
    std::size_t left = 0;
    for (const auto& seq : sequences_) left += seq.size();
    std::snprintf(detail, sizeof detail, "goals left %zu  window %llu%s", left,
                  static_cast<unsigned long long>(windows_),
                  failed_ ? " (failed)" : holding_ ? " (holding)" : "");
    const double total = static_cast<double>(left + goals_done_);
    return {"goals", total > 0 ? static_cast<double>(goals_done_) / total : 0.0, detail};
  }
  std::snprintf(detail, sizeof detail, "at goal %d/%zu  plan %u%s", arrived_, planned_.size(), seq_,
                failed_ ? " (failed)" : holding_ ? " (holding)" : "");
  // How much of the plan's routes the robots have driven (as reported): it grows on every move, where
  // the robots at their goals grow only at the end of a long plan (a stall is judged from it).
  std::uint64_t driven = 0;
  for (const std::uint32_t p : progress_) driven += p;
  return {"driven", route_steps_ == 0 ? 1.0 : std::min(1.0, static_cast<double>(driven) / static_cast<double>(route_steps_)),
          detail};
}

nlohmann::json MapfGcsTask::numbers() const {
  if (window_ > 0) {
    return {{"execution", swarm::scenario::MapfExecution_Name(config_.execution())},
            {"window_steps", window_},
            {"windows", windows_},
            {"windows_continued", windows_continued_},
            {"repicks_continued", repicks_continued_},
            {"repicks_held", repicks_held_},
            {"repicks_cut", plans_cut_},
            {"steps_cut", steps_cut_},
            {"goals_done", goals_done_},
            {"goals_skipped", goals_skipped_},
            {"longest_wait_steps", traffic_ ? traffic_->longest_wait() : 0},
            {"rescues", traffic_ ? traffic_->rescues() : 0},
            {"rescues_failed", traffic_ ? traffic_->rescues_failed() : 0},
            {"rotations_ordered", rotations_ordered_},
            {"plans", plans_}};
  }
  return {{"solver", swarm::scenario::MapfSolver_Name(config_.solver())},
          {"execution", swarm::scenario::MapfExecution_Name(config_.execution())},
          {"map_given", map_given_},
          {"robots_planned", planned_.size()},
          {"robots_at_goal", arrived_},
          {"planned_makespan", first_.makespan},
          {"planned_soc", first_.soc},
          {"lower_bound", first_.lower_bound},
          {"solver_status", planner::mapf::to_string(first_.status)},
          {"solver_seconds", first_.seconds},
          {"rotations_ordered", rotations_ordered_},
          {"plans", plans_}};
}

}  // namespace swarm::gcs
