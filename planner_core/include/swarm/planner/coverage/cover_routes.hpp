// Routes for the live coverage task (tasks/cover/), free of DDS: divide a set
// of cells among robots with DARP (darp.hpp) and give each robot a 4-connected route from where it
// stands that visits every cell of its region (spanning-tree coverage, stc.hpp; or plowing /
// Group-k, plow.hpp / group_k.hpp).
//
// Robots may stand anywhere on Free cells of the map, not only in the set: DARP grows the regions
// from each robot's nearest cell of the set (distinct cells, by BFS through Free cells; a robot
// that can reach no cell of the set gets none; a piece of the set smaller than half a share is
// not started in while a larger one can be reached), and the robot first drives there. Pieces of
// the set that hold no start are given to the nearest robot (assign_orphans); its route covers
// the piece it starts in (what is left uncovered is divided again by the live task).
//
//   CoverRoutes r = divide_and_route(map, cells, robot_cells, weights, config, stop);
//   r.routes[i]   // robot i's route: robot_cells[i] first, every cell of its region visited
//   r.darp        // the division (status, iterations, alpha, ...); r.seconds: its wall time
//
// Several divisions may be tried (CoverRoutesConfig::candidates, other starts and seeds; then
// balance_rounds, other portions), and the one whose longest route is shortest is kept.
//
// Deterministic per config.darp.seed; interruptible through `stop` (the best division so far is
// used). Thread-safe: no shared state.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "swarm/planner/coverage/darp.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/coverage/stc.hpp"

namespace swarm::planner {

enum class CoverOrder : std::uint8_t { Stc, Plow, GroupK };

struct CoverRoutesConfig {
  DarpConfig darp;
  CoverOrder order = CoverOrder::Stc;
  StcConfig stc;
  bool routes = true;  // false: the division only (the GCS's split among groups)
  // Cells of the set in a piece that holds no robot's start (DARP leaves them out: -2) go to the
  // robot nearest them (BFS through Free cells): a live task must cover every reachable cell.
  bool assign_orphans = true;
  // With routes: divisions tried (the first from config.darp; the others from K-Means starts and
  // then other seeds), and the one whose longest route is shortest is kept. Regions equal in cells
  // are not equal in work (a one-cell corridor is swept there and back), so the division alone
  // cannot tell which is best.
  int candidates = 1;
  // With routes: rounds that divide again by work rather than by cells, after the candidates. Each
  // round scales every robot's DARP portion by sqrt(mean route / its route), from the last round's
  // routes (the best candidate's first), and divides again from the best candidate's start; the
  // division whose longest route is shortest is kept, as among candidates. A region's moves per
  // cell depend on its shape (a dead-end aisle is swept there and back, open floor once) and on
  // the drive to it, so equal cells can be far from equal moves.
  int balance_rounds = 0;
};

struct CoverRoutes {
  DarpResult darp;
  int candidates_tried = 1;                // divisions made (CoverRoutesConfig::candidates)
  int balance_rounds = 0;                  // rounds made (CoverRoutesConfig::balance_rounds)
  int chosen = 0;                          // the one kept, from 0: candidates, then rounds
  std::vector<Cell> starts;                // where each robot's region grew from (its nearest set cell)
  std::vector<std::vector<Cell>> routes;   // per robot; {its cell} when it has nothing to cover
  std::vector<int> region_cells;           // per robot
  std::vector<int> turns;                  // per robot, of its route
  double seconds_division = 0;
  double seconds_routes = 0;
};

[[nodiscard]] CoverRoutes divide_and_route(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                                           const std::vector<Cell>& robots, const std::vector<double>& weights,
                                           const CoverRoutesConfig& config, const std::function<bool()>& stop = {});

}  // namespace swarm::planner
