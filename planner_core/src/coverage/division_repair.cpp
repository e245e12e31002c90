#include "division_repair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <tuple>

namespace swarm::planner::detail {
namespace {

// Per piece, the shares rounded to whole cells that add up to the piece's cells: every share
// rounded down, then one more cell each to the largest fractions (ties: the lower robot index).
std::vector<int> whole_targets(const DarpSpace& s) {
  const int n = s.robots();
  std::vector<int> piece_cells(s.pieces, 0);
  for (int p : s.piece) ++piece_cells[p];
  std::vector<int> target(n);
  std::vector<int> left = piece_cells;
  for (int r = 0; r < n; ++r) {
    target[r] = static_cast<int>(std::floor(s.shares[r] + 1e-9));
    left[s.robot_piece[r]] -= target[r];
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return s.shares[a] - std::floor(s.shares[a] + 1e-9) > s.shares[b] - std::floor(s.shares[b] + 1e-9);
  });
  for (int r : order) {
    if (left[s.robot_piece[r]] <= 0) continue;
    ++target[r];
    --left[s.robot_piece[r]];
  }
  return target;
}

// Articulation points of the subgraphs of `graph` induced by each label (cells with equal
// label[c] form one subgraph; label -1 = left out), by an iterative depth-first search (Tarjan)
// from `roots` first (in order), then from any cell not yet reached. Per cell, in `cuts`:
//   cut        removing it disconnects its subgraph's component;
//   beyond     (non-root cells) the cells that removing it cuts off from the search's root, itself
//              not counted: 0 when it is no cut;
//   parts      (only with `want_parts`) for a cut, the sizes of all the parts removing it leaves.
struct Cuts {
  std::vector<std::uint8_t> cut;
  std::vector<int> beyond;
  std::vector<std::vector<int>> parts;
};

void articulation_points(const RegionGraph& graph, const std::vector<int>& label, const std::vector<int>& roots,
                         bool want_parts, Cuts& cuts) {
  const int n = graph.size();
  cuts.cut.assign(n, 0);
  cuts.beyond.assign(n, 0);
  if (want_parts) cuts.parts.assign(n, {});
  std::vector<int> disc(n, -1), low(n, 0), size(n, 1), parent(n, -1);
  std::vector<std::uint8_t> edge(n, 0);  // per cell on the stack: the next direction to try
  std::vector<int> stack, reached;
  int time = 0;
  auto search = [&](int root) {
    if (disc[root] >= 0 || label[root] < 0) return;
    int root_children = 0;
    disc[root] = low[root] = time++;
    stack.assign(1, root);
    reached.assign(1, root);
    while (!stack.empty()) {
      const int v = stack.back();
      if (edge[v] < 4) {
        const int w = graph.next[v][edge[v]++];
        if (w < 0 || label[w] != label[v]) continue;
        if (disc[w] < 0) {
          parent[w] = v;
          disc[w] = low[w] = time++;
          stack.push_back(w);
          reached.push_back(w);
          if (v == root) ++root_children;
        } else if (w != parent[v]) {
          low[v] = std::min(low[v], disc[w]);
        }
        continue;
      }
      stack.pop_back();
      const int p = parent[v];
      if (p < 0) continue;
      low[p] = std::min(low[p], low[v]);
      size[p] += size[v];
      if (low[v] >= disc[p]) {
        if (p != root) cuts.cut[p] = 1, cuts.beyond[p] += size[v];
        if (want_parts) cuts.parts[p].push_back(size[v]);
      }
    }
    if (root_children >= 2) cuts.cut[root] = 1;
    if (!want_parts) return;
    // A non-root cut also leaves the part holding the root.
    const int component = static_cast<int>(reached.size());
    for (int c : reached) {
      if (c == root || !cuts.cut[c]) continue;
      const int rest = component - 1 - cuts.beyond[c];
      if (rest > 0) cuts.parts[c].push_back(rest);
    }
  };
  for (int r : roots) search(r);
  for (int c = 0; c < n; ++c) search(c);
}

// Whether `count` regions of lo..hi cells each, all connected, can be laid over parts of these
// sizes joined only through one cell v: v's region holds v and reaches x_j cells into part j,
// the other regions lie whole inside one part each. Counting only (necessary, not sufficient).
bool counts_fit(const std::vector<int>& parts, int count, int lo, int hi) {
  if (hi < 1) return false;
  // reach[a][x]: a regions placed whole so far, v's region reaching x cells into the parts.
  std::vector<std::vector<std::uint8_t>> reach(count, std::vector<std::uint8_t>(hi, 0));
  reach[0][0] = 1;
  std::vector<int> prefix(hi + 1);
  for (int cells : parts) {
    std::vector<std::vector<std::uint8_t>> next(count, std::vector<std::uint8_t>(hi, 0));
    for (int a = 0; a < count; ++a) {
      prefix[0] = 0;
      for (int x = 0; x < hi; ++x) prefix[x + 1] = prefix[x] + reach[a][x];
      if (prefix[hi] == 0) continue;
      for (int more = 0; a + more < count; ++more) {
        // v's region takes what `more` whole regions leave of the part.
        const int take_lo = more == 0 ? cells : std::max(0, cells - more * hi);
        const int take_hi = more == 0 ? cells : cells - more * lo;
        if (take_hi < 0) break;
        for (int y = take_lo; y < hi; ++y) {
          const int from = std::max(0, y - take_hi), to = y - take_lo;  // x in [from, to]
          if (prefix[to + 1] - prefix[from] > 0) next[a + more][y] = 1;
        }
      }
    }
    reach = std::move(next);
  }
  for (int t = std::max(1, lo); t <= hi; ++t) {
    if (reach[count - 1][t - 1]) return true;
  }
  return false;
}

class Repair {
 public:
  Repair(const DarpSpace& space, std::vector<int>& owner, std::vector<int>& starts, double tolerance)
      : s_(space), g_(space.graph), owner_(owner), starts_(starts), tolerance_(tolerance), n_(space.robots()),
        target_(whole_targets(space)), best_(static_cast<std::size_t>(n_) * n_) {}

  // Step 1: every region reduced to the piece holding its start, the rest handed out by a
  // breadth-first wave from all regions at once.
  void connect() {
    for (int r = 0; r < n_; ++r) owner_[starts_[r]] = r;
    std::vector<std::uint8_t> kept(g_.size(), 0);
    std::vector<int> queue;
    for (int r = 0; r < n_; ++r) {
      kept[starts_[r]] = 1;
      queue.assign(1, starts_[r]);
      for (std::size_t h = 0; h < queue.size(); ++h) {
        for (int nb : g_.next[queue[h]]) {
          if (nb < 0 || kept[nb] || owner_[nb] != r) continue;
          kept[nb] = 1;
          queue.push_back(nb);
        }
      }
    }
    queue.clear();
    for (int c = 0; c < g_.size(); ++c) {
      if (kept[c]) {
        queue.push_back(c);
      } else {
        owner_[c] = -1;
        ++moves_;
      }
    }
    for (std::size_t h = 0; h < queue.size(); ++h) {
      for (int nb : g_.next[queue[h]]) {
        if (nb < 0 || owner_[nb] >= 0) continue;
        owner_[nb] = owner_[queue[h]];
        queue.push_back(nb);
      }
    }
    count_.assign(n_, 0);
    sum_x_.assign(n_, 0.0);
    sum_y_.assign(n_, 0.0);
    for (int c = 0; c < g_.size(); ++c) {
      ++count_[owner_[c]];
      sum_x_[owner_[c]] += g_.cells[c].x;
      sum_y_[owner_[c]] += g_.cells[c].y;
    }
  }

  // Step 2 (and 3's release): chains, else branch moves, until every region holds its target
  // (tighter than the goal, for even shares) or neither is left.
  void balance(int max_steps) {
    for (int steps = 0; steps < max_steps && surplus() > 0; ++steps) {
      if (chain(false) || chain(true) || branch() || reseed()) continue;
      if (!pinned_) break;
      pinned_ = false;
    }
  }

  bool goal() const {
    for (int r = 0; r < n_; ++r) {
      if (std::abs(count_[r] - s_.shares[r]) > tolerance_ + 1e-9) return false;
    }
    return true;
  }
  int moves() const { return moves_; }
  int surplus() const {
    int sum = 0;
    for (int r = 0; r < n_; ++r) sum += std::abs(count_[r] - target_[r]);
    return sum;
  }

 private:
  struct Candidate {
    double score = std::numeric_limits<double>::infinity();
    int cell = -1;
  };

  // Lower = a better cell to hand from a to b: near b's centroid, far from a's.
  double score(int c, int a, int b) const {
    const double x = g_.cells[c].x, y = g_.cells[c].y;
    return std::hypot(x - sum_x_[b] / count_[b], y - sum_y_[b] / count_[b]) -
           std::hypot(x - sum_x_[a] / count_[a], y - sum_y_[a] / count_[a]);
  }

  bool may_leave(int c, int a, bool exact) const {
    if (count_[a] <= 1 || (pinned_ && starts_[a] == c)) return false;
    return exact ? !cuts_.cut[c] : simple_point(g_, owner_, c, a);
  }

  bool touches(int c, int b) const {
    for (int nb : g_.next[c]) {
      if (nb >= 0 && owner_[nb] == b) return true;
    }
    return false;
  }

  // The best cell of a that may go to b, -1 = none.
  Candidate best_crossing(int a, int b, bool exact) const {
    Candidate best;
    for (int c = 0; c < g_.size(); ++c) {
      if (owner_[c] != a || !touches(c, b)) continue;
      const double sc = score(c, a, b);
      if (sc < best.score && may_leave(c, a, exact)) best = {sc, c};
    }
    return best;
  }

  void hand_over(int c, int a, int b) {
    if (starts_[a] == c) {  // released: the region grows from a neighbour of its old start
      for (int nb : g_.next[c]) {
        if (nb >= 0 && owner_[nb] == a) starts_[a] = nb;
      }
    }
    journal_.push_back({c, a});
    owner_[c] = b;
    --count_[a];
    ++count_[b];
    sum_x_[a] -= g_.cells[c].x, sum_y_[a] -= g_.cells[c].y;
    sum_x_[b] += g_.cells[c].x, sum_y_[b] += g_.cells[c].y;
    ++moves_;
  }

  // One chain from a region over its target to the nearest region under its target. False when
  // there is none (with this test of which cells may leave).
  bool chain(bool exact) {
    if (exact) articulation_points(g_, owner_, starts_, false, cuts_);
    std::fill(best_.begin(), best_.end(), Candidate{});
    for (int c = 0; c < g_.size(); ++c) {
      const int a = owner_[c];
      for (int nb : g_.next[c]) {
        if (nb < 0 || owner_[nb] == a) continue;
        const int b = owner_[nb];
        Candidate& k = best_[static_cast<std::size_t>(a) * n_ + b];
        const double sc = score(c, a, b);
        if (sc < k.score && may_leave(c, a, exact)) k = {sc, c};
      }
    }
    // Breadth-first over regions from every region over its target.
    std::vector<int> previous(n_, -2);
    std::vector<int> queue;
    for (int r = 0; r < n_; ++r) {
      if (count_[r] > target_[r]) previous[r] = -1, queue.push_back(r);
    }
    int end = -1;
    for (std::size_t h = 0; h < queue.size() && end < 0; ++h) {
      const int a = queue[h];
      for (int b = 0; b < n_; ++b) {
        if (previous[b] != -2 || best_[static_cast<std::size_t>(a) * n_ + b].cell < 0) continue;
        previous[b] = a;
        if (count_[b] < target_[b]) {
          end = b;
          break;
        }
        queue.push_back(b);
      }
    }
    if (end < 0) return false;
    int first = end;
    while (previous[first] >= 0) first = previous[first];
    // As many cells as the two ends need, hop by hop from the last: each giving region is still
    // as the scan saw it, only the receiving one may have lost the cell the crossing touched. A
    // hop that moves fewer cells than the next limits the ones before it.
    // A hop with no cell left to move (its crossing touched only the cell the next hop took)
    // undoes the chain, which then counts as not found.
    int q = std::min(count_[first] - target_[first], target_[end] - count_[end]);
    const std::vector<int> starts_before = starts_;
    journal_.clear();
    for (int b = end; previous[b] >= 0 && q > 0; b = previous[b]) {
      const int a = previous[b];
      int c = best_[static_cast<std::size_t>(a) * n_ + b].cell;
      if (!touches(c, b)) c = best_crossing(a, b, exact).cell;
      if (c < 0) {
        const std::vector<Handed> undo = std::move(journal_);
        for (auto it = undo.rbegin(); it != undo.rend(); ++it) hand_over(it->cell, owner_[it->cell], it->from);
        moves_ -= 2 * static_cast<int>(undo.size());
        starts_ = starts_before;
        return false;
      }
      q = flow(c, a, b, q);
    }
    return true;
  }

  // Hands `first` (a cell a may give to b) and then up to q - 1 more of a's cells to b, best
  // first: cells of a next to b (or next to a cell just handed over) that a can lose by the 3 x 3
  // test. Returns the cells moved.
  int flow(int first, int a, int b, int q) {
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> heap;
    hand_over(first, a, b);
    int moved = 1;
    if (q <= 1) return moved;
    for (int c = 0; c < g_.size(); ++c) {
      if (owner_[c] == a && touches(c, b)) heap.push({score(c, a, b), c});
    }
    while (moved < q && !heap.empty()) {
      const int c = heap.top().second;
      heap.pop();
      if (owner_[c] != a || !may_leave(c, a, false)) continue;
      hand_over(c, a, b);
      ++moved;
      for (int nb : g_.next[c]) {
        if (nb >= 0 && owner_[nb] == a) heap.push({score(nb, a, b), nb});
      }
    }
    return moved;
  }

  // When no chain exists: a cell that would cut its region goes with everything it cuts off from
  // the region's start (a dead end, a room behind a door) to the neighbouring region, the move
  // that brings the regions nearest their targets; one that only shifts the surplus (into a
  // region under its target) is allowed a bounded number of times. Uses the cuts chain(true)
  // just computed. False when there is no such move.
  bool branch() {
    auto off = [&](int r, int d) { return std::abs(count_[r] + d - target_[r]) - std::abs(count_[r] - target_[r]); };
    struct Move {
      int delta = 1, size = 0, cell = -1, to = -1;
      double score = 0;
    } best;
    for (int c = 0; c < g_.size(); ++c) {
      const int a = owner_[c];
      if (c == starts_[a] || !cuts_.cut[c]) continue;
      const int m = cuts_.beyond[c] + 1;
      for (int nb : g_.next[c]) {
        if (nb < 0 || owner_[nb] == a) continue;
        const int b = owner_[nb];
        const int delta = off(a, -m) + off(b, m);
        if (delta > 0 || (delta == 0 && (count_[b] >= target_[b] || shifts_ >= 4 * n_))) continue;
        const double sc = score(c, a, b);
        if (best.cell >= 0 && std::tie(best.delta, best.size, best.score) <= std::tie(delta, m, sc)) continue;
        best = {delta, m, c, b, sc};
      }
    }
    if (best.cell < 0) return false;
    shifts_ += best.delta == 0;
    const int a = owner_[best.cell];
    // What the cell cuts off: a's cells its start no longer reaches without it.
    std::vector<std::uint8_t> kept(g_.size(), 0);
    std::vector<int> queue{starts_[a]};
    kept[starts_[a]] = 1;
    for (std::size_t h = 0; h < queue.size(); ++h) {
      for (int nb : g_.next[queue[h]]) {
        if (nb < 0 || nb == best.cell || kept[nb] || owner_[nb] != a) continue;
        kept[nb] = 1;
        queue.push_back(nb);
      }
    }
    for (int c = 0; c < g_.size(); ++c) {
      if (owner_[c] == a && !kept[c]) hand_over(c, a, best.to);
    }
    return true;
  }

  // When nothing else moves (released starts only): the region furthest under its target is walled
  // in. It is merged into a neighbour and grown again from the cell of the region furthest over
  // its target (of the same piece) that lies furthest from that region's start: a leaf of a
  // breadth-first tree, so taking it never cuts its region. At most 2 per robot.
  bool reseed() {
    if (pinned_ || reseeds_ >= 2 * n_) return false;
    int d = -1;
    for (int r = 0; r < n_; ++r) {
      if (count_[r] < target_[r] && (d < 0 || target_[r] - count_[r] > target_[d] - count_[d])) d = r;
    }
    if (d < 0) return false;
    int next = -1;
    for (int c = 0; c < g_.size() && next < 0; ++c) {
      if (owner_[c] != d) continue;
      for (int nb : g_.next[c]) {
        if (nb >= 0 && owner_[nb] != d) next = owner_[nb];
      }
    }
    if (next < 0) return false;
    ++reseeds_;
    for (int c = 0; c < g_.size(); ++c) {
      if (owner_[c] == d) hand_over(c, d, next);
    }
    // Some region of the piece now holds 2 cells or more: d's are spread over the others.
    int a = -1;
    for (int r = 0; r < n_; ++r) {
      if (r == d || s_.robot_piece[r] != s_.robot_piece[d] || count_[r] < 2) continue;
      if (a < 0 || count_[r] - target_[r] > count_[a] - target_[a]) a = r;
    }
    const int seed = furthest_cell(a);
    hand_over(seed, a, d);
    starts_[d] = seed;
    return true;
  }

  // The last of r's cells reached breadth-first from r's start.
  int furthest_cell(int r) const {
    std::vector<std::uint8_t> seen(g_.size(), 0);
    std::vector<int> order{starts_[r]};
    seen[starts_[r]] = 1;
    for (std::size_t h = 0; h < order.size(); ++h) {
      for (int nb : g_.next[order[h]]) {
        if (nb < 0 || seen[nb] || owner_[nb] != r) continue;
        seen[nb] = 1;
        order.push_back(nb);
      }
    }
    return order.back();
  }

  const DarpSpace& s_;
  const RegionGraph& g_;
  std::vector<int>& owner_;
  std::vector<int>& starts_;
  double tolerance_;
  int n_;
  std::vector<int> target_;
  std::vector<int> count_;
  std::vector<double> sum_x_, sum_y_;
  std::vector<Candidate> best_;   // n x n: the best crossing from a to b
  Cuts cuts_;
  struct Handed {
    int cell, from;
  };
  std::vector<Handed> journal_;  // the cells a chain has moved so far
  int shifts_ = 0;  // branch moves that only shifted the surplus
  int reseeds_ = 0;
  bool pinned_ = true;
  int moves_ = 0;
};

}  // namespace

RepairOutcome repair_division(const DarpSpace& space, std::vector<int>& owner, std::vector<int>& starts,
                              const std::vector<int>& robots, double tolerance) {
  const std::vector<int> original = starts;
  Repair repair(space, owner, starts, tolerance);
  repair.connect();
  // A chain lowers the surplus by 2 or more, a branch move by at least 1 (or shifts it, a
  // bounded number of times); allow plenty.
  repair.balance(4 * repair.surplus() + 16 * space.robots() + 64);
  RepairOutcome out;
  out.moves = repair.moves();
  out.goal = repair.goal();
  // A region that gave up its start takes the cell nearest its robot.
  const RegionGraph& g = space.graph;
  for (int r = 0; r < space.robots(); ++r) {
    if (starts[r] == original[r]) continue;
    std::vector<int> order;
    static_cast<void>(bfs_steps(g, {robots[r]}, &order));
    for (int c : order) {
      if (owner[c] == r) {
        starts[r] = c;
        break;
      }
    }
  }
  return out;
}

std::string no_balanced_division(const DarpSpace& space, double tolerance) {
  const RegionGraph& g = space.graph;
  Cuts cuts;
  articulation_points(g, space.piece, {}, true, cuts);
  const std::vector<std::uint8_t>& cut = cuts.cut;
  const std::vector<std::vector<int>>& parts = cuts.parts;
  for (int p = 0; p < space.pieces; ++p) {
    int count = 0, lo = std::numeric_limits<int>::max(), hi = 0;
    for (int r = 0; r < space.robots(); ++r) {
      if (space.robot_piece[r] != p) continue;
      ++count;
      lo = std::min(lo, std::max(1, static_cast<int>(std::ceil(space.shares[r] - tolerance - 1e-9))));
      hi = std::max(hi, static_cast<int>(std::floor(space.shares[r] + tolerance + 1e-9)));
    }
    if (count <= 1) continue;
    std::vector<std::vector<int>> tried;
    for (int v = 0; v < g.size(); ++v) {
      if (!cut[v] || space.piece[v] != p) continue;
      std::vector<int> sizes = parts[v];
      std::sort(sizes.begin(), sizes.end());
      if (std::find(tried.begin(), tried.end(), sizes) != tried.end()) continue;
      tried.push_back(sizes);
      if (counts_fit(sizes, count, lo, hi)) continue;
      std::string list;
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        list += (k == 0 ? "" : k + 1 == sizes.size() ? " and " : ", ") + std::to_string(sizes[k]);
      }
      return "cell " + to_string(g.cells[v]) + " is the only way between parts of " + list +
             " cells, and no " + std::to_string(count) + " connected regions of " + std::to_string(lo) + "-" +
             std::to_string(hi) + " cells fit them";
    }
  }
  return "";
}

}  // namespace swarm::planner::detail
