#include "swarm/planner/traffic/rehearsal.hpp"

#include <algorithm>

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

int driven_ticks(const std::vector<std::vector<Cell>>& paths, const std::function<int(int, int)>& lag) {
  const mapf::Dependencies adg = mapf::dependencies(paths);
  // Every step in the order the plan has them: a need is always a step planned earlier, but for a
  // rotation's, planned at the same time.
  struct Step {
    int time, robot;
    std::uint32_t k;
  };
  std::vector<Step> steps;
  std::vector<std::vector<int>> entered(adg.routes.size());
  for (std::size_t r = 0; r < adg.routes.size(); ++r) {
    entered[r].assign(adg.routes[r].size(), 0);
    for (std::uint32_t k = 1; k < adg.routes[r].size(); ++k) steps.push_back({adg.planned_time[r][k], static_cast<int>(r), k});
  }
  std::stable_sort(steps.begin(), steps.end(), [](const Step& a, const Step& b) { return a.time < b.time; });
  int last = 0;
  for (const Step& s : steps) {
    const auto r = static_cast<std::size_t>(s.robot);
    int t = entered[r][s.k - 1] + 1;
    for (const mapf::Need& n : adg.needs[r][s.k]) {
      const auto j = static_cast<std::size_t>(n.robot);
      if (adg.planned_time[j][n.step] >= s.time) continue;  // a rotation: together
      t = std::max(t, entered[j][n.step] + lag(n.robot, s.robot));
    }
    entered[r][s.k] = t;
    last = std::max(last, t);
  }
  return last;
}

}  // namespace swarm::planner::traffic
