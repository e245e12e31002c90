#include "swarm/planner/grid/astar.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>

namespace swarm::planner {
namespace {

struct Open {
  double f;
  double g;
  int idx;
};

// std::priority_queue pops the largest: "larger" here means worse.
struct Worse {
  bool operator()(const Open& a, const Open& b) const {
    if (a.f != b.f) return a.f > b.f;
    if (a.g != b.g) return a.g < b.g;  // prefer deeper nodes: fewer re-expansions on plateaus
    return a.idx > b.idx;
  }
};

// Per-thread search memory reused across calls; a generation stamp replaces clearing it, so a
// short search on a big map costs what it expands, not the map size.
struct Scratch {
  std::vector<std::uint32_t> stamp;  // == generation: g/parent valid for this search
  std::vector<double> g;
  std::vector<int> parent;
  std::vector<std::uint8_t> closed;
  std::uint32_t generation = 0;

  void begin(std::size_t n) {
    if (stamp.size() < n) {
      stamp.assign(n, 0);
      g.resize(n);
      parent.resize(n);
      closed.resize(n);
      generation = 0;
    }
    if (++generation == 0) {  // wrapped: reset once every 2^32 searches
      std::fill(stamp.begin(), stamp.end(), 0);
      generation = 1;
    }
  }
  bool seen(int i) const { return stamp[static_cast<std::size_t>(i)] == generation; }
  void touch(int i) {
    stamp[static_cast<std::size_t>(i)] = generation;
    closed[static_cast<std::size_t>(i)] = 0;
  }
};

}  // namespace

std::optional<std::vector<Cell>> astar(const OccupancyGrid& map, Cell start, Cell goal,
                                       const AStarOptions& options) {
  if (!map.in_bounds(start) || !map.in_bounds(goal)) return std::nullopt;
  if (start == goal) return std::vector<Cell>{start};
  const Passability passability = options.unknown_is_free ? Passability::UnknownIsFree : Passability::FreeOnly;
  const MotionModel& motion = options.motion;
  if (!MotionModel::passable(map, goal, passability)) return std::nullopt;

  thread_local Scratch mem;
  mem.begin(map.size());
  std::priority_queue<Open, std::vector<Open>, Worse> open;
  const int start_idx = map.index(start);
  const int goal_idx = map.index(goal);
  mem.touch(start_idx);
  mem.g[static_cast<std::size_t>(start_idx)] = 0.0;
  mem.parent[static_cast<std::size_t>(start_idx)] = -1;
  open.push({motion.heuristic(start, goal), 0.0, start_idx});

  while (!open.empty()) {
    const Open cur = open.top();
    open.pop();
    const std::size_t ci = static_cast<std::size_t>(cur.idx);
    if (mem.closed[ci] || cur.g > mem.g[ci]) continue;  // stale entry
    mem.closed[ci] = 1;
    if (cur.idx == goal_idx) {
      std::vector<Cell> path;
      for (int i = goal_idx; i != -1; i = mem.parent[static_cast<std::size_t>(i)]) {
        path.push_back(map.cell_of(i));
      }
      std::reverse(path.begin(), path.end());
      return path;
    }
    const Cell c = map.cell_of(cur.idx);
    motion.for_each_neighbour(map, c, [&](Cell n, double cost) {
      const int ni = map.index(n);
      const std::size_t nu = static_cast<std::size_t>(ni);
      const double ng = cur.g + cost;
      if (mem.seen(ni)) {
        if (mem.closed[nu] || ng >= mem.g[nu]) return;
      } else {
        mem.touch(ni);
      }
      mem.g[nu] = ng;
      mem.parent[nu] = cur.idx;
      open.push({ng + motion.heuristic(n, goal), ng, ni});
    }, passability);
  }
  return std::nullopt;
}

double path_length(const std::vector<Cell>& path) {
  double len = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) len += euclidean_distance(path[i - 1], path[i]);
  return len;
}

}  // namespace swarm::planner
