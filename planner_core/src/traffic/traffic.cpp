#include "swarm/planner/traffic/traffic.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner::traffic {

namespace {
// Above this many cached distances (256 MB of ints) the tables of goals no robot heads for go.
constexpr std::size_t kMaxTableCells = std::size_t{64} << 20;
}  // namespace

Planner::Planner(OccupancyGrid map, MotionModel motion, Config config)
    : map_(std::move(map)),
      motion_(motion),
      config_(config),
      free_(map_.size(), false),
      blocked_(map_.size(), false),
      on_now_(map_.size(), -1),
      on_next_(map_.size(), -1),
      tie_(mix_seed({config.seed, 0x7472616666ULL})) {
  for (std::size_t i = 0; i < map_.size(); ++i) free_[i] = map_.at(static_cast<int>(i)) == CellState::Free;
}

void Planner::set_map(const OccupancyGrid& map) {
  if (map.width() != map_.width() || map.height() != map_.height()) {
    throw std::invalid_argument("traffic: a new map must keep the planner's size");
  }
  bool changed = false;
  for (std::size_t i = 0; i < map_.size(); ++i) {
    const bool f = map.at(static_cast<int>(i)) == CellState::Free;
    changed = changed || f != free_[i];
    free_[i] = f;
  }
  map_ = map;
  // Every distance may have changed with one cell: the searches start again.
  if (changed) {
    tables_.clear();
    table_cells_ = 0;
  }
}

int Planner::steps_to(int goal, int cell) {
  auto [it, added] = tables_.try_emplace(goal);
  Table& t = it->second;
  if (added) {
    t.dist.assign(map_.size(), -1);
    table_cells_ += map_.size();
    if (passable(goal)) {
      t.dist[static_cast<std::size_t>(goal)] = 0;
      t.queue.push_back(goal);
    }
  }
  const auto uc = static_cast<std::size_t>(cell);
  while (t.dist[uc] < 0 && t.head < t.queue.size()) {
    const int c = t.queue[t.head++];
    const int next = t.dist[static_cast<std::size_t>(c)] + 1;
    motion_.for_each_neighbour(map_, map_.cell_of(c), [&](Cell n, double) {
      const int ni = map_.index(n);
      if (!passable(ni) || t.dist[static_cast<std::size_t>(ni)] >= 0) return;
      t.dist[static_cast<std::size_t>(ni)] = next;
      t.queue.push_back(ni);
    });
  }
  return t.dist[uc] < 0 ? kUnreachable : t.dist[uc];
}

void Planner::trim_tables(const std::vector<Agent>& agents) {
  if (table_cells_ <= kMaxTableCells) return;
  std::vector<int> wanted;
  for (const Agent& a : agents) {
    if (!a.goals.empty() && map_.in_bounds(a.goals.front())) wanted.push_back(map_.index(a.goals.front()));
  }
  std::sort(wanted.begin(), wanted.end());
  for (auto it = tables_.begin(); it != tables_.end();) {
    if (std::binary_search(wanted.begin(), wanted.end(), it->first)) {
      ++it;
    } else {
      table_cells_ -= map_.size();
      it = tables_.erase(it);
    }
  }
}

int Planner::distance(int a, int cell) {
  const int g = goal_[static_cast<std::size_t>(a)];
  if (g < 0) return cell == now_[static_cast<std::size_t>(a)] ? 0 : 1;  // no goal: rather stay
  return steps_to(g, cell);
}

bool Planner::push(int a, int parent) {
  const auto ua = static_cast<std::size_t>(a);
  const int here = now_[ua];
  // The cells a can take next, best first: nearer its goal, then not standing on another robot
  // (who would have to move away first), then a fair coin.
  struct Candidate {
    int cell;
    int dist;
    int occupied;
    std::uint64_t coin;
  };
  std::array<Candidate, 9> cand{};
  std::size_t n = 0;
  const auto add = [&](int c) {
    const int who = on_now_[static_cast<std::size_t>(c)];
    cand[n++] = {c, distance(a, c), who >= 0 && who != a ? 1 : 0, splitmix64(tie_)};
  };
  add(here);
  motion_.for_each_neighbour(map_, map_.cell_of(here), [&](Cell c, double) {
    const int ci = map_.index(c);
    if (passable(ci)) add(ci);
  });
  const auto better = [](const Candidate& x, const Candidate& y) {
    if (x.dist != y.dist) return x.dist < y.dist;
    if (x.occupied != y.occupied) return x.occupied < y.occupied;
    return x.coin < y.coin;
  };
  for (std::size_t i = 1; i < n; ++i) {  // insertion sort: at most 9 cells
    for (std::size_t j = i; j > 0 && better(cand[j], cand[j - 1]); --j) std::swap(cand[j], cand[j - 1]);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const int v = cand[k].cell;
    const auto uv = static_cast<std::size_t>(v);
    if (on_next_[uv] >= 0) continue;                         // taken by a robot of higher priority
    if (parent >= 0 && v == now_[static_cast<std::size_t>(parent)]) continue;  // would swap with it
    on_next_[uv] = a;
    next_[ua] = v;
    const int b = on_now_[uv];
    if (b >= 0 && b != a && next_[static_cast<std::size_t>(b)] < 0 && !push(b, a)) continue;
    return true;
  }
  next_[ua] = here;
  on_next_[static_cast<std::size_t>(here)] = a;
  return false;
}

Window Planner::plan(const std::vector<Agent>& agents, int steps) {
  const std::size_t n = agents.size();
  if (!priority_.empty() && priority_.size() != n) {
    throw std::invalid_argument("traffic: planned for " + std::to_string(priority_.size()) + " robots before, now " +
                                std::to_string(n));
  }
  // Fixed robots are obstacles: distances measured with another set of them are stale.
  std::vector<bool> blocked(map_.size(), false);
  for (std::size_t a = 0; a < n; ++a) {
    const Cell c = agents[a].at;
    if (!map_.in_bounds(c) || !free_[static_cast<std::size_t>(map_.index(c))]) {
      throw std::invalid_argument("traffic: robot " + std::to_string(a) + " stands on (" + std::to_string(c.x) + ", " +
                                  std::to_string(c.y) + "), which is not a free cell of the map");
    }
    if (agents[a].fixed) blocked[static_cast<std::size_t>(map_.index(c))] = true;
  }
  if (blocked != blocked_) {
    blocked_ = std::move(blocked);
    tables_.clear();
    table_cells_ = 0;
  }
  trim_tables(agents);

  now_.assign(n, -1);
  goal_.assign(n, -1);
  next_.assign(n, -1);
  for (std::size_t a = 0; a < n; ++a) {
    const int c = map_.index(agents[a].at);
    if (on_now_[static_cast<std::size_t>(c)] >= 0) {
      const int other = on_now_[static_cast<std::size_t>(c)];
      for (std::size_t b = 0; b < a; ++b) on_now_[static_cast<std::size_t>(now_[b])] = -1;
      throw std::invalid_argument("traffic: robots " + std::to_string(other) + " and " + std::to_string(a) +
                                  " stand on one cell (" + std::to_string(agents[a].at.x) + ", " +
                                  std::to_string(agents[a].at.y) + ")");
    }
    now_[a] = c;
    on_now_[static_cast<std::size_t>(c)] = static_cast<int>(a);
  }
  if (priority_.empty()) {
    Rng rng(mix_seed({config_.seed, n}));
    base_.resize(n);
    for (double& b : base_) b = rng.uniform01();
    priority_ = base_;
    waiting_.assign(n, 0);
  }

  Window w;
  w.paths.resize(n);
  w.done.assign(n, 0);
  w.skipped.resize(n);
  w.reached_at.resize(n);
  // Moves past the goals a robot stands on and those it cannot reach; sets its current goal.
  const auto advance = [&](std::size_t a) {
    const Agent& ag = agents[a];
    int& i = w.done[a];
    goal_[a] = -1;
    if (ag.fixed) {
      i = static_cast<int>(ag.goals.size());
      w.reached_at[a].assign(ag.goals.size(), -1);
      return false;
    }
    bool reached = false;
    while (i < static_cast<int>(ag.goals.size())) {
      const Cell g = ag.goals[static_cast<std::size_t>(i)];
      const int gi = map_.in_bounds(g) ? map_.index(g) : -1;
      if (gi == now_[a]) {
        reached = true;
        w.reached_at[a].push_back(static_cast<int>(w.paths[a].size()) - 1);
      } else if (gi < 0 || steps_to(gi, now_[a]) >= kUnreachable) {
        w.skipped[a].push_back(i);
        w.reached_at[a].push_back(-1);
      } else {
        goal_[a] = gi;
        break;
      }
      ++i;
    }
    return reached;
  };
  for (std::size_t a = 0; a < n; ++a) {
    w.paths[a].reserve(static_cast<std::size_t>(steps) + 1);
    w.paths[a].push_back(agents[a].at);
    if (advance(a)) priority_[a] = base_[a];
  }

  std::vector<int> order(n);
  std::vector<int> before(n);
  for (int s = 0; s < steps; ++s) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
      return priority_[static_cast<std::size_t>(x)] > priority_[static_cast<std::size_t>(y)];
    });
    for (std::size_t a = 0; a < n; ++a) {
      before[a] = goal_[a] >= 0 ? distance(static_cast<int>(a), now_[a]) : 0;
      if (agents[a].fixed) {
        next_[a] = now_[a];
        on_next_[static_cast<std::size_t>(now_[a])] = static_cast<int>(a);
      }
    }
    for (const int a : order) {
      if (next_[static_cast<std::size_t>(a)] < 0) push(a, -1);
    }
    for (std::size_t a = 0; a < n; ++a) {
      if (goal_[a] >= 0 && distance(static_cast<int>(a), next_[a]) >= before[a]) {
        longest_wait_ = std::max(longest_wait_, ++waiting_[a]);
      } else {
        waiting_[a] = 0;
      }
    }
    for (std::size_t a = 0; a < n; ++a) {
      on_now_[static_cast<std::size_t>(now_[a])] = -1;
      on_next_[static_cast<std::size_t>(next_[a])] = -1;
    }
    for (std::size_t a = 0; a < n; ++a) {
      now_[a] = next_[a];
      next_[a] = -1;
      on_now_[static_cast<std::size_t>(now_[a])] = static_cast<int>(a);
      w.paths[a].push_back(map_.cell_of(now_[a]));
      if (advance(a)) {
        priority_[a] = base_[a];
      } else if (goal_[a] >= 0) {
        priority_[a] += 1.0;
      } else {
        priority_[a] = base_[a];
      }
    }
    ++steps_planned_;
  }
  for (std::size_t a = 0; a < n; ++a) on_now_[static_cast<std::size_t>(now_[a])] = -1;
  w.waiting = waiting_;
  return w;
}

}  // namespace swarm::planner::traffic
