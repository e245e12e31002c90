#include "swarm/member/watched_releases.hpp"

namespace swarm::member {

void WatchedReleases::see(std::uint32_t tick, std::vector<planner::Cell> cells) {
  ticks_.emplace_back(tick, std::move(cells));
  if (ticks_.size() > kTicksKept) ticks_.pop_front();
  follow_up();
}

void WatchedReleases::watch(std::uint32_t route_id, std::uint32_t tick, planner::mapf::Watch w) {
  if (held_ && (held_->route_id > route_id || (held_->route_id == route_id && held_->made_at > tick))) return;
  const std::uint32_t told = held_ && held_->route_id == route_id ? held_->told : 0;
  held_.emplace(Held{route_id, tick, tick, std::move(w.robots),
                     planner::mapf::ReleaseWatch(std::move(w.routes), std::move(w.gates)), told});
  follow_up();
}

void WatchedReleases::follow_up() {
  if (!held_) return;
  Held& h = *held_;
  std::vector<planner::Cell> at(h.robots.size());
  for (const auto& [tick, cells] : ticks_) {
    if (tick < h.next_tick) continue;
    for (std::size_t w = 0; w < h.robots.size(); ++w) {
      const auto r = static_cast<std::size_t>(h.robots[w]);
      at[w] = r < cells.size() ? cells[r] : planner::Cell{-1, -1};  // a robot not in the clock is never seen
    }
    h.watch.see(at);
    h.next_tick = tick + 1;
  }
}

std::optional<WatchedReleases::Open> WatchedReleases::opened() {
  if (!held_ || held_->watch.opened() <= held_->told) return std::nullopt;
  held_->told = held_->watch.opened();
  ++releases_opened_;
  return Open{held_->route_id, held_->told};
}

}  // namespace swarm::member
