#include "swarm_test/ascii_grid.hpp"
#include "swarm/planner/grid/start_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

namespace swarm::planner {

void PrintTo(const Cell& c, std::ostream* os) { *os << "(" << c.x << ", " << c.y << ")"; }

namespace {

using swarm::test::grid_from;  // rows top first (swarm_test/ascii_grid.hpp)

TEST(StartCells, BreadthFirstOrderStartFirst) {
  const OccupancyGrid g(5, 5, 0.2, 0.0, 0.0, CellState::Free);
  // Neighbours in kNeighbourDx/Dy order: +x, -x, +y, -y, then the diagonals.
  const std::vector<Cell> ring = {{2, 2}, {3, 2}, {1, 2}, {2, 3}, {2, 1},
                                  {3, 3}, {3, 1}, {1, 3}, {1, 1}};
  EXPECT_EQ(start_cells(g, {2, 2}, 9), ring);
  EXPECT_EQ(start_cells(g, {2, 2}, 3), std::vector<Cell>(ring.begin(), ring.begin() + 3));
  const std::vector<Cell> next = start_cells(g, {2, 2}, 10);
  ASSERT_EQ(next.size(), 10u);
  EXPECT_EQ(next[9], (Cell{4, 2}));  // first cell two steps away, found from (3, 2)
}

TEST(StartCells, FewerWhenFewerAreReachableAndNoCornerCutting) {
  const OccupancyGrid g = grid_from({
      "#####",  // y = 3
      "#..#.",  // y = 2: (4, 2) is diagonal to (3, 1), past the walls (3, 2) and (4, 1)
      "#...#",  // y = 1
      "#####",  // y = 0
  });
  const std::vector<Cell> cells = start_cells(g, {1, 1}, 10);
  const std::vector<Cell> expected = {{1, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 1}};
  EXPECT_EQ(cells, expected);
}

TEST(StartCells, CellsAreDistinctFreeAndDeterministic) {
  OccupancyGrid g(20, 20, 0.2, 0.0, 0.0, CellState::Free);
  for (int i = 0; i < 15; ++i) g.set(Cell{10, i}, CellState::Occupied);
  const std::vector<Cell> a = start_cells(g, {9, 0}, 60);
  ASSERT_EQ(a.size(), 60u);
  for (const Cell& c : a) EXPECT_TRUE(g.is_free(c));
  std::vector<Cell> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  EXPECT_EQ(start_cells(g, {9, 0}, 60), a);
}

TEST(StartCells, NothingForABadStartOrCount) {
  const OccupancyGrid g = grid_from({"..#"});
  EXPECT_TRUE(start_cells(g, {2, 0}, 3).empty());   // Occupied
  EXPECT_TRUE(start_cells(g, {5, 0}, 3).empty());   // out of bounds
  EXPECT_TRUE(start_cells(g, {0, 0}, 0).empty());
  EXPECT_TRUE(start_cells(g, {0, 0}, -2).empty());
  EXPECT_EQ(start_cells(g, {0, 0}, 1), (std::vector<Cell>{Cell{0, 0}}));
}

}  // namespace
}  // namespace swarm::planner
