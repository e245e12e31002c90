#include "swarm/planner/mapf/validate.hpp"

#include <algorithm>

namespace swarm::planner::mapf {
namespace {

std::string text(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

std::string entity_name(int e) {
  return e >= 0 ? "agent " + std::to_string(e) : "reserved path " + std::to_string(-1 - e);
}

// The path's own legality: endpoints, moves (motion.hpp) and, under the paper's rules, where and
// how long it waits and that it never turns back inside a passage.
void check_path(const Instance& in, int a, const Path& p, std::vector<PathProblem>& out) {
  const auto problem = [&](int t, std::string what) { out.push_back({a, t, std::move(what)}); };
  if (p.empty()) {
    problem(0, "the path is empty");
    return;
  }
  const Cell start = in.starts[static_cast<std::size_t>(a)];
  const Cell goal = in.goals[static_cast<std::size_t>(a)];
  if (p.front() != start) problem(0, "starts at " + text(p.front()) + ", not at its start " + text(start));
  if (p.back() != goal) {
    problem(static_cast<int>(p.size()) - 1, "ends at " + text(p.back()) + ", not at its goal " + text(goal));
  }
  for (std::size_t t = 1; t < p.size(); ++t) {
    const MoveCheck m = in.motion.check(in.map, p[t - 1], p[t]);
    if (m != MoveCheck::Ok && m != MoveCheck::Wait) {
      problem(static_cast<int>(t), "step " + text(p[t - 1]) + " -> " + text(p[t]) + ": " + to_string(m));
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
        problem(static_cast<int>(begin) + 1, "waits at intersection " + text(p[begin]) +
                                                 " after it has moved (stops only in passage middles)");
      } else if (waits % 2 != 0) {
        problem(static_cast<int>(begin) + 1, "stops " + std::to_string(waits) + " steps at " + text(p[begin]) +
                                                 " (stops last 2 steps each)");
      }
    }
    if (middle && begin > 0 && !last_run && p[begin - 1] == p[end]) {
      problem(static_cast<int>(end), "turns back inside the passage at " + text(p[begin]));
    }
    moved = moved || end < p.size();
    begin = end;
  }
}

}  // namespace

std::string describe(const Conflict& c) {
  const std::string who = entity_name(c.a) + " and " + entity_name(c.b);
  if (c.kind == ConflictKind::Vertex) {
    return "vertex conflict of " + who + " at " + text(c.cell) + ", time " + std::to_string(c.time);
  }
  return "swap conflict of " + who + " between " + text(c.cell) + " and " + text(c.other) + ", step " +
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

  // Per time step: the occupants of each cell as linked lists (head per cell, next per entity).
  const std::size_t cells = in.map.size();
  std::vector<int> head_prev(cells, -1), head_now(cells, -1), next_prev(total, -1), next_now(total, -1);
  std::vector<int> touched_prev, touched_now;
  std::vector<Cell> pos_prev(total), pos_now(total);
  std::vector<char> here_prev(total, 0), here_now(total, 0);
  const auto add_conflict = [&](ConflictKind kind, int e, int f, Cell cell, Cell other, int t) {
    if (e >= n && f >= n) return;  // two reserved robots: not ours to judge
    if (f < e) {
      std::swap(e, f);
      if (kind == ConflictKind::Swap) std::swap(cell, other);
    }
    r.conflicts.push_back({kind, name(e), name(f), cell, other, t});
  };
  for (int t = 0; t < static_cast<int>(horizon); ++t) {
    for (int idx : touched_now) head_now[static_cast<std::size_t>(idx)] = -1;
    touched_now.clear();
    for (int e = 0; e < total; ++e) {
      Cell c;
      here_now[e] = position_at(path_of(e), t, vanish && e < n, c) && in.map.in_bounds(c);
      if (!here_now[e]) continue;
      pos_now[e] = c;
      const int idx = in.map.index(c);
      if (head_now[static_cast<std::size_t>(idx)] == -1) touched_now.push_back(idx);
      next_now[e] = head_now[static_cast<std::size_t>(idx)];
      head_now[static_cast<std::size_t>(idx)] = e;
    }
    for (int idx : touched_now) {  // vertex conflicts: every pair on one cell
      for (int e = head_now[static_cast<std::size_t>(idx)]; e != -1; e = next_now[e]) {
        for (int f = next_now[e]; f != -1; f = next_now[f]) {
          add_conflict(ConflictKind::Vertex, e, f, pos_now[e], pos_now[e], t);
        }
      }
    }
    if (t > 0) {  // swap conflicts: e went u -> v while some f went v -> u
      for (int e = 0; e < total; ++e) {
        if (!here_now[e] || !here_prev[e] || pos_now[e] == pos_prev[e]) continue;
        for (int f = head_prev[static_cast<std::size_t>(in.map.index(pos_now[e]))]; f != -1; f = next_prev[f]) {
          if (f > e && here_now[f] && pos_now[f] == pos_prev[e]) {
            add_conflict(ConflictKind::Swap, e, f, pos_prev[e], pos_now[e], t);
          }
        }
      }
    }
    std::swap(head_prev, head_now);
    std::swap(next_prev, next_now);
    std::swap(touched_prev, touched_now);
    std::swap(pos_prev, pos_now);
    std::swap(here_prev, here_now);
  }
  return r;
}

}  // namespace swarm::planner::mapf
