// The motion model: the one definition of a legal robot action, used by the simulator (which
// executes actions), every planner (which plans them) and every validator (which checks plans).
//
// Time is discrete: one action per robot per tick. An action is either a wait (stay on the cell)
// or a step to a neighbouring cell. Which cells neighbour depends on the phase:
//   - Connectivity::Eight (exploration, the paper's robots): the 8 neighbours; a diagonal step
//     never cuts a corner, i.e. both orthogonal cells it sweeps must be passable too.
//   - Connectivity::Four (coverage and MAPF, as their papers assume): the 4 orthogonal neighbours.
// What is passable is the caller's choice of Passability: ground truth (Free only), or an agent's
// optimistic map where Unknown counts as passable. Out-of-map cells are never passable.
//
//   const MotionModel m = MotionModel::four();
//   if (m.check(map, from, to) == MoveCheck::Ok) ...;
//   m.for_each_neighbour(map, c, [&](Cell n, double cost) { ... });   // in a fixed order
//
// Neighbour order is fixed (+x, -x, +y, -y, then the diagonals +x+y, +x-y, -x+y, -x-y), so searches
// built on it are deterministic. Thread-safe: a MotionModel is a value.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

enum class Connectivity : std::uint8_t { Four = 4, Eight = 8 };

enum class Passability : std::uint8_t {
  FreeOnly,       // ground truth, or a map whose Unknown cells must not be entered
  UnknownIsFree,  // optimistic planning through unexplored space
};

// Why an action is or is not legal. Wait and Ok are legal.
enum class MoveCheck : std::uint8_t {
  Ok,           // a step to a passable neighbour
  Wait,         // from == to (legal on any cell the robot stands on)
  NotAdjacent,  // not a neighbour under this connectivity (a jump, or a diagonal in 4-connected)
  Blocked,      // the target is not passable (a wall, or outside the map)
  CornerCut,    // a diagonal step past a non-passable orthogonal cell
};

[[nodiscard]] const char* to_string(MoveCheck check);

struct MotionModel {
  Connectivity connectivity = Connectivity::Eight;

  static constexpr MotionModel four() { return {Connectivity::Four}; }
  static constexpr MotionModel eight() { return {Connectivity::Eight}; }

  [[nodiscard]] constexpr int neighbour_count() const { return connectivity == Connectivity::Four ? 4 : 8; }

  // Is `to` one action away from `from`, ignoring the map? (A wait counts.)
  [[nodiscard]] bool adjacent_or_same(Cell from, Cell to) const;

  // The full check of one action on `map`.
  [[nodiscard]] MoveCheck check(const OccupancyGrid& map, Cell from, Cell to,
                                Passability passability = Passability::FreeOnly) const;
  [[nodiscard]] bool legal(const OccupancyGrid& map, Cell from, Cell to,
                           Passability passability = Passability::FreeOnly) const {
    const MoveCheck c = check(map, from, to, passability);
    return c == MoveCheck::Ok || c == MoveCheck::Wait;
  }

  // Calls f(neighbour, cost) for every legal step from c (cost 1 orthogonal, sqrt 2 diagonal), in
  // the fixed order above. Waits are not listed.
  template <class F>
  void for_each_neighbour(const OccupancyGrid& map, Cell c, F&& f,
                          Passability passability = Passability::FreeOnly) const {
    const int n = neighbour_count();
    for (int k = 0; k < n; ++k) {
      const Cell to{c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]};
      if (!passable(map, to, passability)) continue;
      if (k >= 4 && (!passable(map, {to.x, c.y}, passability) || !passable(map, {c.x, to.y}, passability))) continue;
      f(to, k >= 4 ? kDiagonalCost : 1.0);
    }
  }

  // The admissible, consistent distance heuristic for this connectivity: Manhattan (4) or octile (8).
  [[nodiscard]] double heuristic(Cell a, Cell b) const;

  static bool passable(const OccupancyGrid& map, Cell c, Passability passability) {
    const CellState s = map.at(c);  // Occupied outside the map
    return s == CellState::Free || (s == CellState::Unknown && passability == Passability::UnknownIsFree);
  }

  static constexpr double kDiagonalCost = 1.41421356237309504880;

  friend bool operator==(const MotionModel&, const MotionModel&) = default;
};

// Conflicts among simultaneous actions, the one definition the simulator (which resolves them) and
// every MAPF validator (which counts them in a plan) share. Robot i acts from[i] -> to[i] in one
// tick (to[i] == from[i]: it waits).
//   - vertex conflict: two or more robots end the tick on one cell (a robot that waits there
//     counts); one conflict per such cell, listing every robot that ends there;
//   - edge conflict: two robots swap cells (a -> b while b -> a); one per pair.
// Both are reported in a fixed order (by cell, then by robot id), independent of robot order
// otherwise. Robots with from == to on distinct cells never conflict with each other.
struct VertexConflict {
  Cell cell;
  std::vector<int> robots;  // ascending
};
struct EdgeConflict {
  int a = 0;  // a < b
  int b = 0;
};
struct StepConflicts {
  std::vector<VertexConflict> vertex;
  std::vector<EdgeConflict> edge;
  bool empty() const { return vertex.empty() && edge.empty(); }
};
[[nodiscard]] StepConflicts find_step_conflicts(const std::vector<Cell>& from, const std::vector<Cell>& to);

// "4-connected" / "8-connected (no corner cutting)".
[[nodiscard]] std::string describe(const MotionModel& model);

}  // namespace swarm::planner
