#include "swarm/tasks/mapf/mapf_leader.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "swarm/tasks/mapf/mapf_gcs.hpp"  // the messages' contract (kContinues)

namespace swarm::leader {

MapfGroupTask::MapfGroupTask(const swarm::scenario::Mapf& config, int group)
    : timed_(config.execution() == swarm::scenario::MAPF_EXECUTE_TIMED), group_(group) {}

void MapfGroupTask::start(GroupContext&) {
  have_plan_ = false;
  holding_ = false;
  waiting_.clear();
}

void MapfGroupTask::note(int k) {
  const auto ku = static_cast<std::size_t>(k);
  report_.push_back(robot_of_[ku]);
  report_.push_back(static_cast<std::int32_t>(progress_[ku]));
  report_.push_back(static_cast<std::int32_t>(released_[ku]));
  report_.push_back(static_cast<std::int32_t>(acted(ku)));
}

std::uint32_t MapfGroupTask::acted(std::size_t k) const {
  // A robot past its route's first step has made every act up to where it is: the part that took
  // it there carried them (the simulator acts as the robot arrives).
  return std::max(acted_[k], progress_[k] > 0 ? progress_[k] + 1 : 0);
}

bool MapfGroupTask::acts_done(std::size_t k) const {
  const std::uint32_t made = acted(k);
  const auto before = [made](const std::vector<std::uint32_t>& steps) {
    return std::all_of(steps.begin(), steps.end(), [made](std::uint32_t s) { return s < made; });
  };
  return before(picks_[k]) && before(drops_[k]);
}

void MapfGroupTask::take_plan(const task::Order& o, GroupContext& ctx) {
  std::vector<planner::mapf::Path> paths;
  for (const task::PlannedRoute& r : o.routes) paths.push_back(r.path);
  try {
    adg_ = planner::mapf::dependencies(paths);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "leader-%d: mapf plan %u dropped: %s\n", group_, o.seq, e.what());
    return;
  }
  seq_ = o.seq;
  chain_first_ = o.seq;
  have_plan_ = true;
  adopted_rotations_.clear();
  // Its first window is released whole; the GCS's relays raise the limit from there.
  limit_ = planner::mapf::last_time(paths);
  holding_ = false;
  stopping_.clear();
  stopped_all_ = false;
  reported_done_ = reported_held_ = false;
  ++plans_taken_;
  const std::size_t n = paths.size();
  routes_ = timed_ ? paths : adg_.routes;
  paths_ = std::move(paths);
  robot_of_.clear();
  picks_.assign(n, {});
  drops_.assign(n, {});
  for (std::size_t k = 0; k < n; ++k) {
    const task::PlannedRoute& r = o.routes[k];
    robot_of_.push_back(r.robot);
    const auto to_route = [&](std::uint32_t time) {
      return timed_ ? time : planner::mapf::step_at(adg_, static_cast<int>(k), static_cast<int>(time));
    };
    for (const std::uint32_t s : r.pick_steps) picks_[k].push_back(to_route(s));
    for (const std::uint32_t s : r.drop_steps) drops_[k].push_back(to_route(s));
  }
  index_of_.assign(n, -1);
  progress_.assign(n, 0);
  released_.assign(n, 0);
  acted_.assign(n, 0);
  picks_told_.assign(n, 0);
  last_pick_told_.assign(n, {});
  pick_results_.clear();
  watched_.assign(n, {});
  route_id_.assign(n, 0);
  route_start_.assign(n, 0);
  first_route_.assign(n, 0);
  base_.assign(n, 0);
  own_.clear();
  report_.clear();
  const comm::Topology& t = ctx.topology();
  for (std::size_t k = 0; k < n; ++k) {
    const auto robot = static_cast<comm::AgentId>(robot_of_[k]);
    if (t.group_of(robot) != group_) continue;
    index_of_[k] = t.index_of(robot);
    own_.push_back(static_cast<int>(k));
  }
  if (adopting_) return;  // a take-over: the robots are stopped instead (step)
  // Each robot of the group gets its whole route, released as far as the graph allows now (or,
  // timed, all of it from the start tick).
  for (int k : own_) {
    const auto ku = static_cast<std::size_t>(k);
    released_[ku] = timed_ ? static_cast<std::uint32_t>(routes_[ku].size() - 1) : releasable(k);
    task::Route m;
    m.path = routes_[ku];
    m.release = released_[ku];
    m.pick_steps = picks_[ku];
    m.drop_steps = drops_[ku];
    if (timed_ && !o.values.empty()) m.start_tick = static_cast<std::uint32_t>(o.values[0]);
    route_id_[ku] = ctx.out.route(index_of_[ku], m);
    route_start_[ku] = m.start_tick;
    first_route_[ku] = route_id_[ku];
    note(k);
  }
}

void MapfGroupTask::on_order(const task::Order& o, GroupContext& ctx) {
  if (o.kind == task::OrderKind::Work) {
    if (have_plan_ && o.seq <= seq_) return;  // taken already, or overtaken
    if (o.values.size() == 3 && o.values[0] == gcs::kContinues) {
      // It continues the plan this leader drives (its next window), or one not yet here.
      if (!(have_plan_ && static_cast<std::uint32_t>(o.values[1]) == chain_first_ && o.seq == seq_ + 1 &&
            extend_plan(o, ctx))) {
        waiting_.push_back(o);
        return;
      }
    } else {
      take_plan(o, ctx);
    }
    take_waiting(ctx);
    return;
  }
  if (o.values.empty()) return;
  const auto plan = static_cast<std::uint32_t>(o.values[0]);
  if (!have_plan_ || plan > seq_) {  // for a plan or window not yet here
    constexpr std::size_t kWaitingKept = 256;
    if (waiting_.size() == kWaitingKept) waiting_.erase(waiting_.begin());
    waiting_.push_back(o);
    return;
  }
  if (!in_plan(plan)) return;  // stale
  if (o.kind == task::OrderKind::Hold) {
    holding_ = true;
    // Every robot stops where it stands. Timed, each holds its whole route; timed driving is chosen
    // only with no link delay, so every robot of the plan stops at the same tick: a frozen step of
    // a valid plan. By the graph a robot may stop anywhere (no robot is released into a cell before
    // the robots planned there earlier have left it), and it must be told: its watch (release())
    // could open its route further at any time.
    if (!adopting_) stop_own_robots(ctx);
    return;
  }
  if (o.kind == task::OrderKind::Rotate) {
    if (o.values.size() != 3 || timed_ || o.values[1] < 0 || static_cast<std::size_t>(o.values[1]) >= adg_.rotations.size()) {
      return;
    }
    if (adopting_) {
      adopted_rotations_.emplace_back(o.values[1], static_cast<std::uint32_t>(o.values[2]));
    } else if (stopping_.empty() && !stopped_all_) {
      rotate(o.values[1], static_cast<std::uint32_t>(o.values[2]), ctx);
    }
    return;
  }
  if (o.kind != task::OrderKind::Progress) return;
  take_progress(o.values);
  release(ctx);
}

std::uint32_t MapfGroupTask::releasable(int k) const {
  return std::min(planner::mapf::releasable(adg_, k, progress_, planner::mapf::Rotations::Held),
                  planner::mapf::step_at(adg_, k, static_cast<int>(limit_)));
}

void MapfGroupTask::take_progress(const std::vector<std::int32_t>& v) {
  if (v.size() < 2) return;
  if (v[1] > 0) limit_ = std::max(limit_, static_cast<std::uint32_t>(v[1]));
  for (std::size_t i = 2; i + 3 < v.size(); i += 4) {
    const auto it = std::find(robot_of_.begin(), robot_of_.end(), v[i]);
    if (it == robot_of_.end()) continue;
    const auto k = static_cast<std::size_t>(it - robot_of_.begin());
    if (index_of_[k] >= 0) continue;  // its own: known first-hand
    progress_[k] = std::max(progress_[k], static_cast<std::uint32_t>(v[i + 1]));
    released_[k] = std::max(released_[k], static_cast<std::uint32_t>(v[i + 2]));
  }
}

void MapfGroupTask::take_waiting(GroupContext& ctx) {
  // Continuations first, in order: each may make the next one fit, and the relays for them count.
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < waiting_.size(); ++i) {
      const task::Order& o = waiting_[i];
      if (o.kind == task::OrderKind::Work && o.seq == seq_ + 1 &&
          static_cast<std::uint32_t>(o.values[1]) == chain_first_ && extend_plan(o, ctx)) {
        waiting_.erase(waiting_.begin() + static_cast<std::ptrdiff_t>(i));
        grew = true;
        break;
      }
    }
  }
  std::vector<task::Order> now;
  std::erase_if(waiting_, [&](const task::Order& o) {
    if (o.kind == task::OrderKind::Work) return o.seq <= seq_;  // overtaken by the plan taken
    const auto plan = static_cast<std::uint32_t>(o.values[0]);
    if (plan > seq_) return false;  // still ahead
    if (in_plan(plan)) now.push_back(o);
    return true;
  });
  for (const task::Order& o : now) on_order(o, ctx);
}

bool MapfGroupTask::extend_plan(const task::Order& o, GroupContext& ctx) {
  const auto from = static_cast<std::size_t>(o.values[2]);
  if (timed_ || o.routes.size() != paths_.size()) return false;
  // A window from before the plan's end cuts it there: the GCS cuts no earlier than the limit it
  // has sent (take_progress), which no robot is released past.
  std::vector<planner::mapf::Path> paths = paths_;
  const bool cut = !paths.empty() && from + 1 < paths.front().size();
  // Each robot's step at the cut in the plan as it was.
  std::vector<std::uint32_t> kept(paths.size());
  for (std::size_t k = 0; k < paths.size(); ++k) {
    kept[k] = planner::mapf::step_at(adg_, static_cast<int>(k), static_cast<int>(from));
  }
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const task::PlannedRoute& r = o.routes[k];
    if (cut && from < paths[k].size()) paths[k].resize(from + 1);
    // Of the others' robots this leader may know only the old plan's count (below).
    if (cut && index_of_[k] >= 0 && std::max(progress_[k], released_[k]) > kept[k]) {
      std::fprintf(stderr, "leader-%d: mapf window %u cuts plan %u at time %zu, step %u of robot %d, which is at step %u "
                   "released to %u (limit %u); dropped\n", group_, o.seq, seq_, from, kept[k], robot_of_[k], progress_[k],
                   released_[k], limit_);
      return false;
    }
    if (r.robot != robot_of_[k] || r.path.empty() || paths[k].size() != from + 1 || r.path.front() != paths[k].back()) {
      std::fprintf(stderr, "leader-%d: mapf window %u does not continue plan %u; dropped\n", group_, o.seq, seq_);
      return false;
    }
    paths[k].insert(paths[k].end(), r.path.begin() + 1, r.path.end());
  }
  planner::mapf::Dependencies grown;
  try {
    grown = planner::mapf::dependencies(paths);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "leader-%d: mapf window %u dropped: %s\n", group_, o.seq, e.what());
    return false;  // the plan stays as it was
  }
  for (std::size_t k = 0; cut && k < paths_.size(); ++k) {
    // Another group's robot may be past the cut already, on its new route (this window came
    // late): what the old route says of it past the cut means nothing. Counted at the cut, it is
    // late, never early, until its leader's reports and the clock bring it on.
    if (index_of_[k] < 0) {
      progress_[k] = std::min(progress_[k], kept[k]);
      released_[k] = std::min(released_[k], kept[k]);
    }
    // The acts past the cut go with the steps they were on.
    std::erase_if(picks_[k], [&](std::uint32_t s) { return s > kept[k]; });
    std::erase_if(drops_[k], [&](std::uint32_t s) { return s > kept[k]; });
  }
  const std::vector<std::vector<planner::Cell>> had = std::move(routes_);  // replaced below
  adg_ = std::move(grown);
  // The grown plan's old steps keep their needs (planner/mapf/adg.hpp), and so do a cut plan's up
  // to the cut: progress and releases carry over.
  paths_ = std::move(paths);
  seq_ = o.seq;
  routes_ = adg_.routes;
  reported_done_ = reported_held_ = false;
  ++plans_continued_;
  plans_cut_ += cut ? 1 : 0;
  for (std::size_t k = 0; k < paths_.size(); ++k) {
    const auto to_route = [&](std::uint32_t time) {
      return planner::mapf::step_at(adg_, static_cast<int>(k), static_cast<int>(from + time));
    };
    for (const std::uint32_t s : o.routes[k].pick_steps) picks_[k].push_back(to_route(s));
    for (const std::uint32_t s : o.routes[k].drop_steps) drops_[k].push_back(to_route(s));
  }
  if (adopting_ || holding_ || !stopping_.empty() || stopped_all_) return true;
  // Each robot gets its route again, longer under the same id, or cut and continued under a new one
  // that replaces it: it keeps its place and drives on.
  for (int k : own_) {
    const auto ku = static_cast<std::size_t>(k);
    // A robot that only waits in the new window keeps its route as it is.
    if (!ctx.alive[static_cast<std::size_t>(index_of_[ku])] || routes_[ku] == had[ku]) continue;
    const bool grown = routes_[ku].size() > had[ku].size() &&
                       std::equal(had[ku].begin(), had[ku].end(), routes_[ku].begin());
    released_[ku] = std::max(released_[ku], releasable(k));
    task::Route m = route_from(ku, base_[ku]);
    if (grown) m.grows = route_id_[ku];
    // Any version may come first (jitter): each replaces every earlier one from the same step on.
    m.replaces = first_route_[ku];
    m.start_tick = route_start_[ku];
    route_id_[ku] = ctx.out.route(index_of_[ku], m);
    watched_[ku].clear();
    note(k);
  }
  return true;
}

task::Route MapfGroupTask::route_from(std::size_t k, std::uint32_t from) const {
  task::Route r;
  r.path.assign(routes_[k].begin() + from, routes_[k].end());
  r.release = released_[k] - from;
  // Its acts still ahead, in steps of this route; one at `from` only on a route from the start (a
  // robot sent on from a later step stands there, its act made).
  const auto ahead = [from](std::uint32_t s) { return s > from || (s == from && from == 0); };
  for (const std::uint32_t s : picks_[k]) {
    if (ahead(s)) r.pick_steps.push_back(s - from);
  }
  for (const std::uint32_t s : drops_[k]) {
    if (ahead(s)) r.drop_steps.push_back(s - from);
  }
  return r;
}

void MapfGroupTask::stop_own_robots(GroupContext& ctx, const std::vector<bool>& except) {
  if (!stopping_.empty() || stopped_all_) return;  // stopped already
  for (int k : own_) {
    const auto ku = static_cast<std::size_t>(k);
    if (!ctx.alive[static_cast<std::size_t>(index_of_[ku])] || (ku < except.size() && except[ku])) continue;
    const task::Route stop;  // empty: stop where it stands
    route_id_[ku] = ctx.out.route(index_of_[ku], stop);
    route_start_[ku] = 0;
    stopping_.push_back(k);
  }
  stopped_all_ = stopping_.empty();
}

void MapfGroupTask::on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) {
  if (!have_plan_) return;
  if (!stopping_.empty() || stopped_all_) {
    std::erase_if(stopping_, [&](int k) {
      const auto ku = static_cast<std::size_t>(k);
      return index_of_[ku] == index && route_id_[ku] == p.id && p.state == planner::RouteState::Stopped;
    });
    stopped_all_ = stopping_.empty();
    return;
  }
  for (int k : own_) {
    const auto ku = static_cast<std::size_t>(k);
    if (index_of_[ku] != index || route_id_[ku] != p.id) continue;
    const bool further = base_[ku] + p.step > progress_[ku];
    const bool acted = p.acted > 0 && base_[ku] + p.acted > acted_[ku];
    if (!further && !acted) continue;
    progress_[ku] = std::max(progress_[ku], base_[ku] + p.step);
    if (acted) {
      acted_[ku] = base_[ku] + p.acted;
      tell_picks(ku);
    }
    note(k);
  }
  release(ctx);
}

void MapfGroupTask::on_carrying(int index, const std::vector<std::uint32_t>& objects, GroupContext& ctx) {
  const auto i = static_cast<std::size_t>(index);
  if (index < 0 || i >= ctx.alive.size()) return;  // not a robot of the group
  if (grippers_.size() < ctx.alive.size()) grippers_.resize(ctx.alive.size());
  grippers_[i] = objects;
}

void MapfGroupTask::tell_picks(std::size_t k) {
  // The member's word on what the robot holds came with this progress: what it holds with its
  // acts below acted_ made. It tells what each pick-up among them got, unless a drop came after
  // it (or with it) in the same span.
  const auto index = static_cast<std::size_t>(index_of_[k]);
  const std::uint32_t from = picks_told_[k], to = acted_[k];
  picks_told_[k] = to;
  if (index >= grippers_.size()) return;
  std::vector<std::int32_t> told;
  for (const std::uint32_t s : picks_[k]) {
    if (s < from || s >= to ||
        std::any_of(drops_[k].begin(), drops_[k].end(), [&](std::uint32_t d) { return d >= s && d < to; })) {
      continue;
    }
    const planner::Cell at = routes_[k][s];
    told.insert(told.end(), {robot_of_[k], at.x, at.y, static_cast<std::int32_t>(grippers_[index].size())});
    for (const std::uint32_t o : grippers_[index]) told.push_back(static_cast<std::int32_t>(o));
  }
  if (told.empty()) return;
  pick_results_.insert(pick_results_.end(), told.begin(), told.end());
  last_pick_told_[k] = std::move(told);
}

void MapfGroupTask::see_positions(const GroupContext& ctx) {
  if (timed_ || adopting_) return;
  for (std::size_t k = 0; k < progress_.size(); ++k) {
    const planner::Cell at = ctx.clock.robots[static_cast<std::size_t>(robot_of_[k])].cell;
    const std::uint32_t p = planner::mapf::progress_at(adg_, static_cast<int>(k), progress_[k], at);
    if (p == progress_[k]) continue;
    progress_[k] = p;
    if (index_of_[k] >= 0) note(static_cast<int>(k));  // its own: the GCS hears it now
  }
}

void MapfGroupTask::release(GroupContext& ctx) {
  if (!have_plan_ || holding_ || timed_ || adopting_ || !stopping_.empty() || stopped_all_) return;
  for (int k : own_) {
    const auto ku = static_cast<std::size_t>(k);
    if (!ctx.alive[static_cast<std::size_t>(index_of_[ku])]) continue;
    const std::uint32_t may = releasable(k);
    // A member judges the steps after its release itself, from the robots' cells in the clock,
    // and so sets off in the tick the robots it waits on have gone, not once this release has
    // reached it. The leader's own robot needs no watch: its leader looks every tick.
    planner::mapf::Watch watch;
    if (index_of_[ku] != ctx.self) {
      watch = planner::mapf::watch_release(adg_, k, progress_, kWatchGates);
      // Not past the limit either: the first gate beyond it opens only as far as the limit (its
      // needs hold those of every step before it).
      const std::uint32_t cap = planner::mapf::step_at(adg_, k, static_cast<int>(limit_));
      for (std::size_t g = 0; g < watch.gates.size(); ++g) {
        if (watch.gates[g].release <= cap) continue;
        watch.gates[g].release = cap;
        watch.gates.resize(g + 1);
        if (g > 0 && watch.gates[g - 1].release >= cap) watch.gates.pop_back();
        break;
      }
    }
    const bool further = may > released_[ku];
    released_[ku] = std::max(released_[ku], may);
    // Gates the release has passed say nothing new (each gate holds the needs of those before it).
    std::erase_if(watch.gates, [&](const planner::mapf::Gate& g) { return g.release <= released_[ku]; });
    std::vector<std::uint32_t> gates;
    for (const planner::mapf::Gate& g : watch.gates) gates.push_back(g.release);
    if (!further && gates == watched_[ku]) continue;
    watched_[ku] = std::move(gates);
    for (int& r : watch.robots) r = robot_of_[static_cast<std::size_t>(r)];
    for (planner::mapf::Gate& g : watch.gates) g.release -= base_[ku];
    ctx.out.release(index_of_[ku], route_id_[ku], released_[ku] - base_[ku], watch);
    if (!watch.gates.empty()) ++watches_sent_;
    if (!further) continue;
    ++releases_sent_;
    note(k);
  }
}

void MapfGroupTask::rotate(int q, std::uint32_t tick, GroupContext& ctx) {
  for (const planner::mapf::Need& m : adg_.rotations[static_cast<std::size_t>(q)]) {
    const auto ku = static_cast<std::size_t>(m.robot);
    if (index_of_[ku] < 0 || !ctx.alive[static_cast<std::size_t>(index_of_[ku])]) continue;
    if (progress_[ku] + 1 != m.step) continue;  // not where the GCS saw it (cannot happen: it was held)
    // The rest of its route from the cell it stands on, its first step released from `tick` on:
    // every member's simulator command then leaves in one tick.
    const std::uint32_t from = m.step - 1;
    base_[ku] = from;
    released_[ku] = m.step;
    task::Route r = route_from(ku, from);
    r.start_tick = tick;
    route_id_[ku] = ctx.out.route(index_of_[ku], r);
    route_start_[ku] = tick;
    first_route_[ku] = route_id_[ku];
    note(static_cast<int>(ku));
  }
}

void MapfGroupTask::step(GroupContext& ctx) {
  if (adopting_) {
    adopting_ = false;
    // Timed, the robots keep to the plan's timing until the GCS's hold, which reaches every leader
    // at one tick, stops them all together; by the graph they may stop at once (the others wait),
    // but for a rotation ordered for a tick still to come: its robots of the other groups move
    // then, and so must this group's, which then stand at their step's end.
    if (have_plan_ && (!timed_ || holding_)) stop_own_robots(ctx, adopt_rotations(ctx));
  }
  if (!have_plan_) return;
  // Reports, and the GCS's relays of them to the other leaders, can be lost (a lossy link): every
  // kRefreshTicks the whole state goes again, so no robot waits for ever on a lost one.
  if (ctx.clock.tick % kRefreshTicks == 0) gcs_back(ctx);
  see_positions(ctx);
  if (!stopping_.empty()) {  // a robot lost before its stop was confirmed stands still anyway
    std::erase_if(stopping_, [&](int k) { return !ctx.alive[static_cast<std::size_t>(index_of_[static_cast<std::size_t>(k)])]; });
    stopped_all_ = stopping_.empty();
  }
  release(ctx);
  const bool stopped = !stopping_.empty() || stopped_all_;  // a take-over's stop: wait for the hold
  bool arrived = !stopped, still = true;
  for (int k : own_) {
    const auto ku = static_cast<std::size_t>(k);
    if (stopped || !ctx.alive[static_cast<std::size_t>(index_of_[ku])]) continue;
    // Arrived, its acts made: the GCS counts a pick or a drop only once it is made.
    arrived = arrived && progress_[ku] + 1 >= routes_[ku].size() && acts_done(ku);
    still = still && progress_[ku] >= released_[ku];
  }
  if (stopped) still = stopped_all_;
  task::GroupState state = task::GroupState::Working;
  if (arrived && !reported_done_) {
    state = task::GroupState::Done;
    reported_done_ = true;
  } else if (holding_ && still && !reported_held_) {
    state = task::GroupState::Held;
    reported_held_ = true;
  }
  if (!pick_results_.empty()) {
    task::Report picks;
    picks.values = {gcs::kPickResults};
    picks.values.insert(picks.values.end(), pick_results_.begin(), pick_results_.end());
    pick_results_.clear();
    ctx.out.report(picks);
  }
  if (report_.empty() && state == task::GroupState::Working) return;
  task::Report r;
  r.state = state;
  r.values = {static_cast<std::int32_t>(seq_)};
  r.values.insert(r.values.end(), report_.begin(), report_.end());
  report_.clear();
  ctx.out.report(r);
}

std::vector<bool> MapfGroupTask::adopt_rotations(GroupContext& ctx) {
  std::vector<bool> rotating(routes_.size(), false);
  for (const auto& [q, tick] : adopted_rotations_) {
    if (tick < ctx.clock.tick) continue;  // gone, or not, under the old leader
    // The old leader's routes for it may be held by the simulator already; the same again (under
    // this leader's ids) replaces them, or moves the robots if they never came. Each robot stands
    // at its step's start: the GCS orders a rotation only then.
    for (const planner::mapf::Need& m : adg_.rotations[static_cast<std::size_t>(q)]) {
      const auto ku = static_cast<std::size_t>(m.robot);
      if (index_of_[ku] < 0 || m.step == 0 || ctx.cell_of(index_of_[ku]) != routes_[ku][m.step - 1]) continue;
      progress_[ku] = m.step - 1;
      rotating[ku] = true;
    }
    rotate(q, tick, ctx);
  }
  adopted_rotations_.clear();
  return rotating;
}

void MapfGroupTask::gcs_back(GroupContext&) {
  // Every robot's progress and release, and the group's done or held, again.
  if (!have_plan_) return;
  for (int k : own_) {
    note(k);
    const auto& told = last_pick_told_[static_cast<std::size_t>(k)];
    pick_results_.insert(pick_results_.end(), told.begin(), told.end());
  }
  reported_done_ = reported_held_ = false;
}

nlohmann::json MapfGroupTask::numbers() const {
  return {{"plans", plans_taken_},
          {"windows_continued", plans_continued_},
          {"plans_cut", plans_cut_},
          {"releases_sent", releases_sent_},
          {"watches_sent", watches_sent_}};
}

}  // namespace swarm::leader
