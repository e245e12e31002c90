// The optimal sum of costs of a small MAPF instance (standard rules) by brute force, grid or
// graph alike (InstanceGraph's moves): the reference the solver tests hold CBS to. -1 if there is
// no plan. Exponential: a handful of agents on a few dozen vertices only.
#pragma once

#include <map>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

#include "swarm/planner/mapf/instance.hpp"

namespace swarm::test {

// Dijkstra over (every agent's vertex, which agents have "settled" on their goal for good). An
// unsettled agent pays 1 per step; a settled one stays put and pays nothing, so an agent's cost is
// the step of its last arrival.
inline long long brute_force_soc(const planner::mapf::Instance& in) {
  const planner::mapf::InstanceGraph g(in);
  const int n = in.agents();
  using State = std::pair<std::vector<int>, int>;  // vertices, settled mask
  std::map<State, long long> best;
  using Item = std::tuple<long long, std::vector<int>, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  std::vector<int> start, goal;
  for (int a = 0; a < n; ++a) {
    start.push_back(g.vertex(in.starts[static_cast<std::size_t>(a)]));
    goal.push_back(g.vertex(in.goals[static_cast<std::size_t>(a)]));
  }
  open.push({0, start, 0});
  const int all = (1 << n) - 1;
  while (!open.empty()) {
    auto [cost, at, mask] = open.top();
    open.pop();
    if (auto it = best.find({at, mask}); it != best.end() && it->second <= cost) continue;
    best[{at, mask}] = cost;
    if (mask == all) return cost;
    // Settle any agent on its goal (free).
    for (int a = 0; a < n; ++a) {
      if (!(mask >> a & 1) && at[a] == goal[a]) open.push({cost, at, mask | (1 << a)});
    }
    // Every joint move of the unsettled agents.
    std::vector<std::vector<int>> options(n);
    for (int a = 0; a < n; ++a) {
      options[a].push_back(at[a]);
      if (mask >> a & 1) continue;
      for (const int v : g.graph().neighbours(at[a])) options[a].push_back(v);
    }
    std::vector<int> pick(n, 0), next(n);
    while (true) {
      for (int a = 0; a < n; ++a) next[a] = options[a][pick[a]];
      bool ok = true;
      for (int a = 0; a < n && ok; ++a) {
        for (int b = a + 1; b < n && ok; ++b) ok = next[a] != next[b] && !(next[a] == at[b] && next[b] == at[a]);
      }
      if (ok) open.push({cost + (n - __builtin_popcount(mask)), next, mask});
      int a = 0;
      while (a < n && ++pick[a] == static_cast<int>(options[a].size())) pick[a++] = 0;
      if (a == n) break;
    }
  }
  return -1;
}

}  // namespace swarm::test
