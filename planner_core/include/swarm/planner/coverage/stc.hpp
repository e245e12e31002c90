// Spanning-tree coverage (STC) of one region: a path from a start cell that visits every cell of
// the region with 4-connected steps (MotionModel::four()) and never leaves it.
// Gabriely & Rimon, "Spanning-tree based coverage of continuous areas by a mobile robot", Annals of
// Mathematics and Artificial Intelligence 31 (2001); the usual step after DARP (darp.hpp).
//
// Classic STC groups the cells into 2 x 2 blocks, builds a spanning tree over the blocks and walks
// around it, visiting each cell once; it needs every block whole. DARP's regions have ragged
// borders, so here every block is a node with whatever cells of the region it holds:
//   - each node gets a closed walk of its own cells: 4 cells a square loop (4 moves), 3 cells an
//     L walked there and back (4 moves, the corner twice), 2 adjacent cells there and back
//     (2 moves), 1 cell none; two diagonal cells of a block are two nodes;
//   - neighbouring nodes are joined along a tree edge, cheapest first: "parallel" when both
//     facing sides are whole (the walks are cut open and crossed over, 0 extra moves: classic
//     STC), else a "bridge" through one adjacent pair of cells (a there-and-back detour,
//     2 extra moves). Kruskal takes every parallel edge it can before any bridge;
//   - the single closed walk that results visits every cell; the path is that walk from the
//     start, cut after the last cell it sees for the first time.
// Among spanning trees the one with fewest turns is chosen, as Kapoutsis's reference does with 4
// edge-weight modes ("comb" trees with long straight branches: vertical branches joined along the
// bottom or the top, horizontal ones joined along the left or the right); here those 4 modes are
// tried on each of the 4 placements of the 2 x 2 lattice (16 trees), and each closed walk from
// every visit of the start in both directions. The winner is the shortest path, then the fewest
// turns (on regions made of whole blocks every candidate has the same length, so that is the
// reference's fewest-turns rule; elsewhere a repeated cell costs a move, a turn does not).
//
// Turns: a 90-degree change of direction counts 1, a reversal 2.
// A region that is not connected (a failed DARP division) is covered in the piece holding the
// start; the other cells are counted in left_out.
//
//   OccupancyGrid region = ...;                  // Free = the robot's region
//   StcPath p = spanning_tree_coverage(region, start);
//   // p.cells.front() == start, p.length == p.cells.size() - 1, p.covered + p.left_out == region cells
//
// Deterministic; thread-safe (no shared state). O(cells) per tree, 16 trees.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/tours/turns.hpp"

namespace swarm::planner {

struct StcConfig {
  bool all_lattice_offsets = true;  // try the 4 placements of the 2 x 2 lattice (else only (0, 0))
};

enum class StcStatus : std::uint8_t { Ok, StartOutsideRegion };

struct StcPath {
  StcStatus status = StcStatus::Ok;
  std::vector<Cell> cells;  // start first; consecutive cells are 4-neighbours
  int length = 0;           // moves: cells.size() - 1
  int turns = 0;            // 90 degrees = 1, reversal = 2
  int revisits = 0;         // cells.size() - covered: visits of an already visited cell
  int covered = 0;          // distinct cells visited: the start's piece of the region
  int left_out = 0;         // region cells in other pieces, never visited
  int lattice_x = 0;        // the winning tree: lattice offset (0/1, 0/1) and mode (0..3)
  int lattice_y = 0;
  int tree_mode = 0;
};

// Covers the Free cells of `region` (everything else is outside) from `start`.
[[nodiscard]] StcPath spanning_tree_coverage(const OccupancyGrid& region, Cell start,
                                             const StcConfig& config = {});


}  // namespace swarm::planner
