#include "swarm/planner/mapf/adg.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace swarm::planner::mapf {

namespace {

std::int64_t key(Cell c) { return (static_cast<std::int64_t>(c.x) << 32) ^ static_cast<std::uint32_t>(c.y); }

struct Visit {
  int time;  // the plan's time step of entering the cell
  int robot;
  std::uint32_t step;
};

std::string where(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

// A rotation: robots that the plan moves round a cycle of cells in one time step (legal in MAPF and
// in the simulator, where a rotation of three or more moves together). Each of them would wait for
// the one ahead to leave first: a cycle in the graph. Such a step is one joint action instead: the
// need on the one ahead becomes "stands on the cell" (step - 1), and releasable() releases the
// members together (rotation_of / rotations).
void join_rotations(Dependencies& d) {
  d.rotation_of.resize(d.routes.size());
  for (std::size_t r = 0; r < d.routes.size(); ++r) d.rotation_of[r].assign(d.routes[r].size(), -1);
  // A follow need: robot j leaves the cell at the very time step this robot enters it. Each step
  // has at most one (one robot can stand on a cell before); rotations are cycles of them.
  const auto follow_of = [&d](std::size_t r, std::uint32_t k) -> const Need* {
    for (const Need& n : d.needs[r][k]) {
      if (d.planned_time[static_cast<std::size_t>(n.robot)][n.step] == d.planned_time[r][k]) return &n;
    }
    return nullptr;
  };
  std::vector<std::pair<std::size_t, std::uint32_t>> cycle;
  for (std::size_t r = 0; r < d.routes.size(); ++r) {
    for (std::uint32_t k = 1; k < d.routes[r].size(); ++k) {
      // Walk the follow needs from (r, k); at most one per robot can be in a rotation at one time.
      cycle.clear();
      std::size_t at = r;
      std::uint32_t step = k;
      bool closed = false;
      for (std::size_t hops = 0; hops <= d.routes.size(); ++hops) {
        cycle.emplace_back(at, step);
        const Need* n = follow_of(at, step);
        if (n == nullptr) break;
        at = static_cast<std::size_t>(n->robot);
        step = n->step;
        if (at == r && step == k) {
          closed = true;
          break;
        }
      }
      if (!closed) continue;
      d.rotations.emplace_back();
      for (const auto& [robot, s] : cycle) {
        d.rotation_of[robot][s] = static_cast<int>(d.rotations.size() - 1);
        d.rotations.back().push_back({static_cast<int>(robot), s});
        for (Need& n : d.needs[robot][s]) {
          if (d.planned_time[static_cast<std::size_t>(n.robot)][n.step] == d.planned_time[robot][s]) --n.step;
        }
      }
    }
  }
}

// Numbers the rotations in the order of their time step (stable: the order found among those of
// one step), so that a plan grown at its end (the traffic layer's next window appended) keeps the
// numbers of the rotations it had: a rotation's number is what the GCS orders it by.
void number_by_time(Dependencies& d) {
  const auto time_of = [&d](const std::vector<Need>& q) {
    return d.planned_time[static_cast<std::size_t>(q.front().robot)][q.front().step];
  };
  std::stable_sort(d.rotations.begin(), d.rotations.end(),
                   [&](const std::vector<Need>& a, const std::vector<Need>& b) { return time_of(a) < time_of(b); });
  for (std::size_t q = 0; q < d.rotations.size(); ++q) {
    for (const Need& m : d.rotations[q]) d.rotation_of[static_cast<std::size_t>(m.robot)][m.step] = static_cast<int>(q);
  }
}

}  // namespace

Dependencies dependencies(const std::vector<Path>& paths) {
  const std::size_t n = paths.size();
  Dependencies d;
  d.routes.resize(n);
  d.planned_time.resize(n);
  d.needs.resize(n);
  std::unordered_map<std::int64_t, std::vector<Visit>> visits;
  for (std::size_t r = 0; r < n; ++r) {
    if (paths[r].empty()) throw std::invalid_argument("robot " + std::to_string(r) + " has an empty path");
    for (std::size_t t = 0; t < paths[r].size(); ++t) {
      if (t > 0 && paths[r][t] == paths[r][t - 1]) continue;  // a wait: not an action of the route
      const auto step = static_cast<std::uint32_t>(d.routes[r].size());
      d.routes[r].push_back(paths[r][t]);
      d.planned_time[r].push_back(static_cast<int>(t));
      visits[key(paths[r][t])].push_back({static_cast<int>(t), static_cast<int>(r), step});
    }
  }
  for (std::size_t r = 0; r < n; ++r) {
    const auto& route = d.routes[r];
    d.needs[r].resize(route.size());
    for (std::uint32_t k = 1; k < route.size(); ++k) {
      const int time = d.planned_time[r][k];
      std::unordered_map<int, std::uint32_t> latest;  // robot -> the step after its latest earlier visit
      for (const Visit& v : visits[key(route[k])]) {
        if (v.robot == static_cast<int>(r)) continue;
        const auto& other = d.routes[static_cast<std::size_t>(v.robot)];
        const bool stays = v.step + 1 == other.size();  // its goal: it never leaves
        const int leaves = stays ? -1 : d.planned_time[static_cast<std::size_t>(v.robot)][v.step + 1];
        if (v.time == time || (v.time < time && (stays || leaves > time))) {
          throw std::invalid_argument("the plan has robots " + std::to_string(r) + " and " + std::to_string(v.robot) +
                                      " on " + where(route[k]) + " at time " + std::to_string(time));
        }
        if (v.time > time) continue;  // it comes after this robot: its own needs say so
        auto [it, fresh] = latest.try_emplace(v.robot, v.step + 1);
        if (!fresh && it->second < v.step + 1) it->second = v.step + 1;
      }
      for (const auto& [robot, step] : latest) d.needs[r][k].push_back({robot, step});
      // Deterministic order (the map's is not).
      std::sort(d.needs[r][k].begin(), d.needs[r][k].end(),
                [](const Need& a, const Need& b) { return a.robot < b.robot; });
    }
  }
  join_rotations(d);
  number_by_time(d);
  return d;
}

namespace {

bool met(const Dependencies& adg, std::size_t robot, std::uint32_t k, const std::vector<std::uint32_t>& progress) {
  for (const Need& n : adg.needs[robot][k]) {
    if (progress[static_cast<std::size_t>(n.robot)] < n.step) return false;
  }
  return true;
}

// Every member of rotation q stands on the cell before its step of it (or is past it) and every
// need of every step of it is met.
bool rotation_may_go(const Dependencies& adg, std::size_t q, const std::vector<std::uint32_t>& progress) {
  for (const Need& m : adg.rotations[q]) {
    const auto mr = static_cast<std::size_t>(m.robot);
    if (progress[mr] + 1 < m.step || !met(adg, mr, m.step, progress)) return false;
  }
  return true;
}

}  // namespace

std::uint32_t releasable(const Dependencies& adg, int robot, const std::vector<std::uint32_t>& progress,
                         Rotations rotations) {
  const auto r = static_cast<std::size_t>(robot);
  const auto& needs = adg.needs[r];
  for (std::uint32_t k = 1; k < needs.size(); ++k) {
    if (!met(adg, r, k, progress)) return k - 1;
    // A rotation step the robot has made is behind it, whoever released it.
    if (const int q = adg.rotation_of.empty() || k <= progress[r] ? -1 : adg.rotation_of[r][k]; q >= 0) {
      if (rotations == Rotations::Held || !rotation_may_go(adg, static_cast<std::size_t>(q), progress)) return k - 1;
    }
  }
  return needs.empty() ? 0 : static_cast<std::uint32_t>(needs.size() - 1);
}

std::vector<int> ready_rotations(const Dependencies& adg, const std::vector<std::uint32_t>& progress) {
  std::vector<int> out;
  for (std::size_t q = 0; q < adg.rotations.size(); ++q) {
    bool at_start = true;
    for (const Need& m : adg.rotations[q]) at_start = at_start && progress[static_cast<std::size_t>(m.robot)] + 1 == m.step;
    if (at_start && rotation_may_go(adg, q, progress)) out.push_back(static_cast<int>(q));
  }
  return out;
}

std::uint32_t step_at(const Dependencies& adg, int robot, int time) {
  const std::vector<int>& t = adg.planned_time.at(static_cast<std::size_t>(robot));
  const auto after = std::upper_bound(t.begin(), t.end(), time);
  return after == t.begin() ? 0 : static_cast<std::uint32_t>(after - t.begin() - 1);
}

std::uint32_t last_time(const std::vector<Path>& paths) {
  std::size_t last = 0;
  for (const Path& p : paths) last = std::max(last, p.empty() ? 0 : p.size() - 1);
  return static_cast<std::uint32_t>(last);
}

std::uint32_t progress_at(const Dependencies& adg, int robot, std::uint32_t progress, Cell at) {
  const std::vector<Cell>& route = adg.routes.at(static_cast<std::size_t>(robot));
  const std::size_t next = static_cast<std::size_t>(progress) + 1;
  return next < route.size() && route[next] == at ? progress + 1 : progress;
}

}  // namespace swarm::planner::mapf
