// Multi-agent path finding (MAPF): the instance, the plan, and what a plan costs.
//
// The problem as the field states it (Stern et al., "Multi-Agent Pathfinding: Definitions,
// Variants, and Benchmarks", SoCS 2019): k agents on a grid, each with a start and a goal cell;
// time is discrete; at every time step each agent waits or moves to a neighbouring free cell under
// the motion model (motion.hpp, 4-connected); no two agents may be on one cell at one time step
// (vertex conflict) or swap cells within one step (swap/edge conflict). A plan gives every agent
// a timed path: path[t] = its cell at time step t, path[0] = its start, path.back() = its goal.
//
// Two sets of world rules (Rules):
//   - standard (MovingAI benchmark): after its path ends an agent stays on its goal for ever and
//     still blocks it; waits are allowed anywhere; an agent's cost is the time step at which it
//     last arrives at its goal (the sum of costs, SoC, is the usual objective).
//   - the paper's warehouse (PAPERS.md section 3, warehouse.hpp): an agent leaves the collision
//     check once it reaches its goal (GoalRule::Vanish; its cost is its arrival time), and it may
//     stop only in the middle of a passage or at its start before moving, 2 time steps per stop,
//     and never turns back in a passage (WaitRule::PassageMiddles).
//
// RESERVED paths are timed paths of other robots that are fixed (a live run's other groups): each
// such robot follows its path and then stays on its last cell for ever. Planned agents must not
// have vertex or swap conflicts with them. An agent whose start equals its goal is valid.
//
// Cells are grid.hpp cells (x right, y up). Thread-safe: plain values and pure functions.
//
//   Instance in{map, MotionModel::four(), {{1, 1}, {5, 1}}, {{5, 1}, {1, 1}}};
//   if (const auto problems = check_instance(in); !problems.empty()) ...  // bad input
//   const DistanceTable to_goal(in.map, in.motion, in.goals[0]);           // BFS, in steps
//   const int lb = lower_bound(in);                                        // sum of shortest paths
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "swarm/planner/grid.hpp"
#include "swarm/planner/motion.hpp"

namespace swarm::planner::mapf {

// path[t] = the cell at time step t.
using Path = std::vector<Cell>;

enum class GoalRule : std::uint8_t {
  Stay,    // standard MAPF: an agent stays on its goal for ever and keeps blocking it
  Vanish,  // the paper: an agent leaves the collision check when it reaches its goal
};

enum class WaitRule : std::uint8_t {
  Anywhere,        // standard MAPF: a wait of one step on any cell
  PassageMiddles,  // the paper: stops only in a passage middle or at the start before the first
                   // move, 2 steps each; no turning back in a passage
};

struct Rules {
  GoalRule at_goal = GoalRule::Stay;
  WaitRule waits = WaitRule::Anywhere;

  static constexpr Rules standard() { return {}; }
  static constexpr Rules paper_warehouse() { return {GoalRule::Vanish, WaitRule::PassageMiddles}; }
  friend bool operator==(const Rules&, const Rules&) = default;
};

// "standard" / "paper-warehouse" (other combinations: "goal=vanish, waits=anywhere", ...).
[[nodiscard]] std::string describe(const Rules& rules);

struct Instance {
  OccupancyGrid map;                          // Free cells are passable, everything else is not
  MotionModel motion = MotionModel::four();   // MAPF is 4-connected (check_instance insists)
  std::vector<Cell> starts;                   // one per agent
  std::vector<Cell> goals;                    // one per agent
  std::vector<Path> reserved;                 // fixed timed paths of other robots (may be empty)
  Rules rules;

  [[nodiscard]] int agents() const { return static_cast<int>(starts.size()); }
};

// What is wrong with an instance as input (empty = fine): starts/goals outside the map or on a
// blocked cell, two agents on one start or one goal, a start on a reserved robot's cell at time 0,
// a reserved path that leaves the free cells or jumps, 8-connected motion, paper rules on a map
// that is not a warehouse lattice. Each message names the agent ("agent 3: goal (4, 7) is ...").
// Unsolvable is not wrong: see feasibility_problem.
[[nodiscard]] std::vector<std::string> check_instance(const Instance& in);

// A reason the instance can have no solution, found cheaply ("" = none found): a goal not
// reachable from its start, or (Stay) a goal that a reserved robot occupies for ever.
[[nodiscard]] std::string feasibility_problem(const Instance& in);

// Shortest-path distances (in steps, the motion model's moves over Free cells) from every cell to
// one target cell; kUnreachable where there is no path. BFS: exact for unit-cost moves.
class DistanceTable {
 public:
  static constexpr int kUnreachable = std::numeric_limits<int>::max() / 4;
  DistanceTable() = default;
  DistanceTable(const OccupancyGrid& map, const MotionModel& motion, Cell target);
  [[nodiscard]] int at(int cell_index) const { return dist_[static_cast<std::size_t>(cell_index)]; }
  [[nodiscard]] int at(const OccupancyGrid& map, Cell c) const {
    return map.in_bounds(c) ? at(map.index(c)) : kUnreachable;
  }

 private:
  std::vector<int> dist_;
};

// The cost of one agent's path: Stay, the time step of its last arrival at the goal (trailing
// waits on the goal are free); Vanish, its first arrival (the path ends there). An empty path, or
// one that does not end on the goal, costs kNoCost.
inline constexpr int kNoCost = -1;
[[nodiscard]] int path_cost(const Instance& in, int agent, const Path& path);
// The sum of path_cost over the agents (kNoCost if one is kNoCost).
[[nodiscard]] long long sum_of_costs(const Instance& in, const std::vector<Path>& paths);
// The largest path_cost (kNoCost if one is kNoCost).
[[nodiscard]] int makespan(const Instance& in, const std::vector<Path>& paths);
// Sum over the agents of the shortest start-goal distance ignoring the others: no plan costs less.
// kNoCost when some goal is unreachable.
[[nodiscard]] long long lower_bound(const Instance& in);

// Where agent a is at time step t under the rules: path[min(t, end)] (Stay), or nothing once a
// Vanish agent has arrived (returns false). Reserved robots always stay.
[[nodiscard]] bool position_at(const Path& path, int t, bool vanishes, Cell& out);

// Paper rules: is c the middle of a passage (free, with exactly two free 4-neighbours, opposite
// each other)? Every other free cell is an intersection.
[[nodiscard]] bool is_passage_middle(const OccupancyGrid& map, Cell c);

// Wait and move statistics of a plan, the paper's Table 1/2 measures: per agent, its arrival
// (work time, path_cost) and its idle steps (waits before its arrival, those at the start
// included).
[[nodiscard]] int idle_steps(const Instance& in, int agent, const Path& path);

}  // namespace swarm::planner::mapf
