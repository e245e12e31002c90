#include "swarm/planner/grid/motion.hpp"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <numeric>
#include <unordered_map>

namespace swarm::planner {

const char* to_string(MoveCheck check) {
  switch (check) {
    case MoveCheck::Ok: return "ok";
    case MoveCheck::Wait: return "wait";
    case MoveCheck::NotAdjacent: return "not adjacent";
    case MoveCheck::Blocked: return "blocked";
    case MoveCheck::CornerCut: return "corner cut";
  }
  return "?";
}

bool MotionModel::adjacent_or_same(Cell from, Cell to) const {
  const int dx = std::abs(to.x - from.x);
  const int dy = std::abs(to.y - from.y);
  if (connectivity == Connectivity::Four) return dx + dy <= 1;
  return std::max(dx, dy) <= 1;
}

MoveCheck MotionModel::check(const OccupancyGrid& map, Cell from, Cell to, Passability passability) const {
  if (from == to) return MoveCheck::Wait;
  if (!adjacent_or_same(from, to)) return MoveCheck::NotAdjacent;
  if (!passable(map, to, passability)) return MoveCheck::Blocked;
  if (from.x != to.x && from.y != to.y &&
      (!passable(map, {to.x, from.y}, passability) || !passable(map, {from.x, to.y}, passability))) {
    return MoveCheck::CornerCut;
  }
  return MoveCheck::Ok;
}

double MotionModel::heuristic(Cell a, Cell b) const {
  if (connectivity == Connectivity::Four) return std::abs(a.x - b.x) + std::abs(a.y - b.y);
  return octile_distance(a, b);
}

namespace {
std::int64_t key_of(Cell c) { return (static_cast<std::int64_t>(c.y) << 32) ^ static_cast<std::uint32_t>(c.x); }
}  // namespace

StepConflicts find_step_conflicts(const std::vector<Cell>& from, const std::vector<Cell>& to) {
  assert(from.size() == to.size());
  StepConflicts out;
  const int n = static_cast<int>(from.size());
  // Vertex: robots sorted by the cell they end on; runs of two or more share it.
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return to[a] != to[b] ? to[a] < to[b] : a < b;
  });
  for (int i = 0; i < n;) {
    int j = i + 1;
    while (j < n && to[order[j]] == to[order[i]]) ++j;
    if (j - i >= 2) out.vertex.push_back({to[order[i]], std::vector<int>(order.begin() + i, order.begin() + j)});
    i = j;
  }
  // Edge: a mover whose target is where another robot comes from, going the other way.
  // Every robot that starts on a cell (a plan under check may hold two there; the simulator never).
  std::unordered_multimap<std::int64_t, int> at;
  at.reserve(static_cast<std::size_t>(n) * 2);
  for (int i = 0; i < n; ++i) at.emplace(key_of(from[i]), i);
  for (int a = 0; a < n; ++a) {
    if (to[a] == from[a]) continue;
    const auto [first, last] = at.equal_range(key_of(to[a]));
    for (auto it = first; it != last; ++it) {
      const int b = it->second;
      if (b > a && to[b] == from[a]) out.edge.push_back({a, b});
    }
  }
  std::sort(out.edge.begin(), out.edge.end(), [](const EdgeConflict& x, const EdgeConflict& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return out;
}

std::string describe(const MotionModel& model) {
  return model.connectivity == Connectivity::Four ? "4-connected" : "8-connected (no corner cutting)";
}

}  // namespace swarm::planner
