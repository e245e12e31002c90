// MapfGcsTask's lifelong mode, the traffic layer (tasks/mapf/mapf_gcs.hpp, docs/traffic.md):
// windows of the traffic planner, driven as plans, and the stops they get each robot past.
#include <algorithm>
#include <cstdio>
#include <string>
#include <optional>
#include <tuple>
#include <utility>

#include "swarm/config/task_config.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"

namespace swarm::gcs {

namespace {
// Windows in a row in which no robot reached a goal or moved before a lifelong phase is given up.
constexpr int kIdleWindowsLimit = 8;
constexpr const char* kNextWindow = "window";
}  // namespace

planner::traffic::Config traffic_config(std::uint64_t seed, std::uint32_t phase) {
  return planner::traffic::Config{planner::mix_seed({seed, 9100 + std::uint64_t{phase}})};
}

planner::OccupancyGrid layer_map(const GcsContext& ctx, planner::OccupancyGrid known) {
  for (int r = 0; r < ctx.setup.topology.robots(); ++r) known.set(ctx.cell_of(r), planner::CellState::Free);
  return known;
}

std::vector<planner::traffic::Agent> layer_agents(const GcsContext& ctx, const std::vector<int>& moving,
                                                  const std::vector<std::vector<planner::Cell>>& goals) {
  std::vector<planner::traffic::Agent> agents(static_cast<std::size_t>(ctx.setup.topology.robots()));
  for (std::size_t r = 0; r < agents.size(); ++r) {
    agents[r].at = ctx.cell_of(static_cast<int>(r));
    agents[r].fixed = true;
  }
  for (const int r : moving) {
    auto& agent = agents[static_cast<std::size_t>(r)];
    agent.fixed = false;
    agent.goals = goals[static_cast<std::size_t>(r)];
  }
  return agents;
}

MapfGcsTask::MapfGcsTask(const swarm::scenario::Mapf& config, std::uint32_t phase, bool map_given, Lifelong lifelong)
    : config_(config),
      phase_(phase),
      map_given_(map_given),
      pick_routes_(std::move(lifelong.routes)),
      stop_done_(std::move(lifelong.done)),
      picked_(std::move(lifelong.picked)),
      window_(lifelong.window),
      map_grows_(lifelong.map_grows),
      motion_(lifelong.motion) {}

std::vector<std::vector<MapfGcsTask::Stop>> MapfGcsTask::passing(const std::vector<std::vector<planner::Cell>>& routes) {
  std::vector<std::vector<Stop>> out(routes.size());
  for (std::size_t r = 0; r < routes.size(); ++r) {
    for (const planner::Cell c : routes[r]) out[r].push_back({c, Stop::Act::kNone});
  }
  return out;
}

void MapfGcsTask::plan_window(GcsContext& ctx, const char* why) {
  const comm::Topology& t = ctx.setup.topology;
  const bool next = std::string(why) == kNextWindow;
  // Everyone but the living robots of led groups stands where it is: an obstacle to plan round.
  const std::vector<int> may_move = MapfGcsTask::may_move(ctx);
  if (map_grows_) known_ = ctx.fused.grid();
  if (!next) {
    repick_ = nullptr;
    sequences_ = pick_routes_(ctx, known_, may_move, why);
    sequences_.resize(static_cast<std::size_t>(t.robots()));
  }
  if (!traffic_ || map_grows_) {
    planner::OccupancyGrid map = layer_map(ctx, known_);
    if (traffic_) {
      traffic_->set_map(map);
    } else {
      traffic_ = std::make_unique<planner::traffic::Planner>(
          std::move(map), motion_,
          traffic_config(ctx.setup.world.scenario.seed(), phase_));
    }
  }
  std::vector<std::vector<planner::Cell>> goals(sequences_.size());
  for (const int r : may_move) {
    for (const Stop& s : sequences_[static_cast<std::size_t>(r)]) goals[static_cast<std::size_t>(r)].push_back(s.cell);
  }
  planner::traffic::Window w;
  try {
    w = traffic_->plan(layer_agents(ctx, may_move, goals), window_);
  } catch (const std::invalid_argument& e) {
    failed_ = true;
    failure_ = std::string("no traffic window (") + why + "): " + e.what();
    return;
  }
  planned_ = may_move;
  begin_chain(ctx);
  no_continuation_ = false;
  window_reached_.assign(static_cast<std::size_t>(t.robots()), {});
  window_paths_.assign(planned_.size(), {});
  if (!take_window(w, 0)) return;
  window_tick_ = ctx.tick();
  planner::mapf::Result res;
  res.status = planner::mapf::Status::Solved;
  res.paths = window_paths_;
  if (!next) {
    std::size_t goals = 0;
    for (const int r : planned_) goals += sequences_[static_cast<std::size_t>(r)].size();
    plans_.push_back({{"tick", ctx.tick()}, {"why", why}, {"robots", planned_.size()}, {"goals", goals}});
    std::fprintf(stderr, "gcs: traffic (%s) at tick %u: %zu robots, %zu goals, windows of %d steps\n", why,
                 ctx.tick(), planned_.size(), goals, window_);
  }
  send_plan(ctx, res);
}

bool MapfGcsTask::take_window(const planner::traffic::Window& w, int at) {
  bool moved = false;
  int reached = 0;
  for (std::size_t k = 0; k < planned_.size(); ++k) {
    const auto ur = static_cast<std::size_t>(planned_[k]);
    auto& path = window_paths_[k];
    path.insert(path.end(), w.paths[ur].begin() + (path.empty() ? 0 : 1), w.paths[ur].end());
    goals_[ur] = w.paths[ur].back();
    for (const int time : w.reached_at[ur]) window_reached_[ur].push_back(time < 0 ? -1 : at + time);
    reached += w.done[ur];
    moved = moved || w.paths[ur].back() != w.paths[ur].front();
  }
  idle_windows_ = moved || reached > 0 ? 0 : idle_windows_ + 1;
  if (idle_windows_ >= kIdleWindowsLimit) {
    failed_ = true;
    failure_ = "traffic: no robot moved or reached a goal in " + std::to_string(kIdleWindowsLimit) + " windows";
    return false;
  }
  ++windows_;
  return true;
}

bool MapfGcsTask::can_grow(const GcsContext& ctx) const {
  if (!by_graph_ || holding_ || failed_ || complete_ || no_continuation_ || window_paths_.empty() ||
      window_reached_.empty() || adg_.routes.size() != planned_.size()) {
    return false;
  }
  // Past kPlanSteps the next plan starts afresh; and a robot that may move now but was not
  // planned for (re-admitted) needs a new plan to be in it.
  if (static_cast<int>(window_paths_.front().size()) - 1 + window_ > kPlanSteps) return false;
  return planned_ == may_move(ctx);
}

std::vector<int> MapfGcsTask::may_move(const GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  std::vector<int> out;
  for (int r = 0; r < t.robots(); ++r) {
    if (ctx.alive(r) && ctx.alive(ctx.leader_of(t.group_of(static_cast<comm::AgentId>(r))))) out.push_back(r);
  }
  return out;
}

bool MapfGcsTask::time_to_extend(const GcsContext& ctx) const {
  if (!can_grow(ctx)) return false;
  const int end = static_cast<int>(window_paths_.front().size()) - 1;
  // New sequences continue the plan from its end (repick).
  bool more = repick_ != nullptr;
  for (std::size_t k = 0; k < planned_.size(); ++k) {
    const auto ur = static_cast<std::size_t>(planned_[k]);
    const auto& seq = sequences_[ur];
    const std::size_t planned = window_reached_[ur].size();
    if (seq.size() <= planned) continue;
    more = true;
    // An act on the cell the plan leaves the robot on would fall between two windows' routes.
    if (seq[planned].act != Stop::Act::kNone && seq[planned].cell == window_paths_[k].back()) return false;
  }
  if (!more) return false;
  // New sequences go out at once: a robot whose part of the plan is done stands until they come,
  // however far the leading robot still has to go.
  if (repick_ != nullptr) return true;
  // The leading robot's time in the plan, as reported.
  int lead = 0;
  for (std::size_t k = 0; k < planned_.size(); ++k) lead = std::max(lead, adg_.planned_time[k][progress_[k]]);
  // The window must reach the robots before the leading robot runs out: half a window ahead, plus
  // the lag.
  return lead + window_ / 2 + lag(ctx) >= end;
}

int MapfGcsTask::lag(const GcsContext& ctx) const {
  // The progress's age: its leader saw it in the clock and reported it over the leader<->GCS link.
  // Then the order's way to the members: leaders, then members. Member<->leader delay counts once.
  const comm::LinkTable& links = ctx.setup.links;
  const std::uint32_t at_leaders = comm::last_arrival_tick(links[comm::LinkClass::LeaderGcs], ctx.tick());
  const auto age = static_cast<int>(at_leaders - ctx.tick()) + 1;
  const auto trip = static_cast<int>(comm::last_arrival_tick(links[comm::LinkClass::MemberLeader], at_leaders) - ctx.tick());
  return age + trip;
}

bool MapfGcsTask::raise_limit(const GcsContext& ctx) {
  if (!by_graph_ || holding_ || failed_ || complete_ || window_paths_.empty() || adg_.routes.size() != planned_.size()) {
    return false;
  }
  // The limit is what a new round waits behind, and what keeps a robot from running on: it stays as
  // far ahead of every robot's reported progress as the progress's age and the relay's way to the
  // members take without jitter. With jitter a robot may reach the limit before it is raised and
  // wait a tick or two: measured, that costs less than the steps a higher limit adds to every
  // round (docs/traffic.md, "A new round cuts the plan").
  const comm::LinkTable& links = ctx.setup.links;
  const int jitter = static_cast<int>(links[comm::LinkClass::LeaderGcs].jitter_ticks + links[comm::LinkClass::MemberLeader].jitter_ticks);
  const int ahead = std::max(1, lag(ctx) - jitter);
  const int end = static_cast<int>(window_paths_.front().size()) - 1;
  int want = 0;
  for (std::size_t k = 0; k < planned_.size(); ++k) {
    const std::size_t last = adg_.routes[k].size() - 1;
    const std::size_t s = std::min<std::size_t>(progress_[k] + static_cast<std::size_t>(ahead), last);
    want = std::max(want, adg_.planned_time[k][s]);
  }
  const auto limit = static_cast<std::uint32_t>(std::min(want, end));
  if (limit <= limit_) return false;
  limit_ = limit;
  return true;
}

int MapfGcsTask::cut_plan() {
  const int end = static_cast<int>(window_paths_.front().size()) - 1;
  // A stop the plan reaches within half a window of the limit is kept: a waypoint about to be
  // reached is worth more than the steps saved by turning away from it.
  int at = static_cast<int>(limit_);
  for (const int r : planned_) {
    for (const int time : window_reached_[static_cast<std::size_t>(r)]) {
      if (time > at && time <= static_cast<int>(limit_) + window_ / 2) at = time;
    }
  }
  if (at >= end) return end;
  // An act at or after the cut would have to move with it: cut only plans of passing stops.
  for (const int r : planned_) {
    for (const Stop& s : sequences_[static_cast<std::size_t>(r)]) {
      if (s.act != Stop::Act::kNone) return end;
    }
  }
  for (auto& path : window_paths_) path.resize(static_cast<std::size_t>(at) + 1);
  for (const int r : planned_) {
    auto& reached = window_reached_[static_cast<std::size_t>(r)];
    std::size_t keep = 0;
    for (std::size_t g = 0; g < reached.size(); ++g) {
      if (reached[g] >= 0 && reached[g] <= at) keep = g + 1;
    }
    reached.resize(keep);
    auto& seq = sequences_[static_cast<std::size_t>(r)];
    seq.resize(std::min(seq.size(), keep));
  }
  // The rotations before the cut keep their numbers (planner/mapf/adg.hpp: in order of their time).
  std::size_t kept = 0;
  while (kept < adg_.rotations.size()) {
    const planner::mapf::Need& m = adg_.rotations[kept].front();
    if (adg_.planned_time[static_cast<std::size_t>(m.robot)][m.step] > at) break;
    ++kept;
  }
  rotation_ordered_.resize(kept);
  return at;
}

void MapfGcsTask::extend_window(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  if (map_grows_) known_ = ctx.fused.grid();
  // New sequences follow from the earliest time the plan may be cut, not from its end. If no window
  // can follow from there, the plan stays as it was and the sequences wait for its hold.
  const char* repick = repick_;
  const int old_end = static_cast<int>(window_paths_.front().size()) - 1;
  std::optional<std::tuple<std::vector<planner::mapf::Path>, std::vector<std::vector<int>>, std::vector<std::vector<Stop>>,
                           std::vector<bool>>>
      before;
  if (repick_ != nullptr) before.emplace(window_paths_, window_reached_, sequences_, rotation_ordered_);
  const int end = repick_ != nullptr ? cut_plan() : old_end;
  const bool cut = end < old_end;
  if (repick_ != nullptr) {
    // The plan keeps the stops it gets each robot past; the new sequences follow them from its end.
    std::vector<std::vector<Stop>> next = pick_routes_(ctx, known_, planned_, repick_);
    next.resize(static_cast<std::size_t>(t.robots()));
    for (const int r : planned_) {
      auto& seq = sequences_[static_cast<std::size_t>(r)];
      seq.resize(std::min(seq.size(), window_reached_[static_cast<std::size_t>(r)].size()));
      seq.insert(seq.end(), next[static_cast<std::size_t>(r)].begin(), next[static_cast<std::size_t>(r)].end());
    }
    plans_.push_back({{"tick", ctx.tick()}, {"why", repick_}, {"continues", seq_}});
    repick_ = nullptr;
    ++repicks_continued_;
  }
  // The next window from where the plan leaves every robot; the robots not planned for stand.
  std::vector<planner::traffic::Agent> agents(static_cast<std::size_t>(t.robots()));
  for (int r = 0; r < t.robots(); ++r) {
    agents[static_cast<std::size_t>(r)].at = ctx.cell_of(r);
    agents[static_cast<std::size_t>(r)].fixed = true;
  }
  for (std::size_t k = 0; k < planned_.size(); ++k) {
    const auto ur = static_cast<std::size_t>(planned_[k]);
    auto& agent = agents[ur];
    agent.at = window_paths_[k].back();
    agent.fixed = false;
    const auto& seq = sequences_[ur];
    for (std::size_t g = window_reached_[ur].size(); g < seq.size(); ++g) agent.goals.push_back(seq[g].cell);
  }
  if (map_grows_) {
    planner::OccupancyGrid map = known_;
    for (const auto& a : agents) map.set(a.at, planner::CellState::Free);
    traffic_->set_map(map);
  }
  planner::traffic::Window w;
  try {
    w = traffic_->plan(agents, window_);
  } catch (const std::invalid_argument& e) {
    // The plan is driven to its end and the next one made from where the robots stand.
    no_continuation_ = true;
    if (cut) {
      std::tie(window_paths_, window_reached_, sequences_, rotation_ordered_) = std::move(*before);
      repick_ = repick;
      --repicks_continued_;
      plans_.erase(plans_.size() - 1);
    }
    std::fprintf(stderr, "gcs: traffic: plan %u cannot grow: %s\n", seq_, e.what());
    return;
  }
  const std::uint32_t first = chain_first_;
  begin_plan(ctx);
  chain_first_ = first;
  if (!take_window(w, end)) return;
  ++windows_continued_;
  if (cut) {
    ++plans_cut_;
    steps_cut_ += static_cast<std::uint64_t>(old_end - end);
  }
  planner::mapf::Result res;
  res.status = planner::mapf::Status::Solved;
  res.paths = window_paths_;
  send_plan(ctx, res, end);
}

void MapfGcsTask::add_acts(int robot, task::PlannedRoute& route, int from) const {
  const auto ur = static_cast<std::size_t>(robot);
  const auto& seq = sequences_[ur];
  const auto& at = window_reached_[ur];
  for (std::size_t g = 0; g < at.size() && g < seq.size(); ++g) {
    // A window that continues the plan carries the acts after its first cell (the one before
    // ended there, with its act).
    if (at[g] < 0 || (from > 0 && at[g] <= from)) continue;
    const auto step = static_cast<std::uint32_t>(at[g] - from);
    if (seq[g].act == Stop::Act::kPick) route.pick_steps.push_back(step);
    if (seq[g].act == Stop::Act::kDrop) route.drop_steps.push_back(step);
  }
}

void MapfGcsTask::credit_window(const GcsContext& ctx, bool over) {
  for (std::size_t k = 0; k < planned_.size() && k < progress_.size(); ++k) {
    const auto ur = static_cast<std::size_t>(planned_[k]);
    if (ur >= window_reached_.size()) continue;
    auto& seq = sequences_[ur];
    auto& at = window_reached_[ur];
    std::uint32_t progress = progress_[k];
    const auto& route = by_graph_ ? adg_.routes[k] : window_paths_[k];
    // Once the window is over its last report may be behind (a lost robot, or one a new leader
    // stopped before reporting): where it stands says how far it got. (Not before: a route may
    // come back to a cell.)
    for (std::size_t s = progress; over && s < route.size(); ++s) {
      if (route[s] == ctx.cell_of(planned_[k])) {
        progress = static_cast<std::uint32_t>(s);
        break;
      }
    }
    // A robot past its route's first step made every act up to where it is (the simulator acts
    // as it arrives); on that step, only once its leader says so: a robot lost before its route
    // reached the simulator never made it.
    const std::uint32_t acted = std::max(acted_[k], progress > 0 ? progress + 1 : 0);
    // A stop is behind the robot once it has driven to the window's time of standing on it and
    // made its act there; a skipped stop, once the stops before it are.
    std::size_t n = 0;
    for (; n < at.size() && n < seq.size(); ++n) {
      if (at[n] < 0) continue;
      const std::uint32_t step = by_graph_ ? planner::mapf::step_at(adg_, static_cast<int>(k), at[n])
                                           : static_cast<std::uint32_t>(at[n]);
      if (step > progress || (seq[n].act != Stop::Act::kNone && step >= acted)) break;
    }
    for (std::size_t g = 0; g < n; ++g) {
      ++(at[g] < 0 ? goals_skipped_ : goals_done_);
      if (stop_done_) stop_done_(planned_[k], seq[g], at[g] >= 0);
    }
    seq.erase(seq.begin(), seq.begin() + static_cast<std::ptrdiff_t>(n));
    at.erase(at.begin(), at.begin() + static_cast<std::ptrdiff_t>(std::min(n, at.size())));
  }
  if (over) window_reached_.clear();
}

void MapfGcsTask::window_done(GcsContext& ctx) {
  credit_window(ctx, true);
  if (repick_ != nullptr) {  // the window ended before it was cut
    const char* why = repick_;
    repick_ = nullptr;
    plan_window(ctx, why);
    return;
  }
  // A robot lost with stops ahead of it: the task gives them to the others.
  for (int r = 0; r < ctx.setup.topology.robots(); ++r) {
    if (!ctx.alive(r) && !sequences_[static_cast<std::size_t>(r)].empty()) {
      plan_window(ctx, "robot lost");
      return;
    }
  }
  for (int r = 0; r < ctx.setup.topology.robots(); ++r) {
    if (ctx.alive(r) && !sequences_[static_cast<std::size_t>(r)].empty()) {
      plan_window(ctx, kNextWindow);
      return;
    }
  }
  complete_ = true;
}

void MapfGcsTask::restart(GcsContext& ctx, const char* why) {
  complete_ = false;
  repick_ = nullptr;
  plan(ctx, why);
}

void MapfGcsTask::repick(GcsContext& ctx, const char* why) {
  if (complete_) {
    restart(ctx, why);
    return;
  }
  if (!failed_) repick_ = why;
  cut_for_repick(ctx);
}

void MapfGcsTask::cut_for_repick(GcsContext& ctx) {
  // A window is driven for half its steps at least: new sequences that come faster than the robots
  // can stop and start again would keep them standing.
  if (repick_ == nullptr || holding_ || rotating(ctx.tick()) ||
      ctx.tick() < window_tick_ + static_cast<std::uint32_t>(window_ / 2)) {
    return;
  }
  // A plan that can grow takes the new sequences up from its end, without a stop (extend_window).
  if (can_grow(ctx)) return;
  // Every robot stops where it stands (not at its release: that may be the window's end), and the
  // next window starts from there once every group stands still.
  hold_why_ = repick_;
  repick_ = nullptr;
  holding_ = true;
  ++repicks_held_;
  send_order(ctx, task::OrderKind::Hold, {static_cast<std::int32_t>(seq_)});
}

}  // namespace swarm::gcs
