#include "swarm/sim/world.hpp"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <unordered_map>

#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/sensing/raycast.hpp"
#include "swarm/planner/tours/turns.hpp"

namespace swarm::sim {

using planner::Cell;
using planner::CellChange;
using planner::CellState;

Resolution resolve(const std::vector<Cell>& current, const std::vector<Cell>& intended) {
  assert(current.size() == intended.size());
  const std::size_t n = current.size();
  Resolution r;
  r.next = current;
  r.moved.assign(n, 0);
  r.vertex.assign(n, 0);
  r.edge.assign(n, 0);
  r.blocked.assign(n, 0);
  std::vector<std::uint8_t> failed(n, 0);
  const auto mover = [&](std::size_t i) { return intended[i] != current[i]; };

  // Step 2: conflicts among the intentions; every mover in one stays.
  const planner::StepConflicts c = planner::find_step_conflicts(current, intended);
  for (const auto& v : c.vertex) {
    // A conflict among robots that all stay cannot happen (they stand on distinct cells).
    ++r.events.vertex;
    for (int i : v.robots) {
      r.vertex[i] = 1;
      if (mover(i)) failed[i] = 1;
    }
  }
  for (const auto& e : c.edge) {
    ++r.events.edge;
    r.edge[e.a] = r.edge[e.b] = 1;
    failed[e.a] = failed[e.b] = 1;
  }
  // Step 3: a mover into the cell of a robot that stays is blocked, until nothing changes. Each
  // pass fails at least one more robot or ends, so at most n passes.
  std::unordered_map<std::int64_t, std::size_t> at;
  at.reserve(n * 2);
  const auto key = [](Cell x) { return (static_cast<std::int64_t>(x.y) << 32) ^ static_cast<std::uint32_t>(x.x); };
  for (std::size_t i = 0; i < n; ++i) at.emplace(key(current[i]), i);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!mover(i) || failed[i]) continue;
      const auto it = at.find(key(intended[i]));
      if (it == at.end()) continue;
      const std::size_t j = it->second;
      if (mover(j) && !failed[j]) continue;  // it leaves this tick: follow it
      failed[i] = 1;
      r.blocked[i] = 1;
      changed = true;
    }
  }
  // Step 4: everyone else moves (chains into vacated cells, rotations of three or more).
  for (std::size_t i = 0; i < n; ++i) {
    if (mover(i) && !failed[i]) {
      r.next[i] = intended[i];
      r.moved[i] = 1;
    }
  }
  return r;
}

World::World(planner::OccupancyGrid truth, std::vector<Cell> robot_cells, LidarConfig lidar, int footprint_radius)
    : truth_(std::move(truth)),
      lidar_(lidar),
      footprint_radius_(std::max(0, footprint_radius)),
      robots_(std::move(robot_cells)),
      routes_(robots_.size()),
      progress_(robots_.size()),
      seen_(truth_.width(), truth_.height(), truth_.resolution()),
      counts_(robots_.size()),
      blocked_run_(robots_.size(), 0),
      run_since_mark_(robots_.size(), 0),
      longest_since_mark_(robots_.size(), 0),
      heading_(robots_.size(), -1),
      picks_(robots_.size()),
      drops_(robots_.size()) {
  reachable_ = planner::reachable_mask(truth_, {robots_.front()});
  reachable_free_ = static_cast<int>(std::count(reachable_.begin(), reachable_.end(), 1));
  reset_coverage();
}

void World::command(int robot, std::uint32_t route_id, const std::vector<Cell>& route,
                    const std::vector<std::uint32_t>& picks, const std::vector<std::uint32_t>& drops) {
  planner::RouteProgress& p = progress_[robot];
  // A robot numbers its commands upwards: an older one that arrives after a newer (a lost
  // transmission repeated, link jitter) was overtaken on the way.
  if (route_id <= p.id) return;
  p.id = route_id;
  p.step = 0;
  routes_[robot].clear();
  picks_[robot] = picks;
  drops_[robot] = drops;
  if (route.empty()) {
    p.state = RouteState::Stopped;
  } else if (route.front() != robots_[robot]) {
    p.state = RouteState::Rejected;
    ++counts_[robot].routes_rejected;
  } else {
    routes_[robot] = route;
    p.state = route.size() == 1 ? RouteState::Finished : RouteState::Active;
    act(robot);
  }
}

void World::command_at(std::uint32_t start_tick, int robot, std::uint32_t route_id, std::vector<Cell> route,
                       std::vector<std::uint32_t> picks, std::vector<std::uint32_t> drops) {
  held_.push_back({start_tick, robot, route_id, std::move(route), std::move(picks), std::move(drops)});
}

void World::start_due(std::uint32_t tick) {
  // In the order they came; command() ignores one that a newer command has overtaken.
  std::vector<Held> due;
  std::erase_if(held_, [&](Held& h) {
    if (h.start_tick > tick) return false;
    due.push_back(std::move(h));
    return true;
  });
  for (const Held& h : due) command(h.robot, h.route_id, h.route, h.picks, h.drops);
}

void World::stop(int robot) {
  std::erase_if(held_, [robot](const Held& h) { return h.robot == robot; });
  routes_[static_cast<std::size_t>(robot)].clear();
  progress_[static_cast<std::size_t>(robot)].state = RouteState::Stopped;
}

void World::set_objects(std::vector<planner::TourObject> objects, std::vector<Cell> destinations) {
  objects_.clear();
  for (const auto& o : objects) objects_.push_back({o.cell, o.type, -1, false});
  destinations_ = std::move(destinations);
  collect_ = {};
  collect_.objects = static_cast<int>(objects_.size());
}

void World::put_down(int robot) {
  const Cell cell = planner::put_down_cell(truth_, robots_[static_cast<std::size_t>(robot)], robots_);
  for (Object& o : objects_) {
    if (o.carrier != robot) continue;
    o.carrier = -1;
    o.cell = cell;
  }
}

void World::act(int robot) {
  const auto r = static_cast<std::size_t>(robot);
  const std::uint32_t s = progress_[r].step;
  const Cell here = robots_[r];
  const auto has = [s](const std::vector<std::uint32_t>& v) { return std::find(v.begin(), v.end(), s) != v.end(); };
  if (has(picks_[r])) {
    for (Object& o : objects_) {
      if (o.delivered || o.carrier >= 0 || o.cell != here) continue;
      o.carrier = robot;
      ++collect_.picked;
    }
  }
  if (has(drops_[r])) {
    for (Object& o : objects_) {
      if (o.carrier != robot) continue;
      o.carrier = -1;
      o.cell = here;
      const bool right = static_cast<std::size_t>(o.type) < destinations_.size() &&
                         destinations_[static_cast<std::size_t>(o.type)] == here;
      o.delivered = right;
      ++(right ? collect_.delivered : collect_.wrong_drops);
    }
  }
}

void World::move() {
  const std::size_t n = robots_.size();
  std::vector<Cell> intended = robots_;
  // Step 1: actions the motion model forbids are wall stops.
  for (std::size_t r = 0; r < n; ++r) {
    planner::RouteProgress& p = progress_[r];
    if (p.state != RouteState::Active) continue;
    const Cell to = routes_[r][p.step + 1];
    const planner::MoveCheck check = motion_.check(truth_, robots_[r], to);
    if (check == planner::MoveCheck::Wait) continue;
    if (check != planner::MoveCheck::Ok) {
      ++counts_[r].wall_stops;
      p.state = RouteState::Abandoned;
      routes_[r].clear();
      continue;
    }
    intended[r] = to;
  }
  const Resolution res = resolve(robots_, intended);
  events_.vertex += res.events.vertex;
  events_.edge += res.events.edge;
  for (std::size_t r = 0; r < n; ++r) {
    MotionCounts& c = counts_[r];
    // A move that the motion model allowed but that did not happen: another robot was in the way.
    if (intended[r] != robots_[r] && !res.moved[r]) {
      c.longest_blocked_ticks = std::max(c.longest_blocked_ticks, ++blocked_run_[r]);
      longest_since_mark_[r] = std::max(longest_since_mark_[r], ++run_since_mark_[r]);
    } else {
      blocked_run_[r] = run_since_mark_[r] = 0;
    }
    c.vertex_conflicts += res.vertex[r];
    c.edge_conflicts += res.edge[r];
    c.blocked_moves += res.blocked[r];
    planner::RouteProgress& p = progress_[r];
    if (p.state != RouteState::Active) continue;
    const bool waited = routes_[r][p.step + 1] == robots_[r];
    if (!waited && !res.moved[r]) continue;  // failed: the same action again next tick
    if (waited) ++c.waits;
    if (res.moved[r]) {
      ++c.moves;
      if (robots_[r].x != res.next[r].x && robots_[r].y != res.next[r].y) ++diagonal_moves_;
      const int h = *planner::step_heading(robots_[r], res.next[r]);
      if (heading_[r] >= 0) c.turn_eighths += static_cast<std::uint64_t>(planner::turn_eighths(heading_[r], h));
      heading_[r] = h;
    }
    robots_[r] = res.next[r];
    if (++p.step + 1 >= routes_[r].size()) p.state = RouteState::Finished;
    act(static_cast<int>(r));
  }
  for (std::size_t r = 0; r < n; ++r) coverage_.visit(robots_[r]);
}

void World::mark() {
  std::fill(run_since_mark_.begin(), run_since_mark_.end(), 0);
  std::fill(longest_since_mark_.begin(), longest_since_mark_.end(), 0);
}

void World::scan(int robot, std::vector<float>& ranges) {
  ranges.resize(lidar_.beams);
  planner::scan(truth_, robots_[robot], lidar_.beams, lidar_.range_cells, ranges.data());
  std::vector<CellChange> changes;
  planner::integrate_scan(seen_, robots_[robot], ranges.data(), lidar_.beams, lidar_.range_cells, &changes);
  for (const CellChange& c : changes) {
    if (c.state == CellState::Free && reachable_[c.index]) ++reachable_seen_;
  }
}

double World::explored_fraction() const {
  return reachable_free_ == 0 ? 1.0 : static_cast<double>(reachable_seen_) / reachable_free_;
}

void World::reset_coverage() {
  coverage_ = planner::CoverageTracker(truth_, planner::reachable_mask(truth_, robots_, motion_), footprint_radius_);
  for (const Cell& c : robots_) coverage_.visit(c);
}

MotionCounts World::total_counts() const {
  MotionCounts t;
  for (const auto& c : counts_) t += c;
  return t;
}

std::vector<std::uint32_t> World::carried_by(int robot) const {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (objects_[i].carrier == robot) out.push_back(static_cast<std::uint32_t>(i));
  }
  return out;
}

std::vector<int> World::object_states() const {
  std::vector<int> out;
  out.reserve(objects_.size() * 3);
  for (const Object& o : objects_) {
    const Cell at = o.carrier >= 0 ? robots_[static_cast<std::size_t>(o.carrier)] : o.cell;
    out.insert(out.end(), {at.x, at.y, o.delivered ? kDelivered : o.carrier >= 0 ? o.carrier : kLying});
  }
  return out;
}

}  // namespace swarm::sim
