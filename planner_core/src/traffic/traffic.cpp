#include "swarm/planner/traffic/traffic.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "swarm/planner/grid/rng.hpp"
#include "swarm/planner/mapf/pibt_swap.hpp"
#include "swarm/planner/mapf/solver.hpp"

namespace swarm::planner::traffic {

namespace {
// Above this many cached distances (256 MB of ints) the tables of goals no robot heads for go.
constexpr std::size_t kMaxTableCells = std::size_t{64} << 20;
// A rescue's search budget, in LaCAM's polls of its stop condition (one per 64 of its steps): a
// count, not a time, so that a run stays the same under any load.
constexpr int kRescuePolls = 512;
}  // namespace

int rescue_polls(std::size_t robots) {
  const std::size_t r = std::max<std::size_t>(robots, 1);
  return static_cast<int>(std::clamp<std::size_t>(kRescueConfigEntries / (64 * r), 1, kRescuePolls));
}

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
  if (changed) forget_distances();
  // A rescue goes on while its region stays free (an explored map only grows, mostly).
  for (std::size_t i = 0; i < region_.size(); ++i) {
    if (region_[i] && !free_[i]) {
      end_rescue();
      return;
    }
  }
}

void Planner::end_rescue() {
  rescue_.clear();
  region_.clear();
}

void Planner::forget_distances() {
  tables_.clear();
  table_cells_ = 0;
  // A robot's best distance was measured on the old distances: a detour round a new wall or a dead
  // robot would otherwise count as no progress until it got back under that figure.
  std::fill(stall_goal_.begin(), stall_goal_.end(), -1);
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
    if (passable(ci) && (region_.empty() || !region_[static_cast<std::size_t>(ci)])) add(ci);  // a rescue's region is its own
  });
  const auto better = [](const Candidate& x, const Candidate& y) {
    if (x.dist != y.dist) return x.dist < y.dist;
    if (x.occupied != y.occupied) return x.occupied < y.occupied;
    return x.coin < y.coin;
  };
  for (std::size_t i = 1; i < n; ++i) {  // insertion sort: at most 9 cells
    for (std::size_t j = i; j > 0 && better(cand[j], cand[j - 1]); --j) std::swap(cand[j], cand[j - 1]);
  }
  // Head-on in a corridor: a backs away, its partner following into its cell, until they reach a
  // branch where they can trade places (LaCAM*'s swap, Okumura IJCAI 2023).
  const int swapper = swap_partner(a, cand[0].cell);
  if (swapper >= 0) std::reverse(cand.begin(), cand.begin() + static_cast<std::ptrdiff_t>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const int v = cand[k].cell;
    const auto uv = static_cast<std::size_t>(v);
    if (on_next_[uv] >= 0) continue;                         // taken by a robot of higher priority
    if (parent >= 0 && v == now_[static_cast<std::size_t>(parent)]) continue;  // would swap with it
    on_next_[uv] = a;
    next_[ua] = v;
    const int b = on_now_[uv];
    if (b >= 0 && b != a && next_[static_cast<std::size_t>(b)] < 0 && !push(b, a)) continue;
    const auto us = static_cast<std::size_t>(swapper);
    if (k == 0 && swapper >= 0 && next_[us] < 0 && on_next_[static_cast<std::size_t>(here)] < 0) {
      next_[us] = here;
      on_next_[static_cast<std::size_t>(here)] = swapper;
    }
    return true;
  }
  next_[ua] = here;
  on_next_[static_cast<std::size_t>(here)] = a;
  return false;
}

int Planner::side_ways(int cell, int excluded, int& other) const {
  int count = 0;
  motion_.for_each_neighbour(map_, map_.cell_of(cell), [&](Cell c, double) {
    const int nb = map_.index(c);
    if (nb == excluded || !passable(nb)) return;
    // A robot without a goal resting at the end of a dead end leaves no room there.
    const int who = on_now_[static_cast<std::size_t>(nb)];
    if (who >= 0 && goal_[static_cast<std::size_t>(who)] < 0 && dead_end(nb)) return;
    ++count;
    other = nb;
  });
  return count;
}

bool Planner::dead_end(int cell) const {
  int open = 0;
  motion_.for_each_neighbour(map_, map_.cell_of(cell), [&](Cell c, double) { open += passable(map_.index(c)) ? 1 : 0; });
  return open == 1;
}

bool Planner::swap_required(int pusher, int puller, int at_pusher, int at_puller) {
  const int goal = goal_[static_cast<std::size_t>(pusher)];
  if (goal < 0 || goal_[static_cast<std::size_t>(puller)] < 0) return false;
  // Bound for one cell (a drop, a gathering point), neither has to pass the other: the one ahead
  // goes first. Trading places gains nothing, and each robot backing up for the other kept two
  // robots stepping in and out of one cell for as long as the cell was taken.
  if (goal_[static_cast<std::size_t>(puller)] == goal) return false;
  return mapf::swap_required(pusher, puller, at_pusher, at_puller,
                             [this](int cell, int excluded, int& other) { return side_ways(cell, excluded, other); },
                             [this](int a, int cell) { return distance(a, cell); });
}

bool Planner::swap_possible(int at_pusher, int at_puller) const {
  return mapf::swap_possible(at_pusher, at_puller,
                             [this](int cell, int excluded, int& other) { return side_ways(cell, excluded, other); });
}

int Planner::swap_partner(int a, int best) {
  const int here = now_[static_cast<std::size_t>(a)];
  if (best == here || goal_[static_cast<std::size_t>(a)] < 0) return -1;
  const int b = on_now_[static_cast<std::size_t>(best)];
  if (b >= 0 && next_[static_cast<std::size_t>(b)] < 0 && swap_required(a, b, here, best) && swap_possible(best, here)) {
    return b;
  }
  // Clearing: a robot beside a that must pass it first.
  int partner = -1;
  motion_.for_each_neighbour(map_, map_.cell_of(here), [&](Cell c, double) {
    const int nb = map_.index(c);
    const int k = on_now_[static_cast<std::size_t>(nb)];
    if (partner >= 0 || k < 0 || nb == best || !passable(nb)) return;
    if (swap_required(k, a, here, best) && swap_possible(best, here)) partner = k;
  });
  return partner;
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
    forget_distances();
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
    stall_goal_.assign(n, -1);
    nearest_.assign(n, 0);
    stalled_.assign(n, 0);
  }
  // A rescue is driven on only from where it left its robots, none of them fixed since, and with
  // no other robot in its region (a plan held and started again may leave one there).
  for (std::size_t a = 0; a < n && !rescue_.empty(); ++a) {
    const auto& path = rescue_[a];
    if (path.empty()) {
      if (region_[static_cast<std::size_t>(now_[a])]) end_rescue();
      continue;
    }
    if (agents[a].fixed || path[std::min(rescue_step_, path.size() - 1)] != now_[a]) end_rescue();
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
    // A rescue's robots take their plan's step; the others, kept out of its region, PIBT's.
    if (!rescue_.empty()) ++rescue_step_;
    for (std::size_t a = 0; a < rescue_.size(); ++a) {
      if (rescue_[a].empty()) continue;
      next_[a] = rescue_[a][std::min(rescue_step_, rescue_[a].size() - 1)];
      on_next_[static_cast<std::size_t>(next_[a])] = static_cast<int>(a);
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
    if (!rescue_.empty()) {
      if (rescue_step_ >= rescue_until_) end_rescue();
    } else {
      watch_for_stalls(agents);
    }
    ++steps_planned_;
  }
  for (std::size_t a = 0; a < n; ++a) on_now_[static_cast<std::size_t>(now_[a])] = -1;
  w.waiting = waiting_;
  return w;
}

void Planner::watch_for_stalls(const std::vector<Agent>& agents) {
  std::vector<int> stalled, with_goal;
  bool progress = false;
  // After rescues that found no plan (none may exist: robots on a tree cannot always trade places),
  // the next waits twice as long.
  const int backoff = 1 << std::min(failed_in_a_row_, 6);
  for (std::size_t a = 0; a < agents.size(); ++a) {
    if (goal_[a] < 0 || agents[a].fixed) {
      stall_goal_[a] = -1;
      stalled_[a] = 0;
      continue;
    }
    with_goal.push_back(static_cast<int>(a));
    const int d = distance(static_cast<int>(a), now_[a]);
    if (goal_[a] != stall_goal_[a] || d < nearest_[a]) {
      progress = true;
      stall_goal_[a] = goal_[a];
      nearest_[a] = d;
      stalled_[a] = 0;
    } else if (++stalled_[a] >= kStallSteps * backoff) {
      stalled.push_back(static_cast<int>(a));
    }
  }
  no_progress_ = progress || with_goal.empty() ? 0 : no_progress_ + 1;
  // No robot nearer its goal than it ever was for a while: PIBT is stuck (standing, or pushing the
  // same robots back and forth), and every robot with a goal is stalled.
  if (no_progress_ >= kNoProgressSteps * backoff) stalled = with_goal;
  if (stalled.empty()) return;
  // Counted again from here, so a rescue that failed is tried again only after as long a stall.
  std::fill(stalled_.begin(), stalled_.end(), 0);
  no_progress_ = 0;
  if (plan_rescue(agents, stalled)) {
    ++rescues_;
    failed_in_a_row_ = 0;
  } else {
    ++rescues_failed_;
    ++failed_in_a_row_;  // the next tries a region twice as wide
  }
}

bool Planner::plan_rescue(const std::vector<Agent>& agents, const std::vector<int>& stalled) {
  // The region: the passable cells within `radius` moves of a stalled robot (wider after each
  // failure), as a graph under the robots' motion model (4- or 8-connected), so that LaCAM moves
  // the robots as PIBT does. Its robots are planned in it; the others keep out of it meanwhile.
  // LaCAM keeps a distance table over the region for each of its robots, so the region stops
  // growing (nearest cells first) once cells x robots reach kRescueTableEntries.
  const int radius = kRescueRadius << std::min(failed_in_a_row_, 12);
  std::vector<int> depth(map_.size(), -1);
  std::vector<int> cell_of;  // the region's cells, in the order they were reached
  std::size_t robots = 0;    // the robots standing in it that may move
  for (const int a : stalled) {
    const int c = now_[static_cast<std::size_t>(a)];
    if (depth[static_cast<std::size_t>(c)] < 0) {
      depth[static_cast<std::size_t>(c)] = 0;
      cell_of.push_back(c);
      ++robots;
    }
  }
  bool full = false;
  for (std::size_t head = 0; head < cell_of.size() && !full; ++head) {
    const int c = cell_of[head];
    if (depth[static_cast<std::size_t>(c)] >= radius) continue;
    motion_.for_each_neighbour(map_, map_.cell_of(c), [&](Cell nc, double) {
      const int ni = map_.index(nc);
      if (full || !passable(ni) || depth[static_cast<std::size_t>(ni)] >= 0) return;
      depth[static_cast<std::size_t>(ni)] = depth[static_cast<std::size_t>(c)] + 1;
      cell_of.push_back(ni);
      const int who = on_now_[static_cast<std::size_t>(ni)];
      if (who >= 0 && !agents[static_cast<std::size_t>(who)].fixed) ++robots;
      full = (cell_of.size() + 1) * robots > kRescueTableEntries;
    });
  }
  std::vector<int> vertex_of(map_.size(), -1);
  for (std::size_t v = 0; v < cell_of.size(); ++v) vertex_of[static_cast<std::size_t>(cell_of[v])] = static_cast<int>(v);
  std::vector<mapf::Edge> edges;
  for (std::size_t v = 0; v < cell_of.size(); ++v) {
    motion_.for_each_neighbour(map_, map_.cell_of(cell_of[v]), [&](Cell c, double) {
      const int u = vertex_of[static_cast<std::size_t>(map_.index(c))];
      if (u > static_cast<int>(v)) edges.push_back({static_cast<int>(v), u});
    });
  }
  mapf::Instance in;
  in.graph = mapf::Graph(static_cast<int>(cell_of.size()), std::move(edges));
  const mapf::Graph& g = *in.graph;

  // Its robots, the stalled first. Goals: for a robot with one, the cell of the region it can get to
  // that is nearest its goal (its goal, when that lies inside); for one without, the nearest cell.
  // No two the same: a robot whose best cell another has taken gets its next best.
  std::vector<int> planned = stalled;
  for (std::size_t a = 0; a < agents.size(); ++a) {
    const int v = vertex_of[static_cast<std::size_t>(now_[a])];
    if (v >= 0 && !agents[a].fixed && std::find(stalled.begin(), stalled.end(), static_cast<int>(a)) == stalled.end()) {
      planned.push_back(static_cast<int>(a));
    }
  }
  std::vector<bool> taken(cell_of.size(), false);
  for (const int a : planned) {
    const auto ua = static_cast<std::size_t>(a);
    std::vector<int> reach{vertex_of[static_cast<std::size_t>(now_[ua])]};  // breadth-first within the region
    std::vector<int> hops(cell_of.size(), -1);
    hops[static_cast<std::size_t>(reach.front())] = 0;
    for (std::size_t head = 0; head < reach.size(); ++head) {
      for (const int u : g.neighbours(reach[head])) {
        if (hops[static_cast<std::size_t>(u)] >= 0) continue;
        hops[static_cast<std::size_t>(u)] = hops[static_cast<std::size_t>(reach[head])] + 1;
        reach.push_back(u);
      }
    }
    int best = -1, best_d = 0;
    for (const int v : reach) {  // in order of hops: the first of equal distance is the nearest
      if (taken[static_cast<std::size_t>(v)]) continue;
      const int d = goal_[ua] >= 0 ? distance(a, cell_of[static_cast<std::size_t>(v)]) : 0;
      if (best < 0 || d < best_d) {
        best = v;
        best_d = d;
      }
      if (goal_[ua] < 0) break;
    }
    if (best < 0) return false;  // more robots than cells
    taken[static_cast<std::size_t>(best)] = true;
    in.starts.push_back(mapf::vertex_cell(reach.front()));
    in.goals.push_back(mapf::vertex_cell(best));
  }
  mapf::SolverConfig cfg;
  cfg.kind = mapf::SolverKind::Lacam;
  cfg.lacam.seed = mix_seed({config_.seed, steps_planned_});
  int polls = 0;
  mapf::StopCondition stop;
  const int budget = rescue_polls(planned.size());
  stop.predicate = [&polls, budget] { return ++polls > budget; };
  const mapf::Result r = mapf::solve(in, cfg, stop);
  if (r.status != mapf::Status::Solved) return false;
  rescue_.assign(agents.size(), {});
  for (std::size_t k = 0; k < planned.size(); ++k) {
    auto& path = rescue_[static_cast<std::size_t>(planned[k])];
    for (const Cell& v : r.paths[k]) path.push_back(cell_of[static_cast<std::size_t>(v.x)]);
  }
  region_.assign(map_.size(), false);
  for (const int c : cell_of) region_[static_cast<std::size_t>(c)] = true;
  // Driven only until every stalled robot has come nearer its goal than it ever was: it is past
  // what held it, and PIBT takes over again (LaCAM's first plan is far from short: among 1,000
  // robots one stalled 46 steps from its goal was planned 263 steps there).
  // A plan that brings none of them nearer (one pushed back farther than the region reaches) is no
  // rescue: it counts as failed, and the next region is wider.
  rescue_until_ = 0;
  bool helps = false;
  for (const int a : stalled) {
    const auto& path = rescue_[static_cast<std::size_t>(a)];
    std::size_t t = 0;
    while (t + 1 < path.size() && distance(a, path[t]) >= nearest_[static_cast<std::size_t>(a)]) ++t;
    helps = helps || distance(a, path[t]) < nearest_[static_cast<std::size_t>(a)];
    rescue_until_ = std::max(rescue_until_, t);
  }
  if (!helps) {
    end_rescue();
    return false;
  }
  rescue_step_ = 0;
  return true;
}

}  // namespace swarm::planner::traffic
