// The single-agent search under the solvers: space-time A* (w = 1) or focal search (w > 1,
// Barer et al., "Suboptimal variants of the conflict-based search algorithm", SoCS 2014) over
// (agent state, time step), with
//   - the agent's constraints from the CBS tree (vertex: not on vertex c at time t; edge: not the
//     move u -> v ending at time t),
//   - reserved robots (hard: never share a vertex or swap with one),
//   - a conflict-avoidance table of the other agents' paths (soft: among equally good nodes, the
//     fewest conflicts first; with w > 1 it is FOCAL's order),
//   - the exact distance to the goal as heuristic (BFS, instance.hpp).
// It always terminates: past the last time step at which anything changes (constraints,
// reservations, other paths) the world is static, so later time steps are folded into one.
#pragma once

#include <functional>
#include <vector>

#include "agent_model.hpp"
#include "path_table.hpp"
#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf::detail {

struct Constraint {
  enum Kind : int { Vertex = 0, Edge = 1 } kind = Vertex;
  int agent = 0;
  int cell = 0;   // Vertex: the vertex; Edge: the vertex moved from
  int cell2 = 0;  // Edge: the vertex moved to
  int time = 0;   // Vertex: the time step; Edge: the step's end
};

struct LowLevelQuery {
  int agent = 0;
  int start_state = 0;
  int goal_cell = 0;
  const DistanceTable* h = nullptr;                  // distances to goal_cell
  const std::vector<Constraint>* constraints = nullptr;  // this agent's only
  const PathTable* avoid = nullptr;                  // the other agents (soft); may hold this agent
  double w = 1.0;                                    // focal bound (1 = A*)
};

struct LowLevelResult {
  bool found = false;
  bool stopped = false;      // the stop predicate fired
  CellPath cells;            // vertex per time step
  int cost = 0;              // path_cost of the result
  int lower_bound = 0;       // min f in OPEN when the goal was taken (<= optimal cost)
  int conflicts = 0;         // with `avoid`, along the path
  long long expanded = 0;
};

class LowLevel {
 public:
  // `reserved` (may be null) holds the reserved robots' paths, parking at their ends.
  LowLevel(const Instance& in, const AgentModel& model, const PathTable* reserved);

  [[nodiscard]] LowLevelResult search(const LowLevelQuery& q, const std::function<bool()>& should_stop);

  // Does cell `goal` stay free of reserved robots from time t on? (Stay rule's goal test.)
  [[nodiscard]] int reserved_last_use(int cell) const;

 private:
  const AgentModel& model_;
  const PathTable* reserved_;
  std::vector<int> reserved_last_;  // per vertex: last time step a reserved robot is there (-1 none)
  bool vanish_;
};

}  // namespace swarm::planner::mapf::detail
