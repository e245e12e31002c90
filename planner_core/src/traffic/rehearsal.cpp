#include "swarm/planner/traffic/rehearsal.hpp"

#include <algorithm>
#include <stdexcept>

#include "swarm/planner/mapf/adg.hpp"

namespace swarm::planner::traffic {

Rehearsal rehearse(const OccupancyGrid& map, const MotionModel& motion, std::vector<Agent> agents, int window,
                   const Config& config, int max_steps) {
  Rehearsal out;
  Planner planner(map, motion, config);
  const auto has_goals = [&] {
    return std::any_of(agents.begin(), agents.end(), [](const Agent& a) { return !a.fixed && !a.goals.empty(); });
  };
  out.paths.resize(agents.size());
  int at = 0;
  while (has_goals() && at < max_steps) {
    const Window w = planner.plan(agents, window);
    for (std::size_t a = 0; a < agents.size(); ++a) {
      Agent& agent = agents[a];
      auto& path = out.paths[a];
      path.insert(path.end(), w.paths[a].begin() + (path.empty() ? 0 : 1), w.paths[a].end());
      for (std::size_t k = 1; k < w.paths[a].size(); ++k) out.moves += w.paths[a][k] != w.paths[a][k - 1] ? 1 : 0;
      const auto done = static_cast<std::size_t>(w.done[a]);
      for (std::size_t k = 0; k < done; ++k) {
        const int time = w.reached_at[a][k];
        if (time < 0) ++out.skipped;
        out.makespan = std::max(out.makespan, at + std::max(time, 0));
      }
      agent.goals.erase(agent.goals.begin(), agent.goals.begin() + static_cast<std::ptrdiff_t>(std::min(done, agent.goals.size())));
      agent.at = w.paths[a].back();
    }
    at += window;
  }
  out.finished = !has_goals();
  if (!out.finished) out.makespan = max_steps;
  return out;
}

namespace {

// A plan's steps in the order its drive takes them, and its graph: built once, timed for any
// arrival ticks.
struct DriveOrder {
  struct Step {
    int time, robot;
    std::uint32_t k;
  };
  mapf::Dependencies adg;
  std::vector<Step> steps;
};

DriveOrder drive_order(const std::vector<std::vector<Cell>>& paths) {
  DriveOrder o{mapf::dependencies(paths), {}};
  for (std::size_t r = 0; r < o.adg.routes.size(); ++r) {
    for (std::uint32_t k = 1; k < o.adg.routes[r].size(); ++k) {
      o.steps.push_back({o.adg.planned_time[r][k], static_cast<int>(r), k});
    }
  }
  std::stable_sort(o.steps.begin(), o.steps.end(),
                   [](const DriveOrder::Step& a, const DriveOrder::Step& b) { return a.time < b.time; });
  return o;
}

int time_drive(const DriveOrder& o, const std::function<int(int, int)>& lag, const std::vector<int>& start) {
  const mapf::Dependencies& adg = o.adg;
  const auto& steps = o.steps;
  using Step = DriveOrder::Step;
  // Every step in the order the plan has them. A need is on a step planned earlier, or, where the
  // plan has one robot follow another into the cell it leaves, on a step of the same time: those
  // are taken in the order of their chain (a follow costs the lag like any other need, since the
  // follower sets off only once it sees the cell left). A rotation's needs are on its members'
  // earlier steps (adg.hpp), and its members move in one tick.
  std::vector<std::vector<int>> entered(adg.routes.size());
  for (std::size_t r = 0; r < adg.routes.size(); ++r) {
    entered[r].assign(adg.routes[r].size(), -1);
    entered[r][0] = r < start.size() ? start[r] : 0;
  }
  int last = 0;
  std::vector<Step> pending;
  for (std::size_t begin = 0; begin < steps.size();) {
    std::size_t end = begin;
    while (end < steps.size() && steps[end].time == steps[begin].time) ++end;
    // One time step: a step whose followed step is not timed yet waits for the next pass (a chain
    // of n follows takes n passes). Then a rotation's members go at the latest of them: no robot
    // outside a rotation follows one of its members in its step (the cell left is its next
    // member's), so nothing timed in this step depends on that.
    pending.assign(steps.begin() + static_cast<std::ptrdiff_t>(begin), steps.begin() + static_cast<std::ptrdiff_t>(end));
    while (!pending.empty()) {
      const std::size_t before = pending.size();
      std::erase_if(pending, [&](const Step& s) {
        const auto r = static_cast<std::size_t>(s.robot);
        int t = entered[r][s.k - 1] + 1;
        for (const mapf::Need& n : adg.needs[r][s.k]) {
          const int left = entered[static_cast<std::size_t>(n.robot)][n.step];
          if (left < 0) return false;
          t = std::max(t, left + lag(n.robot, s.robot));
        }
        entered[r][s.k] = t;
        return true;
      });
      if (pending.size() == before) throw std::invalid_argument("driven_ticks: follows in a cycle that is no rotation");
    }
    for (std::size_t i = begin; i < end; ++i) {
      const int q = adg.rotation_of[static_cast<std::size_t>(steps[i].robot)][steps[i].k];
      if (q < 0) continue;
      const auto& members = adg.rotations[static_cast<std::size_t>(q)];
      int together = 0;
      for (const mapf::Need& m : members) together = std::max(together, entered[static_cast<std::size_t>(m.robot)][m.step]);
      for (const mapf::Need& m : members) entered[static_cast<std::size_t>(m.robot)][m.step] = together;
    }
    for (std::size_t i = begin; i < end; ++i) {
      last = std::max(last, entered[static_cast<std::size_t>(steps[i].robot)][steps[i].k]);
    }
    begin = end;
  }
  return last;
}

}  // namespace

int driven_ticks(const std::vector<std::vector<Cell>>& paths, const std::function<int(int, int)>& lag,
                 const std::vector<int>& start) {
  return time_drive(drive_order(paths), lag, start);
}

std::vector<int> driven_ticks_per_start(const std::vector<std::vector<Cell>>& paths,
                                        const std::function<int(int, int)>& lag,
                                        const std::vector<std::vector<int>>& starts) {
  const DriveOrder order = drive_order(paths);
  std::vector<int> out;
  out.reserve(starts.size());
  for (const std::vector<int>& start : starts) out.push_back(time_drive(order, lag, start));
  return out;
}

}  // namespace swarm::planner::traffic
