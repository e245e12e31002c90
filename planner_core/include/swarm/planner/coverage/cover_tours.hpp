// Coverage of a small, scattered set of cells by several robots as tours: every cell of the set
// goes to one robot, and each robot's route visits its cells in an order that keeps the longest
// route short (min-max multiple travelling salesmen, open paths from the robots' cells).
//
// DARP and spanning-tree coverage (cover_routes.hpp) suit a large area: regions of whole 2 x 2
// blocks are swept with no repeated cell. After exploration the cells left to cover are often a
// few dozen per robot, in slivers along walls and shelves: a region of them is ragged, its tree
// walk pays two moves for every bridge, and the robot first drives to it. Here the cells are
// targets instead, visited in any order, the way to each target through any Free cell.
//
// Distances are fewest 4-connected moves through Free cells (one breadth-first search per
// target). Construction: two greedy tours, each improved by local search, the better kept:
//   - parallel nearest neighbour: the robot whose route is shortest so far takes its nearest
//     unassigned target;
//   - farthest first insertion: targets from the farthest from every robot, each inserted where
//     the route it joins stays shortest.
// A robot that sets off later (config.starts) counts its route from there.
// Local search, until nothing improves or `stop`: within a route 2-opt (reversing a stretch) and
// moving one target; between routes moving one target, or swapping two, from any route to
// another. A move is taken when it lowers (longest route, routes that long, sum of routes), in
// that order. Then rounds of ruin and recreate from the better (config below): `ruined_targets`
// targets taken out (half from the longest route), each put back where the score grows least, the
// local search again, the result kept unless it scores worse.
// The cell route then follows shortest paths between consecutive targets; a target passed on the
// way is dropped from its later visit.
//
//   CoverTours t = cover_tours(map, cells, robot_cells, config, stop);
//   if (t.solved) t.routes[i];   // robot i: robot_cells[i] first, 4-connected steps
//   t.owner[index];               // the robot whose list holds that target cell, -1: none
//
// Deterministic for one seed. Cost: one BFS per target, O(targets^2) per local-search pass, a few
// passes per ruin round; sets larger than config.max_targets are not attempted (solved = false). Thread-safe: no shared state.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

struct CoverToursConfig {
  std::size_t max_targets = 600;
  // Rounds of ruin and recreate: at most ruin_rounds, and at most ruin_work / targets² (each
  // round's local search costs about targets²: 600 targets take 27 rounds, about 0.3 s).
  int ruin_rounds = 1000;
  double ruin_work = 1e7;
  std::size_t ruined_targets = 12;
  std::uint64_t seed = 1;  // the ruin's choices
  // Per robot (empty: all 0): the moves it is behind the others before it can set off (its route's
  // way to it). A route's length counts from there, so the longest is what the last robot ends at.
  std::vector<int> starts;
};

struct CoverTours {
  bool solved = false;                     // false: more targets than max_targets, or no robot
  std::vector<std::vector<Cell>> routes;   // per robot; {its cell} when it has no target
  std::vector<int> owner;                  // per grid cell: the robot that visits it as a target
  std::vector<int> region_cells;           // per robot: its targets
  std::size_t targets = 0;                 // cells of the set some robot reaches
  std::size_t unreachable = 0;             // cells of the set no robot reaches (left out)
  int improvements = 0;                    // local-search moves taken
  bool stopped = false;                    // `stop` ended the local search early
  double seconds = 0;
};

[[nodiscard]] CoverTours cover_tours(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                                     const std::vector<Cell>& robots, const CoverToursConfig& config = {},
                                     const std::function<bool()>& stop = {});

// The longest route's moves.
[[nodiscard]] std::size_t longest_moves(const std::vector<std::vector<Cell>>& routes);

}  // namespace swarm::planner
