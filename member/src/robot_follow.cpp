// RobotAgent's route following (robot_agent.hpp, follow()): the leader's route is driven exactly,
// in parts as it is released, each part sent to the simulator as a route of its own.
#include <algorithm>

#include "swarm/member/robot_agent.hpp"

namespace swarm::member {

using planner::Cell;
using planner::RouteState;

void RobotAgent::follow(std::uint32_t id, std::vector<Cell> cells, std::uint32_t release,
                        std::vector<std::uint32_t> picks, std::vector<std::uint32_t> drops, std::uint32_t start_tick,
                        std::uint32_t replaces) {
  if (id < newest_route_) return;  // overtaken by a newer one on the way (link jitter, a resend)
  if (replaces != 0 && follow_ && replaces <= follow_progress_.id && follow_progress_.id < id &&
      take_cut(id, cells, release, picks, drops)) {
    return;
  }
  if (follow_ && id == follow_progress_.id && !follow_->cells.empty() && !cells.empty()) {
    Follow& f = *follow_;
    const std::size_t common = std::min(cells.size(), f.cells.size());
    if (std::equal(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(common), f.cells.begin())) {
      // The route it follows again: grown at its end, it keeps its place and drives on; as it was
      // or shorter, it is an older version overtaken on the way (jitter, a lost message repeated).
      if (cells.size() > f.cells.size()) {
        f.cells = std::move(cells);
        f.picks = std::move(picks);
        f.drops = std::move(drops);
        if (follow_progress_.state == RouteState::Finished) follow_progress_.state = RouteState::Active;
      }
      f.release = std::max(f.release, release);
      return;
    }
  }
  newest_route_ = id;
  Follow f;
  f.cells = std::move(cells);
  for (const auto& [route, up_to] : early_releases_) {
    if (route == id) release = std::max(release, up_to);
  }
  std::erase_if(early_releases_, [id](const auto& r) { return r.first == id; });
  f.release = release;
  f.picks = std::move(picks);
  f.drops = std::move(drops);
  f.start_tick = start_tick;
  follow_ = std::move(f);
  follow_progress_ = {id, 0, RouteState::Active};
}

bool RobotAgent::take_cut(std::uint32_t id, std::vector<Cell>& cells, std::uint32_t release,
                          std::vector<std::uint32_t>& picks, std::vector<std::uint32_t>& drops) {
  Follow& f = *follow_;
  // As far as the robot may have got: where it is, the part the simulator drives, its release
  // (which may lie past the cells it has, in a window still on its way).
  const std::size_t reach = std::max({static_cast<std::size_t>(follow_progress_.step), static_cast<std::size_t>(f.sent_to),
                                      static_cast<std::size_t>(f.release)}) + 1;
  const std::size_t common = std::min(reach, f.cells.size());
  if (cells.size() < reach || f.cells.size() < common ||
      !std::equal(f.cells.begin(), f.cells.begin() + static_cast<std::ptrdiff_t>(common), cells.begin())) {
    return false;
  }
  f.cells = std::move(cells);
  f.picks = std::move(picks);
  f.drops = std::move(drops);
  f.release = std::max(f.release, release);
  for (const auto& [route, up_to] : early_releases_) {
    if (route == id) f.release = std::max(f.release, up_to);
  }
  std::erase_if(early_releases_, [id](const auto& r) { return r.first == id; });
  newest_route_ = id;
  follow_progress_.id = id;
  if (follow_progress_.state == RouteState::Finished && follow_progress_.step + 1 < f.cells.size()) {
    follow_progress_.state = RouteState::Active;
  }
  return true;
}

void RobotAgent::release(std::uint32_t id, std::uint32_t up_to) {
  if (!follow_ || follow_progress_.id != id) {
    // For a route replaced since (forgotten with the others once they are many), or one still on
    // its way.
    constexpr std::size_t kKept = 8;
    auto it = std::find_if(early_releases_.begin(), early_releases_.end(), [id](const auto& r) { return r.first == id; });
    if (it != early_releases_.end()) {
      it->second = std::max(it->second, up_to);
    } else {
      if (early_releases_.size() == kKept) early_releases_.erase(early_releases_.begin());
      early_releases_.emplace_back(id, up_to);
    }
    return;
  }
  // Kept whole: it may reach into the route's next window, whose cells are still on their way
  // (routes and releases travel on different topics).
  follow_->release = std::max(follow_->release, up_to);
}

void RobotAgent::step_following(Step& out, std::uint32_t tick) {
  Follow& f = *follow_;
  // The simulator acts on a part's first cell as it takes the part, on each later one as the robot
  // arrives: the acts up to where it says the robot is are done (a one-cell part, sent for its
  // act alone, reports Finished at once). Counted on a route with acts only: each new count is a
  // report to the leader, which a route without acts does not need.
  const bool acts = !f.picks.empty() || !f.drops.empty();
  if (acts && f.sim_id != 0 && report_.id == f.sim_id && report_.state != RouteState::Rejected &&
      report_.state != RouteState::None) {
    follow_progress_.acted = std::max(follow_progress_.acted, f.base + report_.step + 1);
  }
  if (follow_progress_.state != RouteState::Active) return;
  if (f.cells.empty()) {  // a stop: sent once; Stopped when the simulator has applied it
    if (f.sim_id == 0) {
      out.path_changed = true;
      out.path.clear();
    } else if (report_.id == f.sim_id && report_.state == RouteState::Stopped) {
      follow_progress_.state = RouteState::Stopped;
    }
    return;
  }
  // Where the simulator says the robot is along the part it drives.
  if (f.sim_id != 0 && report_.id == f.sim_id) {
    follow_progress_.step = f.base + report_.step;
    if (report_.state == RouteState::Rejected || report_.state == RouteState::Abandoned) {
      follow_progress_.state = RouteState::Abandoned;  // the leader re-plans it
      return;
    }
  }
  const std::uint32_t at = follow_progress_.step;
  const auto last = static_cast<std::uint32_t>(f.cells.size() - 1);
  const std::uint32_t release = std::min(f.release, last);
  // The next part: from where the robot stands to the release, once the last part is driven
  // (or none was sent). A part in flight is waited for.
  const bool part_done = f.sim_id == 0 || (report_.id == f.sim_id && f.base + report_.step == f.sent_to);
  // An act on the cell the robot stands on as the route starts is made at once, even if the robot
  // may not go on yet or ever (a one-cell route): a part of that one cell carries it.
  const auto here = [at](const std::vector<std::uint32_t>& steps) {
    return std::find(steps.begin(), steps.end(), at) != steps.end();
  };
  const bool act_here = f.sim_id == 0 && (here(f.picks) || here(f.drops));
  if (at >= last && !act_here) {
    follow_progress_.state = RouteState::Finished;
    return;
  }
  if (!part_done || (release <= at && !act_here)) return;
  if (at >= last) follow_progress_.state = RouteState::Finished;  // its act is on its way
  if (pose_ != f.cells[at]) {
    // Not where the route says: it cannot go on, and it stops, so that it does not drive on along
    // the part of an earlier route still in the simulator while its leader routes it from where it
    // stands (before, a leader's new routes chased a robot that kept moving, each one abandoned).
    follow_progress_.state = RouteState::Abandoned;
    out.path_changed = true;
    out.path.clear();
    return;
  }
  out.path_changed = true;
  out.path.assign(f.cells.begin() + at, f.cells.begin() + release + 1);
  if (f.sim_id == 0 && f.start_tick > tick) out.start_tick = f.start_tick;
  // An action at index `at` belongs to this part only if no part was sent before (the route's
  // first cell); otherwise the previous part ended there and carried it.
  const std::uint32_t from = f.sim_id == 0 ? at : at + 1;
  for (std::uint32_t p : f.picks) {
    if (p >= from && p <= release) out.pick_steps.push_back(p - at);
  }
  for (std::uint32_t d : f.drops) {
    if (d >= from && d <= release) out.drop_steps.push_back(d - at);
  }
  f.base = at;
  f.sent_to = release;
}

}  // namespace swarm::member
