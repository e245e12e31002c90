// Multi-agent path finding (MAPF): the instance, the plan, and what a plan costs.
//
// The problem as the field states it (Stern et al., "Multi-Agent Pathfinding: Definitions,
// Variants, and Benchmarks", SoCS 2019): k agents on a graph, each with a start and a goal vertex;
// time is discrete; at every time step each agent waits or moves along one edge; no two agents may
// be on one vertex at one time step (vertex conflict) or swap vertices within one step (swap/edge
// conflict). A plan gives every agent a timed path: path[t] = where it is at time step t,
// path[0] = its start, path.back() = its goal.
//
// The graph is a grid or a general graph:
//   - a GRID instance (the default): `map` and `motion` (motion.hpp, 4-connected); the vertices
//     are the free cells, the edges join 4-neighbours. Cells are grid.hpp cells (x right, y up).
//   - a GRAPH instance: `graph` is set (graph.hpp: V vertices, undirected edges); `map` and
//     `motion` are unused. Vertex v is written Cell{v, 0} wherever the interface takes cells
//     (starts, goals, paths, reserved paths, validator reports: a conflict "at (3, 0)" is on
//     vertex 3), so a plan has one type (Path) for both kinds and everything that reads plans
//     (costs, the validator, adg.hpp) serves both; vertex_cell(v) writes one, cell_vertex reads it.
//     Where a vertex is drawn is the graph's business (Graph::positions), not the cell's.
// Either way the solvers see one adjacency structure: InstanceGraph below (a grid's graph has one
// vertex per free cell, its neighbours in motion.hpp's fixed order, so grid results do not depend
// on the graph machinery). graph_instance() turns a grid instance into the equivalent graph
// instance; graph_file.hpp reads and writes graph instances as text.
//
// Two sets of world rules (Rules):
//   - standard (MovingAI benchmark): after its path ends an agent stays on its goal for ever and
//     still blocks it; waits are allowed anywhere; an agent's cost is the time step at which it
//     last arrives at its goal (the sum of costs, SoC, is the usual objective).
//   - the paper's warehouse (docs/papers.md section 3, warehouse.hpp): an agent leaves the collision
//     check once it reaches its goal (GoalRule::Vanish; its cost is its arrival time), and it may
//     stop only in the middle of a passage or at its start before moving, 2 time steps per stop,
//     and never turns back in a passage (WaitRule::PassageMiddles: grids only, a warehouse lattice).
//
// RESERVED paths are timed paths of other robots that are fixed (a live run's other groups): each
// such robot follows its path and then stays on its last cell for ever. Planned agents must not
// have vertex or swap conflicts with them. An agent whose start equals its goal is valid.
//
// Thread-safe: plain values and pure functions (an InstanceGraph is read-only once built).
//
//   Instance in{map, MotionModel::four(), {{1, 1}, {5, 1}}, {{5, 1}, {1, 1}}};
//   if (const auto problems = check_instance(in); !problems.empty()) ...  // bad input
//   const InstanceGraph g(in);                                            // vertices and edges
//   const DistanceTable to_goal(g.graph(), g.vertex(in.goals[0]));        // BFS, in steps
//   const int lb = lower_bound(in);                                        // sum of shortest paths
//
//   Instance ring;                                                          // a graph instance
//   ring.graph = Graph(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {0, 3}});
//   ring.starts = {vertex_cell(0), vertex_cell(3)};
//   ring.goals = {vertex_cell(3), vertex_cell(0)};
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/mapf/graph.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner::mapf {

// path[t] = the cell (a graph instance: vertex_cell(v)) at time step t.
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
  std::optional<Graph> graph;                 // set: a graph instance (map and motion unused)

  [[nodiscard]] int agents() const { return static_cast<int>(starts.size()); }
};

// How a graph instance writes vertex v where the interface takes a cell, and back (-1: the cell
// names no vertex of `graph`).
[[nodiscard]] constexpr Cell vertex_cell(int v) { return {v, 0}; }
[[nodiscard]] inline int cell_vertex(const Graph& graph, Cell c) { return c.y == 0 && graph.has_vertex(c.x) ? c.x : -1; }

// A cell as messages name it: "(3, 4)" on a grid, "vertex 3" on a graph ("(3, 4)" there too when
// it names no vertex).
[[nodiscard]] std::string cell_name(const Instance& in, Cell c);

// Why one action from -> to is not a legal action of the instance ("" = legal). A grid: motion.hpp's
// check ("not adjacent", "blocked", ...; a wait is legal on any cell). A graph: a wait on a vertex
// or a move along an edge is legal ("not adjacent", "(3, 1) names no vertex").
[[nodiscard]] std::string step_problem(const Instance& in, Cell from, Cell to);

// The graph the solvers see, for either kind of instance, and how cells name its vertices.
//   - a grid instance: one vertex per free cell, numbered in cell index order (row y = 0 first),
//     its neighbours under the motion model in motion.hpp's fixed order (+x, -x, +y, -y);
//     positions = the cells' coordinates. Built here (O(cells)).
//   - a graph instance: the instance's own graph, not copied (the instance must outlive this).
class InstanceGraph {
 public:
  explicit InstanceGraph(const Instance& in);
  InstanceGraph(const InstanceGraph&) = delete;
  InstanceGraph& operator=(const InstanceGraph&) = delete;

  [[nodiscard]] const Graph& graph() const { return external_ != nullptr ? *external_ : own_; }
  [[nodiscard]] int vertices() const { return graph().vertices(); }
  [[nodiscard]] bool on_grid() const { return external_ == nullptr; }
  // The vertex a cell names, or -1 (outside the map, a blocked cell, no vertex of the graph).
  [[nodiscard]] int vertex(Cell c) const {
    if (!on_grid()) return cell_vertex(graph(), c);
    if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return -1;
    return vertex_of_[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x)];
  }
  // The cell of vertex v (0 <= v < vertices()).
  [[nodiscard]] Cell cell(int v) const { return on_grid() ? cell_of_[static_cast<std::size_t>(v)] : vertex_cell(v); }

 private:
  const Graph* external_ = nullptr;  // a graph instance's graph
  Graph own_;                        // a grid instance's graph
  int width_ = 0;
  int height_ = 0;
  std::vector<int> vertex_of_;  // grid: per cell index, -1 where the cell is not free
  std::vector<Cell> cell_of_;   // grid: per vertex
};

// The graph instance equivalent to a grid instance (InstanceGraph's graph, with its positions;
// starts, goals and reserved paths as vertex_cell of their vertices; the same rules): every solver
// gives it the same plan, vertex for cell. A graph instance is returned as it is.
[[nodiscard]] Instance graph_instance(const Instance& in);

// What is wrong with an instance as input (empty = fine): starts/goals outside the map or on a
// blocked cell (a graph: not a vertex), two agents on one start or one goal, a start on a reserved
// robot's cell at time 0, a reserved path that leaves the free cells (vertices) or jumps, an edge
// of the graph naming a missing vertex or a self loop (check_graph), 8-connected motion, paper
// rules on a map that is not a warehouse lattice or on a graph. Each message names the agent
// ("agent 3: goal (4, 7) is ..."). Unsolvable is not wrong: see feasibility_problem.
[[nodiscard]] std::vector<std::string> check_instance(const Instance& in);

// A reason the instance can have no solution, found cheaply ("" = none found): a goal not
// reachable from its start, or (Stay) a goal that a reserved robot occupies for ever.
[[nodiscard]] std::string feasibility_problem(const Instance& in);

// Shortest-path distances (in moves along edges) from every vertex of a graph to one target vertex;
// kUnreachable where there is no path (or the target is no vertex). BFS: exact for unit-cost moves.
class DistanceTable {
 public:
  static constexpr int kUnreachable = std::numeric_limits<int>::max() / 4;
  DistanceTable() = default;
  DistanceTable(const Graph& graph, int target);
  [[nodiscard]] int at(int vertex) const { return dist_[static_cast<std::size_t>(vertex)]; }

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

// Paper rules (grids): is c the middle of a passage (free, with exactly two free 4-neighbours,
// opposite each other)? Every other free cell is an intersection.
[[nodiscard]] bool is_passage_middle(const OccupancyGrid& map, Cell c);

// Wait and move statistics of a plan, the paper's Table 1/2 measures: per agent, its arrival
// (work time, path_cost) and its idle steps (waits before its arrival, those at the start
// included).
[[nodiscard]] int idle_steps(const Instance& in, int agent, const Path& path);

}  // namespace swarm::planner::mapf
