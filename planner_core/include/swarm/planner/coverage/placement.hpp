// Where robots start for a division (`swarm darp --count N`, `swarm experiment darp`): random placements
// on a map, every draw through Rng (same seed, same cells, on every machine). Robots are
// placed in the largest 4-connected piece of free cells, so that they can divide it.
//
//   swarm::Rng rng(seed);
//   std::vector<Cell> far = spread_cells(map, 6, rng);                 // the paper's "far"
//   std::vector<Cell> close = bunched_cells(map, 6, std::nullopt, 0, rng);  // "close together"
//   std::vector<Cell> door = bunched_cells(map, 6, entrance, 3, rng);   // "bunched at the entrance"
//   std::vector<Cell> neck = cells_near(map, 6, bottleneck, 8, rng);    // "near a bottleneck"
//
// Each returns fewer than n cells only when the piece (or the neighbourhood) has fewer free cells.
// Thread-safe (the Rng is the caller's).
#pragma once

#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {

// The cells of the largest 4-connected piece of free cells, row-major.
[[nodiscard]] std::vector<Cell> largest_piece(const OccupancyGrid& map);

// n cells far apart: the first uniformly at random in the largest piece, each next one uniformly
// among the cells whose straight-line distance to the nearest chosen cell is at least 0.7 times
// the largest such distance (farthest-point sampling, loosened so that seeds differ).
[[nodiscard]] std::vector<Cell> spread_cells(const OccupancyGrid& map, int n, Rng& rng);

// n cells close together: drawn uniformly in a crowded zone, the cells within r 4-connected steps
// of a centre, r the smallest radius whose zone holds 3n cells (8 robots: a diamond of 25 cells,
// like the DARP benchmark instance bunched-100-8). The centre is drawn uniformly among the cells
// within `radius` steps of `around`, or anywhere in the largest piece when `around` is not given.
[[nodiscard]] std::vector<Cell> bunched_cells(const OccupancyGrid& map, int n,
                                                       std::optional<Cell> around, int radius,
                                                       Rng& rng);

// n distinct cells drawn uniformly among those within `radius` 4-connected steps of `around`.
[[nodiscard]] std::vector<Cell> cells_near(const OccupancyGrid& map, int n, Cell around,
                                                    int radius, Rng& rng);

}  // namespace swarm::planner
