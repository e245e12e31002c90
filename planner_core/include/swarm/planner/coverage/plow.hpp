// Plowing (boustrophedon) coverage of a region of a grid: the baseline of Jeon, Jo & Noh 2006
// (seeds/003, "바둑판식 알고리즘", their refs [2-4]), and the sweep Group-k runs inside each group.
//
// The sweep is BA*'s (Viet et al., "BA*: an online complete coverage algorithm for cleaning
// robots", Applied Intelligence 2013): from the current cell, step to the first neighbour that is
// an uncovered region cell in the fixed priority up, down, right, left (columns; rows: right, left,
// down, up). That runs up and down columns, moving right between them. When no neighbour
// qualifies (a dead end at an obstacle or at covered cells), the robot goes by a shortest
// 4-connected path through Free cells (breadth-first search, neighbours in motion.hpp's order) to
// the nearest uncovered region cell and sweeps on from there. It stops when no uncovered region
// cell is reachable; those left over are `missed`. Cells passed on the way are clean too.
//
//   CoveragePath p = plow(map, free_cells(map), start);           // the whole map
//   CoveragePath mine = plow(map, my_region, my_cell);             // one robot's DARP region
//
// The path may leave the region to get from one part of it to another (through any Free cell).
// Deterministic. Cost: one BFS (O(map cells)) per dead end. Thread-safe.
#pragma once

#include <vector>

#include "swarm/planner/coverage/coverage.hpp"
#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

struct PlowOptions {
  enum class Sweep { kColumns, kRows };
  Sweep sweep = Sweep::kColumns;
};

[[nodiscard]] CoveragePath plow(const OccupancyGrid& map, const CellMask& region, Cell start,
                                const PlowOptions& options = {});

// One part of a longer plan (Group-k plows several parts in turn): plows the cells of `part`
// that `covered` does not mark yet, continuing `path` from its last cell (which must exist).
// Every cell stepped on is marked in `covered`. Returns the part's cells left uncovered
// (unreachable).
std::vector<Cell> plow_part(const OccupancyGrid& map, const CellMask& part, CellMask& covered,
                            std::vector<Cell>& path, const PlowOptions& options = {});

}  // namespace swarm::planner
