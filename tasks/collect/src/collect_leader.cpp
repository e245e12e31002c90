#include "swarm/tasks/collect/collect_leader.hpp"

#include <any>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "swarm/tasks/collect/nearest_with_room.hpp"
#include "swarm/comm/link.hpp"
#include "swarm/tasks/collect/object_facts.hpp"
#include "swarm/planner/grid/astar.hpp"
#include "swarm/planner/coverage/cover_routes.hpp"
#include "swarm/planner/tours/tour.hpp"

namespace swarm::leader {

using planner::Cell;

namespace {
// A robot whose route has not advanced for this many ticks backs off (see the header).
constexpr std::uint32_t kStallTicks = 6;
}  // namespace

CollectGroupTask::CollectGroupTask(const swarm::scenario::Collect& config, const app::RoleSetup& setup, int group,
                                   std::uint32_t index)
    : group_(group),
      map_given_(config::map_given(setup.world.scenario, index)),
      world_(std::any_cast<const tasks::CollectWorld&>(setup.world.phase_data.at(index))),
      robots_(static_cast<std::size_t>(setup.topology.robots_per_group())) {}

void CollectGroupTask::start(GroupContext&) {
  have_order_ = reported_ = resuming_ = false;
  resume_order_.reset();
  state_.assign(world_.objects.size(), State::Waiting);
  carrier_.assign(world_.objects.size(), -1);
  where_.clear();
  told_.clear();
  for (const auto& o : world_.objects) {
    where_.push_back(o.cell);
    told_.push_back({collect::kObjectLying, o.cell.x, o.cell.y});
  }
  for (Robot& r : robots_) r = Robot{};
  holds_.assign(robots_.size(), std::nullopt);
  put_down_.assign(robots_.size(), std::nullopt);
}

void CollectGroupTask::took_over(GroupContext& ctx) {
  resuming_ = true;
  // Where the simulator left what each robot lost by now held: it put it down when it lost the
  // robot, from the robot cells of this clock (member_lost does the same for later losses).
  for (int i = 0; i < static_cast<int>(robots_.size()); ++i) {
    if (!ctx.alive[static_cast<std::size_t>(i)]) member_lost(i, ctx);
  }
  // Every living member sends what it holds to a new leader at once: all heard the tick after its
  // last arrival.
  grippers_heard_by_ = comm::last_arrival_tick(ctx.setup.links[comm::LinkClass::MemberLeader], ctx.clock.tick) + 1;
}

void CollectGroupTask::on_carrying(int index, const std::vector<std::uint32_t>& objects, GroupContext&) {
  holds_[static_cast<std::size_t>(index)] = objects;
}

namespace {
void check_object(std::int64_t id, std::size_t objects) {
  if (id < 0 || static_cast<std::size_t>(id) >= objects) {
    throw std::runtime_error("a collect order names object " + std::to_string(id) + " of " + std::to_string(objects));
  }
}
}  // namespace

void CollectGroupTask::on_order(const task::Order& o, GroupContext& ctx) {
  if (o.kind == task::OrderKind::Resume) {
    if (o.values.size() % 4 != 0) throw std::runtime_error("a collect resume order's values are not (object, what, a, b) sets");
    for (std::size_t k = 0; k < o.values.size(); k += 4) check_object(o.values[k], world_.objects.size());
    if (resuming_ && (!resume_order_ || o.seq > resume_order_->seq)) resume_order_ = o;
    return;
  }
  if (o.kind != task::OrderKind::Work || (have_order_ && o.seq <= seq_)) return;
  if (resuming_) return;  // a take-over starts from the resume order: what was done since this one
  for (std::int32_t id : o.values) check_object(id, world_.objects.size());
  seq_ = o.seq;
  have_order_ = true;
  mine_.assign(o.values.begin(), o.values.end());
  share(mine_, ctx);
  for (int i : ctx.living()) plan(i, ctx);
}

void CollectGroupTask::resume(GroupContext& ctx) {
  const task::Order& o = *resume_order_;
  seq_ = o.seq;
  have_order_ = true;
  resuming_ = false;
  ++resumes_;
  mine_.clear();
  const comm::Topology& t = ctx.topology();
  const std::vector<int> living = ctx.living();
  auto holder = [&](std::uint32_t id) {
    for (int i : living) {
      const auto& h = holds_[static_cast<std::size_t>(i)];
      if (h && std::find(h->begin(), h->end(), id) != h->end()) return i;
    }
    return -1;
  };
  std::vector<int> lying;
  const auto& v = o.values;
  for (std::size_t k = 0; k + 3 < v.size(); k += 4) {
    const int id = v[k];
    const auto idu = static_cast<std::size_t>(id);
    mine_.push_back(id);
    told_[idu] = {v[k + 1], v[k + 2], v[k + 3]};
    state_[idu] = State::Waiting;
    carrier_[idu] = -1;
    int on = holder(static_cast<std::uint32_t>(id));
    const bool carried = v[k + 1] == collect::kObjectCarried && v[k + 2] >= 0 && v[k + 2] < t.robots() &&
                         t.group_of(static_cast<comm::AgentId>(v[k + 2])) == group_;
    const int was_on = carried ? t.index_of(static_cast<comm::AgentId>(v[k + 2])) : -1;
    // The report's holder, if its gripper was not heard: trust the report.
    if (on < 0 && was_on >= 0 && ctx.alive[static_cast<std::size_t>(was_on)] && !holds_[static_cast<std::size_t>(was_on)]) {
      on = was_on;
    }
    if (on >= 0) {
      state_[idu] = State::Carried;
      carrier_[idu] = on;
      where_[idu] = ctx.cell_of(on);  // its tour "picks it up" where it starts: it holds it already
      robots_[static_cast<std::size_t>(on)].pending.push_back(id);
    } else if (v[k + 1] == collect::kObjectDelivered) {
      state_[idu] = State::Delivered;
    } else if (was_on >= 0 && put_down_[static_cast<std::size_t>(was_on)]) {
      where_[idu] = *put_down_[static_cast<std::size_t>(was_on)];  // its robot was lost
      lying.push_back(id);
    } else if (was_on >= 0) {
      state_[idu] = State::Delivered;  // a living robot that held it holds it no more: it dropped it on its tour
    } else {
      where_[idu] = {v[k + 2], v[k + 3]};
      // A lost robot of the group standing on its cell had come to pick it up and did, after the
      // old leader's last report (a robot lost on it would otherwise cover it for good): the
      // simulator put it down beside that robot.
      for (std::size_t i = 0; i < put_down_.size(); ++i) {
        if (put_down_[i] && !ctx.alive[i] && ctx.cell_of(static_cast<int>(i)) == where_[idu]) where_[idu] = *put_down_[i];
      }
      lying.push_back(id);
    }
  }
  std::fprintf(stderr, "leader-%d: resumes %zu objects (%zu lying)\n", group_, mine_.size(), lying.size());
  share(lying, ctx);
  for (int i : living) {
    plan(i, ctx);
    if (robots_[static_cast<std::size_t>(i)].busy) continue;
    // No tour for it: it must not drive on along the old leader's, picking up what is now
    // another's. An empty route stops it where it stands.
    const task::Route stop;
    robots_[static_cast<std::size_t>(i)].route_id = ctx.out.route(i, stop);
  }
}

void CollectGroupTask::share(const std::vector<int>& ids, GroupContext& ctx) {
  // Each object to the nearest living robot with room left, counting what the robots have
  // pending already (nearest_with_room.hpp).
  const std::vector<int> living = ctx.living();
  std::vector<Cell> objects, at;
  std::vector<std::size_t> held;
  for (int id : ids) objects.push_back(where_[static_cast<std::size_t>(id)]);
  for (int i : living) {
    at.push_back(ctx.cell_of(i));
    held.push_back(robots_[static_cast<std::size_t>(i)].pending.size());
  }
  const std::vector<int> to = collect::nearest_with_room(objects, at, held);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (to[k] >= 0) robots_[static_cast<std::size_t>(living[static_cast<std::size_t>(to[k])])].pending.push_back(ids[k]);
  }
}

const planner::OccupancyGrid& CollectGroupTask::known_map(const GroupContext& ctx) const {
  return map_given_ ? ctx.setup.given_map : ctx.map.group();
}

planner::OccupancyGrid CollectGroupTask::planning_map(const GroupContext& ctx) const {
  // A lost robot stands where it stopped for good (the clock says who is lost, in every group):
  // tours and detours go round it.
  planner::OccupancyGrid map = known_map(ctx);
  for (const task::RobotAt& r : ctx.clock.robots) {
    if (!r.alive) map.set(r.cell, planner::CellState::Occupied);
  }
  return map;
}

void CollectGroupTask::plan(int index, GroupContext& ctx) {
  Robot& r = robots_[static_cast<std::size_t>(index)];
  if (r.busy || r.pending.empty()) return;
  planner::TourProblem problem;
  problem.start = ctx.cell_of(index);
  problem.destinations = world_.destinations;
  for (int id : r.pending) problem.objects.push_back({where_[static_cast<std::size_t>(id)], world_.objects[static_cast<std::size_t>(id)].type});
  planner::TourOptions options;
  options.variant = planner::TourVariant::kDistanceAngle;
  options.search = planner::TourOptions::Search::kExact;
  options.seed = static_cast<std::uint64_t>(1000 * group_ + index + 1);
  const planner::OccupancyGrid map = planning_map(ctx);
  const planner::TourPlan plan = planner::plan_tour(map, problem, options);
  // Nothing reachable (a lost robot may stand in the way for good): the objects stay pending.
  if (plan.legs.empty()) return;
  r.picks.clear();
  r.delivers.clear();
  std::uint32_t at = 0;
  std::vector<int> carried;
  for (const planner::TourLeg& leg : plan.legs) {
    at += static_cast<std::uint32_t>(leg.cells.size() - 1);
    if (leg.stop.kind == planner::TourStop::kPickUp) {
      const int id = r.pending[static_cast<std::size_t>(leg.stop.object)];
      r.picks.emplace_back(id, at);
      carried.push_back(id);
    } else {
      for (int id : carried) r.delivers.emplace_back(id, at);
      carried.clear();
    }
  }
  // Objects the planner left out (unreachable on the map the leader has) stay pending.
  std::vector<int> left;
  for (int skipped : plan.skipped) left.push_back(r.pending[static_cast<std::size_t>(skipped)]);
  r.pending = left;
  // Then back to where the robot started the mission: a robot that stayed on the last
  // destination would stand in the way of every robot delivering there after it.
  std::vector<Cell> cells = plan.cells();
  const Cell home = ctx.setup.world.robot_cells[ctx.topology().robot(group_, index)];
  if (auto back = planner::astar(map, cells.back(), home, {.unknown_is_free = false}); back && back->size() > 1) {
    cells.insert(cells.end(), back->begin() + 1, back->end());
  }
  send(index, ctx, std::move(cells));
  r.length_cells += plan.length_cells();
  r.rotation_eighths += plan.rotation;
  ++r.tours;
}

void CollectGroupTask::send(int index, GroupContext& ctx, std::vector<Cell> cells) {
  Robot& r = robots_[static_cast<std::size_t>(index)];
  task::Route m;
  m.path = cells;
  m.release = static_cast<std::uint32_t>(cells.size() - 1);
  for (const auto& [id, step] : r.picks) {
    if (step != kDone) m.pick_steps.push_back(step);
  }
  for (const auto& [id, step] : r.delivers) {
    if (step != kDone && std::find(m.drop_steps.begin(), m.drop_steps.end(), step) == m.drop_steps.end()) {
      m.drop_steps.push_back(step);
    }
  }
  r.route_id = ctx.out.route(index, m);
  r.step = 0;
  r.busy = cells.size() > 1;
  r.moved_tick = ctx.clock.tick;
  r.cells = std::move(cells);
}

void CollectGroupTask::reroute(int index, int waits, GroupContext& ctx) {
  Robot& r = robots_[static_cast<std::size_t>(index)];
  const std::uint32_t at = r.step;
  const Cell here = r.cells[at];
  // Around the robots in the way if there is a way (a swap is never undone by waiting), else wait.
  std::vector<Cell> others;
  for (const task::RobotAt& s : ctx.clock.robots) {
    if (s.cell != here) others.push_back(s.cell);
  }
  const planner::OccupancyGrid map = planning_map(ctx);
  // (4-connected, so legal under the tour's 8-connected motion too)
  std::vector<Cell> around = planner::detour(map, r.cells, at, others);
  std::vector<Cell> cells;
  std::uint32_t target = at;  // the tour step the new route rejoins at, and its index there
  std::uint32_t rejoin = 0;
  const auto tail = static_cast<std::uint32_t>(r.cells.size() - 1);
  // around = a path to tour step `target`, then the tour after it: find the first such step.
  bool found = false;
  for (std::uint32_t j = at + 1; j <= tail && !around.empty() && around.front() == here && !found; ++j) {
    if (around.size() < tail - j + 1) continue;
    const auto k = static_cast<std::uint32_t>(around.size() - 1 - (tail - j));
    if (k == 0) continue;
    if (std::equal(around.begin() + k, around.end(), r.cells.begin() + j)) {
      found = around.size() + at != r.cells.size() || !std::equal(around.begin(), around.end(), r.cells.begin() + at);
      target = j;
      rejoin = k;
    }
  }
  // A detour that skips a pick-up or a drop would leave objects behind or carried for ever: wait
  // instead.
  for (const auto* list : {&r.picks, &r.delivers}) {
    for (const auto& [id, step] : *list) found = found && !(step != kDone && step > at && step < target);
  }
  if (found) {
    cells = std::move(around);
    ++detours_;
  } else {
    cells.assign(static_cast<std::size_t>(waits), here);
    cells.insert(cells.end(), r.cells.begin() + at, r.cells.end());
    rejoin = static_cast<std::uint32_t>(waits);
    target = at;
    ++backoffs_;
  }
  // Tour steps before `target` that the new route skips: their picks and drops are undone (the
  // objects wait for a later tour); steps from `target` on keep their place relative to it.
  const std::uint32_t shift_from = target;
  for (auto* list : {&r.picks, &r.delivers}) {
    for (auto& [id, step] : *list) {
      if (step == kDone) continue;
      if (step < at || (step <= at && list == &r.picks)) {
        step = kDone;  // already done where the robot stands
      } else if (step < shift_from) {
        if (list == &r.picks && state_[static_cast<std::size_t>(id)] == State::Waiting) r.pending.push_back(id);
        step = kDone;
      } else {
        step = step - shift_from + rejoin;
      }
    }
  }
  send(index, ctx, std::move(cells));
}

void CollectGroupTask::on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) {
  Robot& r = robots_[static_cast<std::size_t>(index)];
  if (p.id != r.route_id || r.cells.empty()) return;  // (a stop has no cells)
  if (p.step > r.step) r.moved_tick = ctx.clock.tick;
  reached(index, p.step);
  if (p.state == planner::RouteState::Finished) {
    r.busy = false;
    plan(index, ctx);
  } else if (p.state != planner::RouteState::Active) {
    // Refused or abandoned (the robot was not where the route began): from where it stands back
    // onto its route, the rest unchanged.
    const planner::OccupancyGrid map = planning_map(ctx);
    const auto back = planner::astar(map, ctx.cell_of(index), r.cells[r.step], {.unknown_is_free = false});
    if (!back) return;
    std::vector<Cell> cells = *back;
    cells.insert(cells.end(), r.cells.begin() + r.step + 1, r.cells.end());
    const auto rejoin = static_cast<std::uint32_t>(back->size() - 1);
    for (auto* list : {&r.picks, &r.delivers}) {
      for (auto& [id, step] : *list) {
        if (step == kDone) continue;
        step = step < r.step ? kDone : step - r.step + rejoin;
      }
    }
    send(index, ctx, std::move(cells));
  }
}

void CollectGroupTask::reached(int index, std::uint32_t step) {
  Robot& r = robots_[static_cast<std::size_t>(index)];
  r.step = std::max(r.step, step);
  for (const auto& [id, at] : r.picks) {
    if (r.step >= at && state_[static_cast<std::size_t>(id)] == State::Waiting) {
      state_[static_cast<std::size_t>(id)] = State::Carried;
      carrier_[static_cast<std::size_t>(id)] = index;
    }
  }
  for (const auto& [id, at] : r.delivers) {
    if (r.step >= at) state_[static_cast<std::size_t>(id)] = State::Delivered;
  }
}

void CollectGroupTask::member_lost(int index, GroupContext& ctx) {
  Robot& lost = robots_[static_cast<std::size_t>(index)];
  // The loss is noticed ticks after the robot's last report, and its body drove on along the route
  // the simulator had: where it stopped (its true cell, in the clock) says how far it got, so a
  // pick or a drop it made since its last report counts (the first such cell from its last known
  // step: a route that passes a cell twice is taken at its earlier pass).
  for (std::uint32_t k = lost.step; k < lost.cells.size(); ++k) {
    if (lost.cells[k] == ctx.cell_of(index)) {
      reached(index, k);
      break;
    }
  }
  // Where the simulator put down what it carried: the same rule, from the same robot cells, on the
  // map the group knows (the cells around a robot are in its scans, so they agree with the truth).
  std::vector<Cell> robots;
  for (const task::RobotAt& s : ctx.clock.robots) robots.push_back(s.cell);
  const Cell at = planner::put_down_cell(known_map(ctx), ctx.cell_of(index), robots);
  put_down_[static_cast<std::size_t>(index)] = at;
  if (resuming_) return;  // what it held is judged with the resume order
  std::vector<int> orphans = lost.pending;
  for (const auto& [id, step] : lost.picks) {
    auto& s = state_[static_cast<std::size_t>(id)];
    if (s == State::Delivered) continue;
    if (s == State::Carried) where_[static_cast<std::size_t>(id)] = at;  // the simulator put it down there
    s = State::Waiting;
    orphans.push_back(id);
  }
  lost = Robot{};
  const std::vector<int> living = ctx.living();
  if (living.empty()) return;
  // To the living robot with the fewest objects still ahead of it; objects lying on one cell (what
  // the lost robot carried, put down beside it) all to one robot, as a robot picks up everything
  // on the cell it picks at.
  std::vector<std::pair<Cell, int>> taken_by;  // (cell, robot) given so far
  for (int id : orphans) {
    const Cell cell = where_[static_cast<std::size_t>(id)];
    int best = living.front();
    for (int i : living) {
      if (robots_[static_cast<std::size_t>(i)].pending.size() < robots_[static_cast<std::size_t>(best)].pending.size()) best = i;
    }
    for (const auto& [c, i] : taken_by) {
      if (c == cell) best = i;
    }
    if (std::none_of(taken_by.begin(), taken_by.end(), [&](const auto& t) { return t.first == cell; })) {
      taken_by.emplace_back(cell, best);
    }
    robots_[static_cast<std::size_t>(best)].pending.push_back(id);
    ++reassigned_;
  }
  for (int i : living) plan(i, ctx);
}

void CollectGroupTask::report_changes(GroupContext& ctx) {
  std::vector<std::int32_t> values{static_cast<std::int32_t>(seq_)};
  const comm::Topology& t = ctx.topology();
  for (int id : mine_) {
    const auto idu = static_cast<std::size_t>(id);
    std::array<std::int32_t, 3> now{collect::kObjectLying, where_[idu].x, where_[idu].y};
    if (state_[idu] == State::Delivered) now = {collect::kObjectDelivered, 0, 0};
    if (state_[idu] == State::Carried && carrier_[idu] >= 0) now = {collect::kObjectCarried, t.robot(group_, carrier_[idu]), 0};
    if (now == told_[idu]) continue;
    told_[idu] = now;
    values.push_back(id);
    values.insert(values.end(), now.begin(), now.end());
  }
  if (values.size() == 1) return;
  task::Report report;
  report.state = task::GroupState::Working;
  report.values = std::move(values);
  ctx.out.report(report);
}

void CollectGroupTask::step(GroupContext& ctx) {
  if (resuming_) {
    if (!resume_order_ || ctx.clock.tick < grippers_heard_by_) return;
    resume(ctx);
  }
  if (!have_order_ || reported_) return;
  for (int i : ctx.living()) {
    plan(i, ctx);  // an idle robot with objects waiting
    Robot& r = robots_[static_cast<std::size_t>(i)];
    if (r.busy && ctx.clock.tick >= r.moved_tick + kStallTicks && ctx.cell_of(i) == r.cells[r.step]) {
      reroute(i, 1 + static_cast<int>(ctx.topology().robot(group_, i)), ctx);
    }
  }
  report_changes(ctx);
  for (int id : mine_) {
    if (state_[static_cast<std::size_t>(id)] != State::Delivered) return;
  }
  task::Report report;
  report.state = task::GroupState::Done;
  report.values = {static_cast<std::int32_t>(seq_)};
  ctx.out.report(report);
  reported_ = true;
}

void CollectGroupTask::gcs_back(GroupContext&) {
  // What is known of every object, and the group's done, again.
  for (auto& t : told_) t = {-1, -1, -1};
  reported_ = false;
}

nlohmann::json CollectGroupTask::numbers() const {
  nlohmann::json per_robot = nlohmann::json::array();
  for (const Robot& r : robots_) {
    per_robot.push_back({{"tours", r.tours}, {"planned_length_cells", r.length_cells}, {"planned_rotation_eighths", r.rotation_eighths}});
  }
  int delivered = 0;
  for (int id : mine_) delivered += state_[static_cast<std::size_t>(id)] == State::Delivered ? 1 : 0;
  return {{"objects", mine_.size()}, {"delivered_known", delivered}, {"reassigned", reassigned_},
          {"backoffs", backoffs_},   {"detours", detours_},           {"resumes", resumes_},
          {"per_robot", per_robot}};
}

}  // namespace swarm::leader
