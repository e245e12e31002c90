// A set of grid cells as a compact graph: the cells of a region numbered 0..size()-1, each with
// its neighbours under a motion model (motion.hpp). DARP (darp.hpp) and spanning-tree coverage
// (stc.hpp) iterate over thousands of cells thousands of times; a dense numbering with neighbour
// lists makes those loops flat arrays instead of grid look-ups.
//
// A region is given as an OccupancyGrid whose Free cells are the region (anything else is outside),
// so "is this step legal" is exactly MotionModel::check on that grid. Cells are numbered in
// row-major order (y, then x), neighbours listed in the motion model's fixed order.
//
//   OccupancyGrid region = ...;                        // Free = in the region
//   RegionGraph g = RegionGraph::build(region);        // 4-connected
//   std::vector<int> d = bfs_steps(g, {g.index_of(start)});   // steps, -1 = unreachable
//   int n = 0; std::vector<int> label = components(g, n);    // n components, label per cell
//
// Deterministic; not thread-safe to mutate, a const RegionGraph may be shared.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {

struct RegionGraph {
  int width = 0;   // of the grid the cells come from
  int height = 0;
  std::vector<Cell> cells;               // compact index -> cell, row-major
  std::vector<int> compact;              // grid index -> compact index, -1 = not in the region
  // next[i][k]: the compact index of the cell one step in direction k (kNeighbourDx/Dy: +x, -x,
  // +y, -y) when that step is legal under MotionModel::four(), else -1.
  std::vector<std::array<int, 4>> next;

  [[nodiscard]] int size() const { return static_cast<int>(cells.size()); }
  // Compact index of a grid cell, -1 when outside the grid or the region.
  [[nodiscard]] int index_of(Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height ? compact[c.y * width + c.x] : -1;
  }

  // The Free cells of `region` and their 4-connected steps (MotionModel::four()).
  [[nodiscard]] static RegionGraph build(const OccupancyGrid& region);
};

// Breadth-first step counts from every source at once (-1 = unreachable). `order`, if given,
// receives the cells in the order they were reached (sources first, in the order given).
[[nodiscard]] std::vector<int> bfs_steps(const RegionGraph& graph, const std::vector<int>& sources,
                                         std::vector<int>* order = nullptr);

// 4-connected components: label per cell (0..count-1, numbered in row-major order of their first
// cell); `count` receives the number of components.
[[nodiscard]] std::vector<int> components(const RegionGraph& graph, int& count);

// Whether `owner`'s cells around c (owner[c] == r, c a cell of graph) stay 4-connected to each
// other once c is taken away, judged from c's 3 x 3 neighbourhood alone: true is certain (r's
// region stays connected, provided it was), false may be a false alarm (a loop elsewhere).
[[nodiscard]] bool simple_point(const RegionGraph& graph, const std::vector<int>& owner, int c, int r);

// `mask` with its 4-connected pieces joined into one: from the largest piece, the nearest other
// piece is joined by a shortest path of Free cells of `map` (those not in the mask are added),
// then the nearest to all that, and so on; pieces no Free path reaches stay apart. Robots standing
// in a one-cell door and just behind it leave the cells still to cover in two pieces, the room and
// the rest; a division grows its regions from the robots' pieces, so a piece left apart would be
// nobody's to drive. `pieces`, if given, receives the number of pieces the mask had.
[[nodiscard]] std::vector<std::uint8_t> join_pieces(const OccupancyGrid& map, std::vector<std::uint8_t> mask,
                                                    int* pieces = nullptr);

// A grid of the same size and geometry as `map` whose Free cells are the cells with mask[i] != 0
// that are Free in `map` (an empty mask = every Free cell); everything else is Occupied.
[[nodiscard]] OccupancyGrid region_grid(const OccupancyGrid& map, const std::vector<std::uint8_t>& mask);

}  // namespace swarm::planner
