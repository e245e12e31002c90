#include "swarm/planner/mapf/instance.hpp"

#include <algorithm>
#include <deque>
#include <map>

namespace swarm::planner::mapf {
namespace {

std::string text(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

bool free_cell(const OccupancyGrid& map, Cell c) { return map.is_free(c); }

// Paper rules need a warehouse lattice: every passage middle lies between two intersections and
// every intersection's free neighbours are passage middles.
std::string lattice_problem(const OccupancyGrid& map) {
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    const Cell c = map.cell_of(i);
    if (!map.is_free(c)) continue;
    const bool middle = is_passage_middle(map, c);
    for (int k = 0; k < 4; ++k) {
      const Cell n{c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]};
      if (!map.is_free(n)) continue;
      if (middle == is_passage_middle(map, n)) {
        return "the map is not a warehouse lattice (cells " + text(c) + " and " + text(n) +
               " are both " + (middle ? "passage middles" : "intersections") +
               "): the paper's rules need intersections joined by one-cell passages";
      }
    }
  }
  return "";
}

}  // namespace

std::string describe(const Rules& rules) {
  if (rules == Rules::standard()) return "standard";
  if (rules == Rules::paper_warehouse()) return "paper-warehouse";
  return std::string("goal=") + (rules.at_goal == GoalRule::Stay ? "stay" : "vanish") +
         ", waits=" + (rules.waits == WaitRule::Anywhere ? "anywhere" : "passage-middles");
}

bool is_passage_middle(const OccupancyGrid& map, Cell c) {
  if (!map.is_free(c)) return false;
  const bool e = map.is_free({c.x + 1, c.y}), w = map.is_free({c.x - 1, c.y});
  const bool n = map.is_free({c.x, c.y + 1}), s = map.is_free({c.x, c.y - 1});
  return (e && w && !n && !s) || (n && s && !e && !w);
}

std::vector<std::string> check_instance(const Instance& in) {
  std::vector<std::string> out;
  if (in.motion.connectivity != Connectivity::Four) {
    out.push_back("motion must be 4-connected for MAPF (got " + describe(in.motion) + ")");
  }
  if (in.starts.size() != in.goals.size()) {
    out.push_back(std::to_string(in.starts.size()) + " starts but " + std::to_string(in.goals.size()) +
                  " goals");
    return out;
  }
  const auto check_cell = [&](int a, const char* what, Cell c) {
    if (!in.map.in_bounds(c)) {
      out.push_back("agent " + std::to_string(a) + ": " + what + " " + text(c) + " is outside the " +
                    std::to_string(in.map.width()) + " x " + std::to_string(in.map.height()) + " map");
    } else if (!free_cell(in.map, c)) {
      out.push_back("agent " + std::to_string(a) + ": " + what + " " + text(c) + " is on a blocked cell");
    }
  };
  std::map<Cell, int> start_of, goal_of;
  for (int a = 0; a < in.agents(); ++a) {
    check_cell(a, "start", in.starts[a]);
    check_cell(a, "goal", in.goals[a]);
    if (auto [it, fresh] = start_of.emplace(in.starts[a], a); !fresh) {
      out.push_back("agents " + std::to_string(it->second) + " and " + std::to_string(a) +
                    " share the start " + text(in.starts[a]));
    }
    if (auto [it, fresh] = goal_of.emplace(in.goals[a], a); !fresh) {
      out.push_back("agents " + std::to_string(it->second) + " and " + std::to_string(a) +
                    " share the goal " + text(in.goals[a]));
    }
  }
  for (std::size_t r = 0; r < in.reserved.size(); ++r) {
    const Path& p = in.reserved[r];
    const std::string name = "reserved path " + std::to_string(r);
    if (p.empty()) {
      out.push_back(name + " is empty");
      continue;
    }
    for (std::size_t t = 0; t < p.size(); ++t) {
      if (!free_cell(in.map, p[t])) {
        out.push_back(name + ": cell " + text(p[t]) + " at time " + std::to_string(t) + " is not free");
        break;
      }
      if (t > 0 && !in.motion.legal(in.map, p[t - 1], p[t])) {
        out.push_back(name + ": step " + text(p[t - 1]) + " -> " + text(p[t]) + " at time " +
                      std::to_string(t) + " is not a legal move");
        break;
      }
    }
    if (auto it = start_of.find(p.front()); it != start_of.end()) {
      out.push_back("agent " + std::to_string(it->second) + ": start " + text(p.front()) +
                    " is where " + name + " is at time 0");
    }
  }
  if (in.rules.waits == WaitRule::PassageMiddles) {
    if (const std::string lp = lattice_problem(in.map); !lp.empty()) {
      out.push_back(lp);
    } else {
      for (int a = 0; a < in.agents(); ++a) {
        for (const auto& [what, c] : {std::pair{"start", in.starts[a]}, std::pair{"goal", in.goals[a]}}) {
          if (in.map.is_free(c) && is_passage_middle(in.map, c)) {
            out.push_back("agent " + std::to_string(a) + ": " + what + " " + text(c) +
                          " is a passage middle; the paper's rules need an intersection");
          }
        }
      }
    }
  }
  return out;
}

DistanceTable::DistanceTable(const OccupancyGrid& map, const MotionModel& motion, Cell target)
    : dist_(map.size(), kUnreachable) {
  if (!map.is_free(target)) return;
  std::deque<Cell> todo{target};
  dist_[static_cast<std::size_t>(map.index(target))] = 0;
  while (!todo.empty()) {
    const Cell c = todo.front();
    todo.pop_front();
    const int d = dist_[static_cast<std::size_t>(map.index(c))] + 1;
    // Moves are symmetric on a grid (a step c -> n is legal iff n -> c is), so distances from the
    // target are distances to it.
    motion.for_each_neighbour(map, c, [&](Cell n, double) {
      int& dn = dist_[static_cast<std::size_t>(map.index(n))];
      if (dn != kUnreachable) return;
      dn = d;
      todo.push_back(n);
    });
  }
}

std::string feasibility_problem(const Instance& in) {
  // One flood fill labels the connected areas: a goal outside its start's area is unreachable.
  std::vector<int> area(in.map.size(), -1);
  int areas = 0;
  for (int i = 0; i < static_cast<int>(in.map.size()); ++i) {
    if (in.map.at(i) != CellState::Free || area[static_cast<std::size_t>(i)] >= 0) continue;
    std::vector<int> todo{i};
    area[static_cast<std::size_t>(i)] = areas;
    while (!todo.empty()) {
      const Cell c = in.map.cell_of(todo.back());
      todo.pop_back();
      in.motion.for_each_neighbour(in.map, c, [&](Cell n, double) {
        int& an = area[static_cast<std::size_t>(in.map.index(n))];
        if (an < 0) {
          an = areas;
          todo.push_back(in.map.index(n));
        }
      });
    }
    ++areas;
  }
  for (int a = 0; a < in.agents(); ++a) {
    const Cell s = in.starts[static_cast<std::size_t>(a)], g = in.goals[static_cast<std::size_t>(a)];
    if (!in.map.is_free(s) || !in.map.is_free(g)) continue;  // check_instance's job
    if (area[static_cast<std::size_t>(in.map.index(s))] != area[static_cast<std::size_t>(in.map.index(g))]) {
      return "agent " + std::to_string(a) + ": goal " + text(g) + " cannot be reached from start " + text(s);
    }
  }
  if (in.rules.at_goal == GoalRule::Stay) {
    for (std::size_t r = 0; r < in.reserved.size(); ++r) {
      if (in.reserved[r].empty()) continue;
      for (int a = 0; a < in.agents(); ++a) {
        if (in.goals[a] == in.reserved[r].back()) {
          return "agent " + std::to_string(a) + ": goal " + text(in.goals[a]) + " is where reserved path " +
                 std::to_string(r) + " ends and stays for ever";
        }
      }
    }
  }
  return "";
}

bool position_at(const Path& path, int t, bool vanishes, Cell& out) {
  if (path.empty()) return false;
  if (t < static_cast<int>(path.size())) {
    out = path[static_cast<std::size_t>(t)];
    return true;
  }
  if (vanishes) return false;
  out = path.back();
  return true;
}

int path_cost(const Instance& in, int agent, const Path& path) {
  const Cell goal = in.goals[static_cast<std::size_t>(agent)];
  if (path.empty() || path.back() != goal) return kNoCost;
  if (in.rules.at_goal == GoalRule::Vanish) return static_cast<int>(path.size()) - 1;
  int end = static_cast<int>(path.size()) - 1;
  while (end > 0 && path[static_cast<std::size_t>(end - 1)] == goal) --end;
  return end;
}

long long sum_of_costs(const Instance& in, const std::vector<Path>& paths) {
  long long sum = 0;
  for (int a = 0; a < in.agents(); ++a) {
    const int c = a < static_cast<int>(paths.size()) ? path_cost(in, a, paths[a]) : kNoCost;
    if (c == kNoCost) return kNoCost;
    sum += c;
  }
  return sum;
}

int makespan(const Instance& in, const std::vector<Path>& paths) {
  int m = 0;
  for (int a = 0; a < in.agents(); ++a) {
    const int c = a < static_cast<int>(paths.size()) ? path_cost(in, a, paths[a]) : kNoCost;
    if (c == kNoCost) return kNoCost;
    m = std::max(m, c);
  }
  return m;
}

long long lower_bound(const Instance& in) {
  // One A* per agent (unit costs, Manhattan heuristic, buckets of equal f, latest first) over
  // arrays shared by all agents: it expands little more than each path, where a BFS per agent
  // would sweep the whole map (it matters for 1000 agents on a 256 x 257 map).
  const std::size_t cells = in.map.size();
  std::vector<int> g(cells, 0), stamp(cells, -1);
  std::vector<std::vector<int>> bucket;
  long long sum = 0;
  for (int a = 0; a < in.agents(); ++a) {
    const Cell start = in.starts[static_cast<std::size_t>(a)], goal = in.goals[static_cast<std::size_t>(a)];
    if (!in.map.is_free(start) || !in.map.is_free(goal)) return kNoCost;
    const auto h = [&](Cell c) { return static_cast<int>(in.motion.heuristic(c, goal)); };
    for (auto& b : bucket) b.clear();
    const auto push = [&](int idx, int f) {
      if (f >= static_cast<int>(bucket.size())) bucket.resize(static_cast<std::size_t>(f) + 1);
      bucket[static_cast<std::size_t>(f)].push_back(idx);
    };
    const int s = in.map.index(start);
    stamp[static_cast<std::size_t>(s)] = a;
    g[static_cast<std::size_t>(s)] = 0;
    push(s, h(start));
    int found = -1;
    for (std::size_t f = 0; f < bucket.size() && found < 0; ++f) {
      while (!bucket[f].empty() && found < 0) {
        const int idx = bucket[f].back();
        bucket[f].pop_back();
        const Cell c = in.map.cell_of(idx);
        const int gc = g[static_cast<std::size_t>(idx)];
        if (gc + h(c) != static_cast<int>(f)) continue;  // a stale entry
        if (c == goal) {
          found = gc;
          break;
        }
        in.motion.for_each_neighbour(in.map, c, [&](Cell n, double) {
          const int ni = in.map.index(n);
          if (stamp[static_cast<std::size_t>(ni)] == a && g[static_cast<std::size_t>(ni)] <= gc + 1) return;
          stamp[static_cast<std::size_t>(ni)] = a;
          g[static_cast<std::size_t>(ni)] = gc + 1;
          push(ni, gc + 1 + h(n));
        });
      }
    }
    if (found < 0) return kNoCost;
    sum += found;
  }
  return sum;
}

int idle_steps(const Instance& in, int agent, const Path& path) {
  const int cost = path_cost(in, agent, path);
  const int end = cost == kNoCost ? static_cast<int>(path.size()) - 1 : cost;
  int idle = 0;
  for (int t = 1; t <= end; ++t) idle += path[static_cast<std::size_t>(t)] == path[static_cast<std::size_t>(t - 1)];
  return idle;
}

}  // namespace swarm::planner::mapf
