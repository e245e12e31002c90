#include "swarm/planner/coverage/cover_tours.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "swarm/planner/grid/motion.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {
namespace {

constexpr std::int64_t kFar = std::int64_t{1} << 30;  // no path: never worth taking

// Breadth-first search through Free cells (4-connected) from one cell: the moves to every cell
// (-1: not reached) and, per cell, its neighbour one move closer to the source.
struct Search {
  std::vector<int> moves;
  std::vector<int> toward;
};

Search search_from(const OccupancyGrid& map, int source) {
  Search s{std::vector<int>(map.size(), -1), std::vector<int>(map.size(), -1)};
  std::vector<int> queue{source};
  s.moves[static_cast<std::size_t>(source)] = 0;
  const MotionModel four = MotionModel::four();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int ci = queue[head];
    four.for_each_neighbour(map, map.cell_of(ci), [&](Cell n, double) {
      const auto ni = static_cast<std::size_t>(map.index(n));
      if (s.moves[ni] >= 0) return;
      s.moves[ni] = s.moves[static_cast<std::size_t>(ci)] + 1;
      s.toward[ni] = ci;
      queue.push_back(static_cast<int>(ni));
    });
  }
  return s;
}

// Moves between the robots' cells and the targets. Nodes 0..robots-1 are the robots, then the
// targets; a distance is always to a target.
class Distances {
 public:
  Distances(std::size_t robots, std::size_t targets)
      : robots_(robots), targets_(targets), to_(targets * (robots + targets), kFar) {}
  void set(std::size_t node, std::size_t target, std::int64_t moves) { to_[target * (robots_ + targets_) + node] = moves; }
  // From a node to a target; node < 0: nowhere (an empty tail).
  [[nodiscard]] std::int64_t operator()(int node, int target) const {
    return to_[static_cast<std::size_t>(target) * (robots_ + targets_) + static_cast<std::size_t>(node)];
  }
  [[nodiscard]] int node_of_target(int target) const { return static_cast<int>(robots_) + target; }

 private:
  std::size_t robots_, targets_;
  std::vector<std::int64_t> to_;
};

// The robots' target lists and their lengths in moves.
struct Tours {
  std::vector<std::vector<int>> order;
  std::vector<std::int64_t> length;
};

// The objective: the longest route, then how many routes are that long, then the sum of routes.
// The count lets the search make progress on a plateau of the longest: each route brought below it
// is a step towards lowering it.
struct Score {
  std::int64_t longest = 0;
  int at_longest = 0;
  std::int64_t sum = 0;
  bool operator<(const Score& o) const {
    if (longest != o.longest) return longest < o.longest;
    return at_longest != o.at_longest ? at_longest < o.at_longest : sum < o.sum;
  }
};

// The longest among some routes, and how many are that long.
struct Longest {
  std::int64_t length = 0;
  int count = 0;
  void add(std::int64_t l) {
    if (l > length) length = l, count = 0;
    count += l == length ? 1 : 0;
  }
  // With routes of lengths `a` and `b` (-1: none) added, and the sum of all routes.
  [[nodiscard]] Score with(std::int64_t a, std::int64_t b, std::int64_t sum) const {
    Longest l = *this;
    if (a >= 0) l.add(a);
    if (b >= 0) l.add(b);
    return {l.length, l.count, sum};
  }
};

class Solver {
 public:
  Solver(const Distances& d, std::size_t robots, std::size_t targets, const std::vector<int>& starts)
      : d_(d), robots_(static_cast<int>(robots)), targets_(static_cast<int>(targets)), start_(robots, 0) {
    for (std::size_t r = 0; r < robots && r < starts.size(); ++r) start_[r] = std::max(0, starts[r]);
  }

  // Every robot with no target: its length is its start.
  [[nodiscard]] Tours empty() const {
    return {std::vector<std::vector<int>>(static_cast<std::size_t>(robots_)), start_};
  }

  // The node before position `p` of robot r's list, and the target after it (-1: none).
  [[nodiscard]] int before(const Tours& t, int r, std::size_t p) const {
    return p == 0 ? r : d_.node_of_target(t.order[static_cast<std::size_t>(r)][p - 1]);
  }
  [[nodiscard]] static int after(const Tours& t, int r, std::size_t p) {
    const auto& o = t.order[static_cast<std::size_t>(r)];
    return p + 1 < o.size() ? o[p + 1] : -1;
  }
  // Moves from `from` to target `a` and on to target `b` (-1: the route ends), less from -> b.
  [[nodiscard]] std::int64_t detour(int from, int a, int b) const {
    const std::int64_t in = d_(from, a);
    return b < 0 ? in : in + d_(d_.node_of_target(a), b) - d_(from, b);
  }

  [[nodiscard]] Tours nearest_neighbour() const {
    Tours t = empty();
    std::vector<std::uint8_t> taken(static_cast<std::size_t>(targets_), 0), done(static_cast<std::size_t>(robots_), 0);
    std::vector<int> at(static_cast<std::size_t>(robots_));
    std::iota(at.begin(), at.end(), 0);
    for (int left = targets_; left > 0;) {
      int r = -1;
      for (int k = 0; k < robots_; ++k) {
        if (!done[static_cast<std::size_t>(k)] && (r < 0 || t.length[static_cast<std::size_t>(k)] < t.length[static_cast<std::size_t>(r)])) r = k;
      }
      if (r < 0) break;  // the rest reach no target left
      int best = -1;
      for (int g = 0; g < targets_; ++g) {
        if (taken[static_cast<std::size_t>(g)] || d_(at[static_cast<std::size_t>(r)], g) >= kFar) continue;
        if (best < 0 || d_(at[static_cast<std::size_t>(r)], g) < d_(at[static_cast<std::size_t>(r)], best)) best = g;
      }
      if (best < 0) {
        done[static_cast<std::size_t>(r)] = 1;
        continue;
      }
      taken[static_cast<std::size_t>(best)] = 1;
      t.length[static_cast<std::size_t>(r)] += d_(at[static_cast<std::size_t>(r)], best);
      t.order[static_cast<std::size_t>(r)].push_back(best);
      at[static_cast<std::size_t>(r)] = d_.node_of_target(best);
      --left;
    }
    return t;
  }

  [[nodiscard]] Tours farthest_insertion() const {
    Tours t = empty();
    std::vector<std::pair<std::int64_t, int>> by_reach;  // (-nearest robot, target)
    for (int g = 0; g < targets_; ++g) {
      std::int64_t nearest = kFar;
      for (int r = 0; r < robots_; ++r) nearest = std::min(nearest, d_(r, g));
      by_reach.emplace_back(-nearest, g);
    }
    std::sort(by_reach.begin(), by_reach.end());
    for (const auto& [unused, g] : by_reach) {
      std::int64_t best_len = kFar, best_add = kFar;
      int best_r = -1;
      std::size_t best_p = 0;
      for (int r = 0; r < robots_; ++r) {
        const auto& o = t.order[static_cast<std::size_t>(r)];
        for (std::size_t p = 0; p <= o.size(); ++p) {
          const int from = before(t, r, p);
          const int next = p < o.size() ? o[p] : -1;
          const std::int64_t add = detour(from, g, next);
          const std::int64_t len = t.length[static_cast<std::size_t>(r)] + add;
          if (len < best_len || (len == best_len && add < best_add)) best_len = len, best_add = add, best_r = r, best_p = p;
        }
      }
      if (best_r < 0 || best_add >= kFar) continue;
      auto& o = t.order[static_cast<std::size_t>(best_r)];
      o.insert(o.begin() + static_cast<std::ptrdiff_t>(best_p), g);
      t.length[static_cast<std::size_t>(best_r)] = best_len;
    }
    return t;
  }

  [[nodiscard]] static Score score(const Tours& t) {
    std::int64_t sum = 0;
    for (const std::int64_t l : t.length) sum += l;
    return longest_but(t, -1, -1).with(-1, -1, sum);
  }

  // The longest route among all but robots a and b.
  [[nodiscard]] static Longest longest_but(const Tours& t, int a, int b) {
    Longest most;
    for (std::size_t r = 0; r < t.length.size(); ++r) {
      if (static_cast<int>(r) != a && static_cast<int>(r) != b) most.add(t.length[r]);
    }
    return most;
  }

  // 2-opt within each route: reversing the stretch p..q when that shortens the route.
  bool two_opt(Tours& t, int& taken) const {
    bool any = false;
    for (int r = 0; r < robots_; ++r) {
      auto& o = t.order[static_cast<std::size_t>(r)];
      for (bool again = true; again;) {
        again = false;
        for (std::size_t p = 0; p + 1 < o.size(); ++p) {
          const int from = before(t, r, p);
          for (std::size_t q = p + 1; q < o.size(); ++q) {
            const int next = after(t, r, q);
            const int first = d_.node_of_target(o[p]), last = d_.node_of_target(o[q]);
            const std::int64_t old_cost = d_(from, o[p]) + (next < 0 ? 0 : d_(last, next));
            const std::int64_t new_cost = d_(from, o[q]) + (next < 0 ? 0 : d_(first, next));
            if (new_cost >= old_cost) continue;
            std::reverse(o.begin() + static_cast<std::ptrdiff_t>(p), o.begin() + static_cast<std::ptrdiff_t>(q) + 1);
            t.length[static_cast<std::size_t>(r)] += new_cost - old_cost;
            again = any = true;
            ++taken;
            break;
          }
          if (again) break;
        }
      }
    }
    return any;
  }

  // 2-opt and exchanges until neither improves (or `stop`).
  void improve(Tours& t, int& taken, const std::function<bool()>& stop) const {
    for (bool improved = true; improved && !(stop && stop());) {
      improved = two_opt(t, taken);
      improved = exchange(t, taken, stop) || improved;
    }
  }

  // Ruin and recreate (Schrimpf, Schneider, Stamm-Wilbrandt and Dueck, J. Comput. Phys. 2000):
  // the local search stops where no single move or swap helps, and a route's last targets are
  // often placed badly for want of a joint move. Each round takes `ruined` targets out, half of
  // them from the longest route, puts each back where the score grows least, searches locally
  // again, and keeps the result unless it scores worse: a min-max score has wide plateaus, and a
  // walk along one finds the way down that strict improvement stops short of.
  void ruin_and_recreate(Tours& best, int rounds, std::size_t ruined, Rng& rng, int& taken,
                         const std::function<bool()>& stop) const {
    for (int round = 0; round < rounds && !(stop && stop()); ++round) {
      Tours t = best;
      std::vector<int> out;
      const auto take_from = [&](int r) {
        auto& o = t.order[static_cast<std::size_t>(r)];
        const std::size_t i = static_cast<std::size_t>(rng.below(o.size()));
        t.length[static_cast<std::size_t>(r)] -= removal(t, r, i);
        out.push_back(o[i]);
        o.erase(o.begin() + static_cast<std::ptrdiff_t>(i));
      };
      const auto longest = static_cast<int>(std::max_element(t.length.begin(), t.length.end()) - t.length.begin());
      while (out.size() < ruined / 2 && !t.order[static_cast<std::size_t>(longest)].empty()) take_from(longest);
      std::size_t left = 0;
      for (const auto& o : t.order) left += o.size();
      while (out.size() < ruined && left > 0) {
        const int r = static_cast<int>(rng.below(static_cast<std::uint64_t>(robots_)));
        if (t.order[static_cast<std::size_t>(r)].empty()) continue;
        take_from(r);
        --left;
      }
      for (std::size_t i = out.size(); i > 1; --i) std::swap(out[i - 1], out[static_cast<std::size_t>(rng.below(i))]);
      for (const int g : out) insert_best(t, g);
      improve(t, taken, stop);
      if (!(score(best) < score(t))) best = std::move(t);
    }
  }

  // Moving one target to another route (or its best place in its own), and swapping two targets
  // of different routes, whenever the score drops.
  bool exchange(Tours& t, int& taken, const std::function<bool()>& stop) const {
    bool any = false;
    for (int a = 0; a < robots_; ++a) {
      for (std::size_t i = 0; i < t.order[static_cast<std::size_t>(a)].size(); ++i) {
        if (stop && (i % 32) == 0 && stop()) return any;
        if (relocate(t, a, i) || swap(t, a, i)) {
          any = true;
          ++taken;
        }
      }
    }
    return any;
  }

 private:
  // Target g where the score grows least; left out if no route reaches it (cannot happen: it was
  // on one).
  void insert_best(Tours& t, int g) const {
    const Score now = score(t);
    Score best{kFar, 0, kFar};
    int best_r = -1;
    std::size_t best_p = 0;
    for (int r = 0; r < robots_; ++r) {
      const auto& o = t.order[static_cast<std::size_t>(r)];
      const Longest rest = longest_but(t, r, r);
      for (std::size_t p = 0; p <= o.size(); ++p) {
        const std::int64_t add = detour(before(t, r, p), g, p < o.size() ? o[p] : -1);
        if (add >= kFar) continue;
        const Score s = rest.with(t.length[static_cast<std::size_t>(r)] + add, -1, now.sum + add);
        if (s < best) best = s, best_r = r, best_p = p;
      }
    }
    if (best_r < 0) return;
    auto& o = t.order[static_cast<std::size_t>(best_r)];
    t.length[static_cast<std::size_t>(best_r)] += detour(before(t, best_r, best_p), g, best_p < o.size() ? o[best_p] : -1);
    o.insert(o.begin() + static_cast<std::ptrdiff_t>(best_p), g);
  }

  // Removing position i of route a saves this many moves.
  [[nodiscard]] std::int64_t removal(const Tours& t, int a, std::size_t i) const {
    return detour(before(t, a, i), t.order[static_cast<std::size_t>(a)][i], after(t, a, i));
  }

  bool relocate(Tours& t, int a, std::size_t i) const {
    const Score now = score(t);
    const int g = t.order[static_cast<std::size_t>(a)][i];
    const std::int64_t la = t.length[static_cast<std::size_t>(a)] - removal(t, a, i);
    Score best = now;
    int best_b = -1;
    std::size_t best_p = 0;
    for (int b = 0; b < robots_; ++b) {
      if (b == a) continue;
      const auto& o = t.order[static_cast<std::size_t>(b)];
      const Longest rest = longest_but(t, a, b);
      for (std::size_t p = 0; p <= o.size(); ++p) {
        const std::int64_t add = detour(before(t, b, p), g, p < o.size() ? o[p] : -1);
        if (add >= kFar) continue;
        const std::int64_t lb = t.length[static_cast<std::size_t>(b)] + add;
        const Score s = rest.with(la, lb, now.sum - t.length[static_cast<std::size_t>(a)] -
                                              t.length[static_cast<std::size_t>(b)] + la + lb);
        if (s < best) best = s, best_b = b, best_p = p;
      }
    }
    if (best_b < 0) return false;
    auto& from = t.order[static_cast<std::size_t>(a)];
    from.erase(from.begin() + static_cast<std::ptrdiff_t>(i));
    t.length[static_cast<std::size_t>(a)] = la;
    auto& to = t.order[static_cast<std::size_t>(best_b)];
    to.insert(to.begin() + static_cast<std::ptrdiff_t>(best_p), g);
    t.length[static_cast<std::size_t>(best_b)] += detour(before(t, best_b, best_p), g, after(t, best_b, best_p));
    return true;
  }

  // Route a's target at i and route b's at j trade places.
  bool swap(Tours& t, int a, std::size_t i) const {
    if (i >= t.order[static_cast<std::size_t>(a)].size()) return false;
    const Score now = score(t);
    const int g = t.order[static_cast<std::size_t>(a)][i];
    const int pa = before(t, a, i), na = after(t, a, i);
    auto replaced = [&](int from, int old_target, int new_target, int next) {
      const std::int64_t out = d_(from, old_target) + (next < 0 ? 0 : d_(d_.node_of_target(old_target), next));
      const std::int64_t in = d_(from, new_target) + (next < 0 ? 0 : d_(d_.node_of_target(new_target), next));
      return in - out;
    };
    Score best = now;
    int best_b = -1;
    std::size_t best_j = 0;
    for (int b = 0; b < robots_; ++b) {
      if (b == a) continue;
      const auto& o = t.order[static_cast<std::size_t>(b)];
      const Longest rest = longest_but(t, a, b);
      for (std::size_t j = 0; j < o.size(); ++j) {
        const int u = o[j];
        const std::int64_t da = replaced(pa, g, u, na);
        const std::int64_t db = replaced(before(t, b, j), u, g, after(t, b, j));
        if (da >= kFar / 2 || db >= kFar / 2) continue;
        const std::int64_t la = t.length[static_cast<std::size_t>(a)] + da;
        const std::int64_t lb = t.length[static_cast<std::size_t>(b)] + db;
        const Score s = rest.with(la, lb, now.sum + da + db);
        if (s < best) best = s, best_b = b, best_j = j;
      }
    }
    if (best_b < 0) return false;
    auto& ob = t.order[static_cast<std::size_t>(best_b)];
    const int u = ob[best_j];
    t.length[static_cast<std::size_t>(a)] += replaced(pa, g, u, na);
    t.length[static_cast<std::size_t>(best_b)] += replaced(before(t, best_b, best_j), u, g, after(t, best_b, best_j));
    t.order[static_cast<std::size_t>(a)][i] = u;
    ob[best_j] = g;
    return true;
  }

  const Distances& d_;
  int robots_, targets_;
  std::vector<std::int64_t> start_;
};

}  // namespace

std::size_t longest_moves(const std::vector<std::vector<Cell>>& routes) {
  std::size_t most = 0;
  for (const auto& r : routes) most = std::max(most, r.empty() ? 0 : r.size() - 1);
  return most;
}

CoverTours cover_tours(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                       const std::vector<Cell>& robots, const CoverToursConfig& config,
                       const std::function<bool()>& stop) {
  const auto t0 = std::chrono::steady_clock::now();
  CoverTours out;
  out.owner.assign(map.size(), -1);
  out.region_cells.assign(robots.size(), 0);
  out.routes.resize(robots.size());
  for (std::size_t r = 0; r < robots.size(); ++r) out.routes[r] = {robots[r]};
  std::vector<int> candidates;
  for (std::size_t i = 0; i < map.size() && i < cells.size(); ++i) {
    if (cells[i] && map.at(static_cast<int>(i)) == CellState::Free) candidates.push_back(static_cast<int>(i));
  }
  if (robots.empty() || candidates.size() > config.max_targets) return out;

  // One search per candidate target; those no robot reaches are left out.
  std::vector<int> targets;
  std::vector<std::vector<int>> moves;  // per kept target: moves from each robot, then each candidate
  for (const int c : candidates) {
    const Search s = search_from(map, c);
    std::vector<int> row;
    bool reached = false;
    for (const Cell& r : robots) {
      const int m = map.in_bounds(r) ? s.moves[static_cast<std::size_t>(map.index(r))] : -1;
      reached = reached || m >= 0;
      row.push_back(m);
    }
    for (const int other : candidates) row.push_back(s.moves[static_cast<std::size_t>(other)]);
    if (!reached) {
      ++out.unreachable;
      continue;
    }
    targets.push_back(c);
    moves.push_back(std::move(row));
  }
  out.targets = targets.size();
  out.solved = true;
  if (targets.empty()) {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }
  // Index of each candidate among the kept targets.
  std::vector<int> kept_index(candidates.size(), -1);
  for (std::size_t k = 0, j = 0; k < candidates.size() && j < targets.size(); ++k) {
    if (candidates[k] == targets[j]) kept_index[k] = static_cast<int>(j++);
  }
  Distances d(robots.size(), targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    for (std::size_t r = 0; r < robots.size(); ++r) {
      if (moves[t][r] >= 0) d.set(r, t, moves[t][r]);
    }
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const int j = kept_index[k];
      if (j >= 0 && moves[t][robots.size() + k] >= 0) d.set(robots.size() + static_cast<std::size_t>(j), t, moves[t][robots.size() + k]);
    }
  }

  const Solver solver(d, robots.size(), targets.size(), config.starts);
  std::vector<Tours> tried = {solver.nearest_neighbour(), solver.farthest_insertion()};
  for (Tours& t : tried) solver.improve(t, out.improvements, stop);
  Tours best = Solver::score(tried[1]) < Solver::score(tried[0]) ? tried[1] : tried[0];
  Rng rng(config.seed);
  const double squared = static_cast<double>(targets.size()) * static_cast<double>(targets.size());
  const int rounds = static_cast<int>(std::min<double>(config.ruin_rounds, config.ruin_work / squared));
  solver.ruin_and_recreate(best, rounds, std::min(config.ruined_targets, targets.size()), rng, out.improvements, stop);
  out.stopped = stop && stop();

  // The cell routes: shortest paths between consecutive targets, skipping a target its route has
  // already passed.
  for (std::size_t r = 0; r < robots.size(); ++r) {
    std::vector<Cell>& route = out.routes[r];
    std::vector<std::uint8_t> passed(map.size(), 0);
    passed[static_cast<std::size_t>(map.index(robots[r]))] = 1;
    for (const int t : best.order[r]) {
      const int goal = targets[static_cast<std::size_t>(t)];
      out.owner[static_cast<std::size_t>(goal)] = static_cast<int>(r);
      ++out.region_cells[r];
      if (passed[static_cast<std::size_t>(goal)]) continue;
      const Search s = search_from(map, goal);
      if (s.moves[static_cast<std::size_t>(map.index(route.back()))] < 0) continue;  // never: d() was finite
      for (int at = map.index(route.back()); at != goal;) {
        at = s.toward[static_cast<std::size_t>(at)];
        route.push_back(map.cell_of(at));
        passed[static_cast<std::size_t>(at)] = 1;
      }
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace swarm::planner
