// Robot placements for `swarm darp --count` and `swarm experiment darp`: distinct free cells of the
// largest piece, where each kind promises, the same for the same seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "swarm/planner/coverage/placement.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace {

using swarm::planner::Cell;
using swarm::planner::OccupancyGrid;
using swarm::planner::Rng;
using namespace swarm::planner;

OccupancyGrid room() {
  // A 20 x 10 room and, behind a wall, a 3-cell pocket (a smaller piece: never used).
  OccupancyGrid g(24, 10, 0.2, 0, 0, swarm::planner::CellState::Free);
  for (int y = 0; y < 10; ++y) g.set({20, y}, swarm::planner::CellState::Occupied);
  for (int y = 3; y < 10; ++y) {
    for (int x = 21; x < 24; ++x) g.set({x, y}, swarm::planner::CellState::Occupied);
  }
  return g;
}

// 4-connected steps between two cells of the open room.
int steps(Cell a, Cell b) { return std::abs(a.x - b.x) + std::abs(a.y - b.y); }

void expect_distinct_in_room(const std::vector<Cell>& cells, std::size_t n) {
  EXPECT_EQ(cells.size(), n);
  EXPECT_EQ(std::set<Cell>(cells.begin(), cells.end()).size(), n);
  for (const Cell& c : cells) EXPECT_LT(c.x, 20) << "in the largest piece";
}

TEST(DarpPlacement, LargestPieceIsTheRoom) { EXPECT_EQ(largest_piece(room()).size(), 200u); }

TEST(DarpPlacement, SpreadCellsAreFarApartAndReproducible) {
  Rng a(3), b(3);
  const auto cells = spread_cells(room(), 4, a);
  expect_distinct_in_room(cells, 4);
  EXPECT_EQ(cells, spread_cells(room(), 4, b));
  double nearest = 1e9;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::size_t j = i + 1; j < cells.size(); ++j) {
      nearest = std::min(nearest, swarm::planner::euclidean_distance(cells[i], cells[j]));
    }
  }
  EXPECT_GE(nearest, 5.0);  // 4 cells farthest-first in a 20 x 10 room
}

// 6 robots: a zone of at least 18 cells, i.e. radius 3 around the centre (25 cells in open
// space; radius 0 around (10, 5) makes that cell the centre).
TEST(DarpPlacement, BunchedCellsShareASmallZone) {
  Rng rng(5);
  const auto cells = bunched_cells(room(), 6, Cell{10, 5}, 0, rng);
  expect_distinct_in_room(cells, 6);
  for (const Cell& c : cells) EXPECT_LE(steps(c, {10, 5}), 3);
  Rng anywhere(5);
  expect_distinct_in_room(bunched_cells(room(), 6, std::nullopt, 0, anywhere), 6);
  Rng near(5);
  for (const Cell& c : bunched_cells(room(), 4, Cell{2, 2}, 1, near)) {
    EXPECT_LE(steps(c, {2, 2}), 1 + 2) << "centre within 1 step, zone radius 2";
  }
}

TEST(DarpPlacement, CellsNearStayWithinTheRadius) {
  Rng rng(9);
  const auto cells = cells_near(room(), 5, Cell{10, 5}, 2, rng);
  expect_distinct_in_room(cells, 5);
  for (const Cell& c : cells) EXPECT_LE(steps(c, {10, 5}), 2);
  Rng more(9);
  EXPECT_EQ(cells_near(room(), 50, Cell{10, 5}, 1, more).size(), 5u) << "only 5 cells within 1 step";
}

}  // namespace
