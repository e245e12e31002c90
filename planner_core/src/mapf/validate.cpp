#include "swarm/planner/mapf/validate.hpp"

#include <algorithm>

#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner::mapf {
namespace {

std::string entity_name(int e) {
  return e >= 0 ? "agent " + std::to_string(e) : "reserved path " + std::to_string(-1 - e);
}

// The path's own legality: endpoints, moves (step_problem: motion.hpp on a grid, edges on a graph)
// and, under the paper's rules, where and how long it waits and that it never turns back inside a
// passage.
void check_path(const Instance& in, int a, const Path& p, std::vector<PathProblem>& out) {
  const auto problem = [&](int t, std::string what) { out.push_back({a, t, std::move(what)}); };
  if (p.empty()) {
    problem(0, "the path is empty");
    return;
  }
  const Cell start = in.starts[static_cast<std::size_t>(a)];
  const Cell goal = in.goals[static_cast<std::size_t>(a)];
  const auto name = [&](Cell c) { return cell_name(in, c); };
  if (p.front() != start) problem(0, "starts at " + name(p.front()) + ", not at its start " + name(start));
  if (p.back() != goal) {
    problem(static_cast<int>(p.size()) - 1, "ends at " + name(p.back()) + ", not at its goal " + name(goal));
  }
  for (std::size_t t = 1; t < p.size(); ++t) {
    if (const std::string why = step_problem(in, p[t - 1], p[t]); !why.empty()) {
      problem(static_cast<int>(t), "step " + name(p[t - 1]) + " -> " + name(p[t]) + ": " + why);
    }
  }
  if (in.rules.at_goal == GoalRule::Vanish) {
    const auto first = std::find(p.begin(), p.end(), goal);
    if (first != p.end() && first + 1 != p.end()) {
      problem(static_cast<int>(first - p.begin()),
              "reaches its goal and goes on (under the vanish rule it leaves on arrival)");
    }
  }
  if (in.rules.waits != WaitRule::PassageMiddles) return;
  // Runs of one cell: [begin, end) time steps on the same cell.
  std::size_t begin = 0;
  bool moved = false;
  while (begin < p.size()) {
    std::size_t end = begin + 1;
    while (end < p.size() && p[end] == p[begin]) ++end;
    const std::size_t waits = end - begin - 1;
    const bool last_run = end == p.size();
    const bool middle = is_passage_middle(in.map, p[begin]);
    if (waits > 0 && !(last_run && p[begin] == goal && in.rules.at_goal == GoalRule::Stay)) {
      if (!middle && moved) {
        problem(static_cast<int>(begin) + 1, "waits at intersection " + planner::to_string(p[begin]) +
                                                 " after it has moved (stops only in passage middles)");
      } else if (waits % 2 != 0) {
        problem(static_cast<int>(begin) + 1, "stops " + std::to_string(waits) + " steps at " + planner::to_string(p[begin]) +
                                                 " (stops last 2 steps each)");
      }
    }
    if (middle && begin > 0 && !last_run && p[begin - 1] == p[end]) {
      problem(static_cast<int>(end), "turns back inside the passage at " + planner::to_string(p[begin]));
    }
    moved = moved || end < p.size();
    begin = end;
  }
}

}  // namespace

std::string describe(const Conflict& c) {
  const std::string who = entity_name(c.a) + " and " + entity_name(c.b);
  if (c.kind == ConflictKind::Vertex) {
    return "vertex conflict of " + who + " at " + planner::to_string(c.cell) + ", time " + std::to_string(c.time);
  }
  return "swap conflict of " + who + " between " + planner::to_string(c.cell) + " and " + planner::to_string(c.other) + ", step " +
         std::to_string(c.time - 1) + " -> " + std::to_string(c.time);
}

std::string ValidationReport::summary() const {
  if (ok()) return "valid";
  std::string s = std::to_string(conflicts.size()) + " conflicts, " + std::to_string(problems.size()) +
                  " path problems (first: ";
  if (!problems.empty()) {
    s += "agent " + std::to_string(problems.front().agent) + " at time " + std::to_string(problems.front().time) +
         ": " + problems.front().what;
  } else {
    s += describe(conflicts.front());
  }
  return s + ")";
}

ValidationReport validate(const Instance& in, const std::vector<Path>& paths) {
  ValidationReport r;
  const int n = in.agents();
  if (static_cast<int>(paths.size()) != n) {
    r.problems.push_back({0, 0, std::to_string(paths.size()) + " paths for " + std::to_string(n) + " agents"});
    return r;
  }
  for (int a = 0; a < n; ++a) check_path(in, a, paths[a], r.problems);

  // Entities: planned agents 0..n-1, then reserved robots n..n+R-1 (named -1 - r).
  const int total = n + static_cast<int>(in.reserved.size());
  const auto path_of = [&](int e) -> const Path& {
    return e < n ? paths[static_cast<std::size_t>(e)] : in.reserved[static_cast<std::size_t>(e - n)];
  };
  const auto name = [&](int e) { return e < n ? e : -1 - (e - n); };
  const bool vanish = in.rules.at_goal == GoalRule::Vanish;
  std::size_t horizon = 0;
  for (int e = 0; e < total; ++e) horizon = std::max(horizon, path_of(e).size());

  // Per time step, the conflicts among the entities present (a vanished agent is gone) come from
  // the motion model's one definition (planner::find_step_conflicts, which the simulator uses to
  // resolve moves), turned into pairs as CBS needs them: a cell held by k robots is k(k-1)/2
  // vertex conflicts here, one event in the simulator's count.
  const auto add_conflict = [&](ConflictKind kind, int e, int f, Cell cell, Cell other, int t) {
    if (e >= n && f >= n) return;  // two reserved robots: not ours to judge
    if (f < e) {
      std::swap(e, f);
      if (kind == ConflictKind::Swap) std::swap(cell, other);
    }
    r.conflicts.push_back({kind, name(e), name(f), cell, other, t});
  };
  // Places outside the map (a graph: cells naming no vertex) are path problems above, not conflicts.
  const auto placed = [&](Cell c) { return in.graph ? cell_vertex(*in.graph, c) >= 0 : in.map.in_bounds(c); };
  std::vector<int> present;  // entity ids present at t (and so at t - 1: agents only vanish)
  std::vector<Cell> from, to;
  for (int t = 0; t < static_cast<int>(horizon); ++t) {
    present.clear();
    from.clear();
    to.clear();
    for (int e = 0; e < total; ++e) {
      Cell now, before;
      if (!position_at(path_of(e), t, vanish && e < n, now) || !placed(now)) continue;
      // At t = 0 (and for an entity that was not there before) the step is a wait: no swap.
      if (t == 0 || !position_at(path_of(e), t - 1, vanish && e < n, before) || !placed(before)) before = now;
      present.push_back(e);
      from.push_back(before);
      to.push_back(now);
    }
    const planner::StepConflicts c = planner::find_step_conflicts(from, to);
    for (const planner::VertexConflict& v : c.vertex) {
      for (std::size_t i = 0; i < v.robots.size(); ++i) {
        for (std::size_t j = i + 1; j < v.robots.size(); ++j) {
          add_conflict(ConflictKind::Vertex, present[static_cast<std::size_t>(v.robots[i])],
                       present[static_cast<std::size_t>(v.robots[j])], v.cell, v.cell, t);
        }
      }
    }
    for (const planner::EdgeConflict& x : c.edge) {
      const auto a = static_cast<std::size_t>(x.a);
      add_conflict(ConflictKind::Swap, present[a], present[static_cast<std::size_t>(x.b)], from[a], to[a], t);
    }
  }
  return r;
}

}  // namespace swarm::planner::mapf
