#include "swarm/planner/coverage/stc.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <numeric>

#include "swarm/planner/coverage/region_graph.hpp"

namespace swarm::planner {
namespace {

// Quadrants of a 2 x 2 block (y up): q = qx + 2 qy. Counter-clockwise order around the block.
constexpr int kSW = 0, kSE = 1, kNW = 2, kNE = 3;
constexpr std::array<int, 4> kRing = {kSW, kSE, kNE, kNW};

// The walk: a circular doubly linked list of visits (a cell may be visited more than once).
struct Walk {
  std::vector<int> cell, next, prev;  // per visit
  std::vector<int> first_visit;       // per cell: one of its visits (-1: none yet)
  std::vector<int> other_visit;       // per visit: the next visit of the same cell (-1: none)

  explicit Walk(int cells) : first_visit(cells, -1) {}

  int add(int c) {
    const int v = static_cast<int>(cell.size());
    cell.push_back(c);
    next.push_back(v);
    prev.push_back(v);
    other_visit.push_back(first_visit[c]);
    first_visit[c] = v;
    return v;
  }
  void link(int a, int b) { next[a] = b, prev[b] = a; }
  // A visit of cell a whose successor is a visit of cell b, or -1.
  int find_step(int a, int b) const {
    for (int v = first_visit[a]; v >= 0; v = other_visit[v]) {
      if (cell[next[v]] == b) return v;
    }
    return -1;
  }
};

struct Edge {
  int weight;
  int a_node, b_node;
  bool parallel;
  // Parallel: cells x, y of a (x ~ c, y ~ d) and c, d of b. Bridge: x of a next to c of b.
  int x, y, c, d;
};

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Cuts both walks open along the facing sides and crosses them over: ... x -> c ... d -> y ...
// Returns false when a side is not a step of its walk (then the caller bridges instead).
bool splice_parallel(Walk& w, int x, int y, int c, int d) {
  int vx = w.find_step(x, y);
  if (vx < 0) {
    vx = w.find_step(y, x);
    if (vx < 0) return false;
    std::swap(x, y);
    std::swap(c, d);
  }
  const int vd = w.find_step(d, c);
  if (vd < 0) return false;
  const int vy = w.next[vx];
  const int vc = w.next[vd];
  w.link(vx, vc);
  w.link(vd, vy);
  return true;
}

// A detour from x (in one walk) into c's walk and back: x -> c ... (c's whole walk) ... c -> x.
// A walk of one visit is not repeated (that would be a wait, x -> x).
void splice_bridge(Walk& w, int x, int c) {
  const int vx = w.first_visit[x];
  const int vc = w.first_visit[c];
  const int after_x = w.next[vx];
  const int before_c = w.prev[vc];
  const bool single_x = after_x == vx;
  const bool single_c = before_c == vc;
  const int back_to_x = single_x ? vx : w.add(x);
  w.link(vx, vc);
  if (single_c) {
    w.link(vc, back_to_x);
  } else {
    const int c2 = w.add(c);
    w.link(before_c, c2);
    w.link(c2, back_to_x);
  }
  if (!single_x) w.link(back_to_x, after_x);
}

struct Candidate {
  int length = 0;
  int turns = 0;
  std::vector<int> order;  // visits' cells along the path
};

int turn_between(Cell a, Cell b, Cell c) {
  const int dx1 = b.x - a.x, dy1 = b.y - a.y, dx2 = c.x - b.x, dy2 = c.y - b.y;
  if (dx1 == dx2 && dy1 == dy2) return 0;
  if (dx1 == -dx2 && dy1 == -dy2) return 2;
  return 1;
}

// The open path along the closed walk from visit `from`, forwards or backwards, cut after the
// last cell seen for the first time.
Candidate open_path(const Walk& w, const std::vector<Cell>& cells, int from, bool forward, int total,
                    std::vector<int>& seen, int stamp) {
  Candidate out;
  std::vector<int> order;
  order.reserve(w.cell.size());
  int v = from;
  int distinct = 0;
  std::size_t last_new = 0;
  for (std::size_t k = 0; k < w.cell.size() && distinct < total; ++k) {
    const int c = w.cell[v];
    order.push_back(c);
    if (seen[c] != stamp) {
      seen[c] = stamp;
      ++distinct;
      last_new = k;
    }
    v = forward ? w.next[v] : w.prev[v];
  }
  order.resize(last_new + 1);
  out.length = static_cast<int>(order.size()) - 1;
  for (std::size_t k = 2; k < order.size(); ++k) {
    out.turns += turn_between(cells[order[k - 2]], cells[order[k - 1]], cells[order[k]]);
  }
  out.order = std::move(order);
  return out;
}

// One spanning tree's closed walk over the cells `in` of the graph (a connected piece).
Walk build_walk(const RegionGraph& g, const std::vector<int>& in, int ox, int oy, int mode) {
  int bx0 = 1 << 30, by0 = 1 << 30, bx1 = -1, by1 = -1;
  for (int c : in) {
    const Cell p = g.cells[c];
    bx0 = std::min(bx0, (p.x + ox) >> 1), bx1 = std::max(bx1, (p.x + ox) >> 1);
    by0 = std::min(by0, (p.y + oy) >> 1), by1 = std::max(by1, (p.y + oy) >> 1);
  }
  const int bw = bx1 - bx0 + 1, bh = by1 - by0 + 1;
  std::vector<std::array<int, 4>> block(static_cast<std::size_t>(bw) * bh, {-1, -1, -1, -1});
  auto block_of = [&](int bx, int by) -> std::array<int, 4>& {
    return block[static_cast<std::size_t>(by - by0) * bw + (bx - bx0)];
  };
  for (int c : in) {
    const Cell p = g.cells[c];
    block_of((p.x + ox) >> 1, (p.y + oy) >> 1)[((p.x + ox) & 1) + 2 * ((p.y + oy) & 1)] = c;
  }

  // Nodes and their own closed walks.
  Walk w(g.size());
  std::vector<int> node_of(g.size(), -1);
  int nodes = 0;
  for (const auto& q : block) {
    const bool diagonal = (q[kSW] >= 0 && q[kNE] >= 0 && q[kSE] < 0 && q[kNW] < 0) ||
                          (q[kSE] >= 0 && q[kNW] >= 0 && q[kSW] < 0 && q[kNE] < 0);
    std::vector<int> ring;  // present cells in counter-clockwise order
    int missing = -1;
    for (int k = 0; k < 4; ++k) {
      if (q[kRing[k]] >= 0) ring.push_back(q[kRing[k]]);
      else missing = k;
    }
    if (ring.empty()) continue;
    if (diagonal) {
      for (int c : ring) node_of[c] = nodes++, w.add(c);
      continue;
    }
    std::vector<int> walk = ring;
    if (ring.size() == 3) {  // a, corner, b, corner: the L there and back
      const int a = q[kRing[(missing + 1) % 4]], corner = q[kRing[(missing + 2) % 4]], b = q[kRing[(missing + 3) % 4]];
      walk = {a, corner, b, corner};
    }
    std::vector<int> visits;
    for (int c : walk) visits.push_back(w.add(c));
    for (std::size_t k = 0; k < visits.size(); ++k) w.link(visits[k], visits[(k + 1) % visits.size()]);
    for (int c : ring) node_of[c] = nodes;
    ++nodes;
  }

  // Candidate tree edges between neighbouring blocks.
  constexpr int kBridge = 1 << 24;  // any bridge after every parallel edge
  std::vector<Edge> edges;
  for (int by = by0; by <= by1; ++by) {
    for (int bx = bx0; bx <= bx1; ++bx) {
      const auto& a = block_of(bx, by);
      for (int dir = 0; dir < 2; ++dir) {  // 0: +x, 1: +y
        const int nx = bx + (dir == 0), ny = by + (dir == 1);
        if (nx > bx1 || ny > by1) continue;
        const auto& b = block_of(nx, ny);
        // Facing cells: (a's side, b's side), in two adjacent pairs.
        const std::array<std::pair<int, int>, 2> pairs =
            dir == 0 ? std::array<std::pair<int, int>, 2>{{{a[kSE], b[kSW]}, {a[kNE], b[kNW]}}}
                     : std::array<std::pair<int, int>, 2>{{{a[kNW], b[kSW]}, {a[kNE], b[kSE]}}};
        int weight = 1;
        const bool along_x = dir == 0;
        if (mode == 0 || mode == 1) weight = along_x ? 2 + (mode == 0 ? by - by0 : by1 - by) : 1;
        else weight = along_x ? 1 : 2 + (mode == 2 ? bx - bx0 : bx1 - bx);
        const auto& [x, c] = pairs[0];
        const auto& [y, d] = pairs[1];
        if (x >= 0 && y >= 0 && c >= 0 && d >= 0 && node_of[x] == node_of[y] && node_of[c] == node_of[d]) {
          edges.push_back({weight, node_of[x], node_of[c], true, x, y, c, d});
          continue;
        }
        for (const auto& [u, v] : pairs) {
          if (u >= 0 && v >= 0) edges.push_back({kBridge + weight, node_of[u], node_of[v], false, u, -1, v, -1});
        }
      }
    }
  }
  std::stable_sort(edges.begin(), edges.end(), [](const Edge& l, const Edge& r) { return l.weight < r.weight; });

  // Kruskal; every accepted edge is spliced into the walk at once (splices on different sides
  // of a node never touch the same step, so the order does not matter).
  std::vector<int> parent(nodes);
  std::iota(parent.begin(), parent.end(), 0);
  for (const Edge& e : edges) {
    const int ra = find(parent, e.a_node), rb = find(parent, e.b_node);
    if (ra == rb) continue;
    parent[ra] = rb;
    if (!e.parallel || !splice_parallel(w, e.x, e.y, e.c, e.d)) splice_bridge(w, e.x, e.c);
  }
  return w;
}

}  // namespace

StcPath spanning_tree_coverage(const OccupancyGrid& region, Cell start, const StcConfig& config) {
  StcPath out;
  const RegionGraph g = RegionGraph::build(region);
  const int s = g.index_of(start);
  if (s < 0) {
    out.status = StcStatus::StartOutsideRegion;
    out.left_out = g.size();
    return out;
  }
  int count = 0;
  const std::vector<int> label = components(g, count);
  std::vector<int> in;
  for (int i = 0; i < g.size(); ++i) {
    if (label[i] == label[s]) in.push_back(i);
  }
  out.covered = static_cast<int>(in.size());
  out.left_out = g.size() - out.covered;

  std::vector<int> seen(g.size(), 0);
  int stamp = 0;
  Candidate best;
  bool have = false;
  const int offsets = config.all_lattice_offsets ? 4 : 1;
  for (int off = 0; off < offsets; ++off) {
    for (int mode = 0; mode < 4; ++mode) {
      const Walk w = build_walk(g, in, off & 1, off >> 1, mode);
      for (int v = w.first_visit[s]; v >= 0; v = w.other_visit[v]) {
        for (bool forward : {true, false}) {
          Candidate c = open_path(w, g.cells, v, forward, out.covered, seen, ++stamp);
          if (!have || c.length < best.length || (c.length == best.length && c.turns < best.turns)) {
            best = std::move(c);
            have = true;
            out.lattice_x = off & 1;
            out.lattice_y = off >> 1;
            out.tree_mode = mode;
          }
        }
      }
    }
  }
  for (int c : best.order) out.cells.push_back(g.cells[c]);
  out.length = best.length;
  out.turns = best.turns;
  out.revisits = static_cast<int>(out.cells.size()) - out.covered;
  return out;
}

}  // namespace swarm::planner
