#include "swarm/planner/mapf/instance.hpp"

#include <algorithm>
#include <map>

namespace swarm::planner::mapf {
namespace {

// Is c a place of the instance: a free cell of the map, or a vertex of the graph?
bool is_place(const Instance& in, Cell c) { return in.graph ? cell_vertex(*in.graph, c) >= 0 : in.map.is_free(c); }

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
        return "the map is not a warehouse lattice (cells " + planner::to_string(c) + " and " + planner::to_string(n) +
               " are both " + (middle ? "passage middles" : "intersections") +
               "): the paper's rules need intersections joined by one-cell passages";
      }
    }
  }
  return "";
}

}  // namespace

std::string cell_name(const Instance& in, Cell c) {
  if (in.graph && cell_vertex(*in.graph, c) >= 0) return "vertex " + std::to_string(c.x);
  return planner::to_string(c);
}

std::string step_problem(const Instance& in, Cell from, Cell to) {
  if (!in.graph) {
    const MoveCheck m = in.motion.check(in.map, from, to);
    return m == MoveCheck::Ok || m == MoveCheck::Wait ? "" : to_string(m);
  }
  for (Cell c : {to, from}) {
    if (cell_vertex(*in.graph, c) < 0) return planner::to_string(c) + " names no vertex";
  }
  return from == to || in.graph->adjacent(from.x, to.x) ? "" : "not adjacent";
}

InstanceGraph::InstanceGraph(const Instance& in) {
  if (in.graph) {
    external_ = &*in.graph;
    return;
  }
  const OccupancyGrid& map = in.map;
  width_ = map.width();
  height_ = map.height();
  vertex_of_.assign(map.size(), -1);
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (map.at(i) != CellState::Free) continue;
    vertex_of_[static_cast<std::size_t>(i)] = static_cast<int>(cell_of_.size());
    cell_of_.push_back(map.cell_of(i));
  }
  std::vector<int> first{0}, neighbours;
  std::vector<Position> positions;
  first.reserve(cell_of_.size() + 1);
  neighbours.reserve(cell_of_.size() * 4);
  positions.reserve(cell_of_.size());
  for (const Cell c : cell_of_) {
    in.motion.for_each_neighbour(map, c, [&](Cell n, double) {
      neighbours.push_back(vertex_of_[static_cast<std::size_t>(map.index(n))]);
    });
    first.push_back(static_cast<int>(neighbours.size()));
    positions.push_back({static_cast<double>(c.x), static_cast<double>(c.y)});
  }
  own_ = Graph::from_adjacency(std::move(first), std::move(neighbours), std::move(positions));
}

Instance graph_instance(const Instance& in) {
  if (in.graph) return in;
  const InstanceGraph g(in);
  const auto place = [&](Cell c) { return vertex_cell(g.vertex(c)); };
  Instance out;
  out.graph = g.graph();
  out.rules = in.rules;
  for (const Cell c : in.starts) out.starts.push_back(place(c));
  for (const Cell c : in.goals) out.goals.push_back(place(c));
  for (const Path& p : in.reserved) {
    Path& q = out.reserved.emplace_back();
    for (const Cell c : p) q.push_back(place(c));
  }
  return out;
}

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
  if (in.graph) {
    for (const std::string& p : check_graph(*in.graph)) out.push_back("graph: " + p);
  } else if (in.motion.connectivity != Connectivity::Four) {
    out.push_back("motion must be 4-connected for MAPF (got " + describe(in.motion) + ")");
  }
  if (in.starts.size() != in.goals.size()) {
    out.push_back(std::to_string(in.starts.size()) + " starts but " + std::to_string(in.goals.size()) +
                  " goals");
    return out;
  }
  const auto check_cell = [&](int a, const char* what, Cell c) {
    const std::string agent = "agent " + std::to_string(a) + ": " + what + " ";
    if (in.graph) {
      if (cell_vertex(*in.graph, c) >= 0) return;
      out.push_back(agent + (c.y == 0 ? "vertex " + std::to_string(c.x) + " is not in the " +
                                             std::to_string(in.graph->vertices()) + "-vertex graph"
                                       : planner::to_string(c) + " names no vertex (a graph instance writes vertex v as (v, 0))"));
    } else if (!in.map.in_bounds(c)) {
      out.push_back(agent + planner::to_string(c) + " is outside the " + std::to_string(in.map.width()) + " x " +
                    std::to_string(in.map.height()) + " map");
    } else if (!in.map.is_free(c)) {
      out.push_back(agent + planner::to_string(c) + " is on a blocked cell");
    }
  };
  std::map<Cell, int> start_of, goal_of;
  for (int a = 0; a < in.agents(); ++a) {
    check_cell(a, "start", in.starts[a]);
    check_cell(a, "goal", in.goals[a]);
    if (auto [it, fresh] = start_of.emplace(in.starts[a], a); !fresh) {
      out.push_back("agents " + std::to_string(it->second) + " and " + std::to_string(a) +
                    " share the start " + cell_name(in, in.starts[a]));
    }
    if (auto [it, fresh] = goal_of.emplace(in.goals[a], a); !fresh) {
      out.push_back("agents " + std::to_string(it->second) + " and " + std::to_string(a) +
                    " share the goal " + cell_name(in, in.goals[a]));
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
      if (!is_place(in, p[t])) {
        out.push_back(name + ": cell " + planner::to_string(p[t]) + " at time " + std::to_string(t) + " is not " +
                      (in.graph ? "a vertex" : "free"));
        break;
      }
      if (t > 0 && !step_problem(in, p[t - 1], p[t]).empty()) {
        out.push_back(name + ": step " + cell_name(in, p[t - 1]) + " -> " + cell_name(in, p[t]) + " at time " +
                      std::to_string(t) + " is not a legal move");
        break;
      }
    }
    if (auto it = start_of.find(p.front()); it != start_of.end()) {
      out.push_back("agent " + std::to_string(it->second) + ": start " + cell_name(in, p.front()) +
                    " is where " + name + " is at time 0");
    }
  }
  if (in.rules.waits == WaitRule::PassageMiddles && in.graph) {
    out.push_back("the paper's rules (stops only in passage middles) need a warehouse grid; a graph instance "
                  "takes the standard waits (Rules::standard())");
  } else if (in.rules.waits == WaitRule::PassageMiddles) {
    if (const std::string lp = lattice_problem(in.map); !lp.empty()) {
      out.push_back(lp);
    } else {
      for (int a = 0; a < in.agents(); ++a) {
        for (const auto& [what, c] : {std::pair{"start", in.starts[a]}, std::pair{"goal", in.goals[a]}}) {
          if (in.map.is_free(c) && is_passage_middle(in.map, c)) {
            out.push_back("agent " + std::to_string(a) + ": " + what + " " + planner::to_string(c) +
                          " is a passage middle; the paper's rules need an intersection");
          }
        }
      }
    }
  }
  return out;
}

DistanceTable::DistanceTable(const Graph& graph, int target)
    : dist_(static_cast<std::size_t>(graph.vertices()), kUnreachable) {
  if (!graph.has_vertex(target)) return;
  // Edges are undirected, so distances from the target are distances to it.
  std::vector<int> todo{target};
  todo.reserve(static_cast<std::size_t>(graph.vertices()));
  dist_[static_cast<std::size_t>(target)] = 0;
  for (std::size_t head = 0; head < todo.size(); ++head) {
    const int v = todo[head];
    const int d = dist_[static_cast<std::size_t>(v)] + 1;
    for (const int n : graph.neighbours(v)) {
      int& dn = dist_[static_cast<std::size_t>(n)];
      if (dn != kUnreachable) continue;
      dn = d;
      todo.push_back(n);
    }
  }
}

std::string feasibility_problem(const Instance& in) {
  // One flood fill labels the connected areas: a goal outside its start's area is unreachable.
  const InstanceGraph g(in);
  const Graph& graph = g.graph();
  std::vector<int> area(static_cast<std::size_t>(graph.vertices()), -1);
  int areas = 0;
  for (int v = 0; v < graph.vertices(); ++v) {
    if (area[static_cast<std::size_t>(v)] >= 0) continue;
    std::vector<int> todo{v};
    area[static_cast<std::size_t>(v)] = areas;
    while (!todo.empty()) {
      const int u = todo.back();
      todo.pop_back();
      for (const int n : graph.neighbours(u)) {
        int& an = area[static_cast<std::size_t>(n)];
        if (an < 0) {
          an = areas;
          todo.push_back(n);
        }
      }
    }
    ++areas;
  }
  for (int a = 0; a < in.agents(); ++a) {
    const Cell s = in.starts[static_cast<std::size_t>(a)], goal = in.goals[static_cast<std::size_t>(a)];
    const int vs = g.vertex(s), vg = g.vertex(goal);
    if (vs < 0 || vg < 0) continue;  // check_instance's job
    if (area[static_cast<std::size_t>(vs)] != area[static_cast<std::size_t>(vg)]) {
      return "agent " + std::to_string(a) + ": goal " + cell_name(in, goal) + " cannot be reached from start " +
             cell_name(in, s);
    }
  }
  if (in.rules.at_goal == GoalRule::Stay) {
    for (std::size_t r = 0; r < in.reserved.size(); ++r) {
      if (in.reserved[r].empty()) continue;
      for (int a = 0; a < in.agents(); ++a) {
        if (in.goals[a] == in.reserved[r].back()) {
          return "agent " + std::to_string(a) + ": goal " + cell_name(in, in.goals[a]) + " is where reserved path " +
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
  // One A* per agent (unit costs, buckets of equal f, latest first) over arrays shared by all
  // agents: on a grid, with the Manhattan heuristic, it expands little more than each path, where a
  // BFS per agent would sweep the whole map (it matters for 1000 agents on a 256 x 257 map). A
  // graph has no geometry: the heuristic is 0 (a BFS).
  const InstanceGraph ig(in);
  const Graph& graph = ig.graph();
  const auto vertices = static_cast<std::size_t>(graph.vertices());
  std::vector<int> g(vertices, 0), stamp(vertices, -1);
  std::vector<std::vector<int>> bucket;
  long long sum = 0;
  for (int a = 0; a < in.agents(); ++a) {
    const Cell goal = in.goals[static_cast<std::size_t>(a)];
    const int s = ig.vertex(in.starts[static_cast<std::size_t>(a)]), target = ig.vertex(goal);
    if (s < 0 || target < 0) return kNoCost;
    const auto h = [&](int v) { return ig.on_grid() ? static_cast<int>(in.motion.heuristic(ig.cell(v), goal)) : 0; };
    for (auto& b : bucket) b.clear();
    const auto push = [&](int v, int f) {
      if (f >= static_cast<int>(bucket.size())) bucket.resize(static_cast<std::size_t>(f) + 1);
      bucket[static_cast<std::size_t>(f)].push_back(v);
    };
    stamp[static_cast<std::size_t>(s)] = a;
    g[static_cast<std::size_t>(s)] = 0;
    push(s, h(s));
    int found = -1;
    for (std::size_t f = 0; f < bucket.size() && found < 0; ++f) {
      while (!bucket[f].empty() && found < 0) {
        const int v = bucket[f].back();
        bucket[f].pop_back();
        const int gv = g[static_cast<std::size_t>(v)];
        if (gv + h(v) != static_cast<int>(f)) continue;  // a stale entry
        if (v == target) {
          found = gv;
          break;
        }
        for (const int n : graph.neighbours(v)) {
          if (stamp[static_cast<std::size_t>(n)] == a && g[static_cast<std::size_t>(n)] <= gv + 1) continue;
          stamp[static_cast<std::size_t>(n)] = a;
          g[static_cast<std::size_t>(n)] = gv + 1;
          push(n, gv + 1 + h(n));
        }
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
