#include "swarm/planner/mapf/release_watch.hpp"

#include <utility>

namespace swarm::planner::mapf {

Watch watch_release(const Dependencies& adg, int robot, const std::vector<std::uint32_t>& progress,
                    std::size_t max_gates) {
  Watch w;
  const auto r = static_cast<std::size_t>(robot);
  const auto& needs = adg.needs.at(r);
  // Progress as it will be once the gates so far are open: the needs of each gate's step raised.
  std::vector<std::uint32_t> assumed = progress;
  std::vector<int> slot(adg.routes.size(), -1);
  std::uint32_t at = releasable(adg, robot, assumed, Rotations::Held);
  while (w.gates.size() < max_gates && static_cast<std::size_t>(at) + 1 < needs.size()) {
    const std::uint32_t k = at + 1;
    if (!adg.rotation_of.empty() && adg.rotation_of[r][k] >= 0) break;  // the GCS releases rotations
    for (const Need& n : needs[k]) {
      const auto nr = static_cast<std::size_t>(n.robot);
      if (assumed[nr] >= n.step) continue;
      if (slot[nr] < 0) {
        slot[nr] = static_cast<int>(w.robots.size());
        w.robots.push_back(n.robot);
      }
      assumed[nr] = n.step;
    }
    const std::uint32_t next = releasable(adg, robot, assumed, Rotations::Held);
    if (next <= at) break;
    Gate g;
    g.release = next;
    for (int watched : w.robots) {
      const auto wr = static_cast<std::size_t>(watched);
      g.reached.push_back(assumed[wr] - progress[wr]);
    }
    w.gates.push_back(std::move(g));
    at = next;
  }
  for (Gate& g : w.gates) g.reached.resize(w.robots.size(), 0);
  for (int watched : w.robots) {
    const auto wr = static_cast<std::size_t>(watched);
    const auto& route = adg.routes[wr];
    w.routes.emplace_back(route.begin() + progress[wr], route.begin() + assumed[wr] + 1);
  }
  return w;
}

ReleaseWatch::ReleaseWatch(std::vector<std::vector<Cell>> routes, std::vector<Gate> gates)
    : routes_(std::move(routes)), gates_(std::move(gates)), reached_(routes_.size(), 0) {}

void ReleaseWatch::see(const std::vector<Cell>& at) {
  for (std::size_t w = 0; w < routes_.size() && w < at.size(); ++w) {
    // One step a tick at most, only onto the route's next cell: as progress_at (adg.hpp).
    const std::size_t next = static_cast<std::size_t>(reached_[w]) + 1;
    if (next < routes_[w].size() && routes_[w][next] == at[w]) ++reached_[w];
  }
  while (next_gate_ < gates_.size()) {
    const Gate& g = gates_[next_gate_];
    bool open = g.reached.size() == reached_.size();
    for (std::size_t w = 0; open && w < reached_.size(); ++w) open = reached_[w] >= g.reached[w];
    if (!open) break;
    opened_ = g.release;
    ++next_gate_;
  }
}

}  // namespace swarm::planner::mapf
