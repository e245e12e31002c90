#include "swarm/planner/coverage/plow.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::planner {
namespace {

// A 3 x 3 room from the bottom-left corner: up the first column, right, down, right, up.
TEST(Plow, SweepsColumnsUpAndDownMovingRight) {
  const OccupancyGrid room(3, 3, 0.1, 0, 0, CellState::Free);
  const CoveragePath p = plow(room, free_cells(room), {0, 0});
  EXPECT_EQ(p.cells, (std::vector<Cell>{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 1}, {1, 0}, {2, 0}, {2, 1}, {2, 2}}));
  EXPECT_TRUE(p.missed.empty());
  EXPECT_EQ(p.steps(), 8);
  const TurnCounts t = p.turns();
  EXPECT_EQ(t.turns_90, 4);
  EXPECT_EQ(t.turns_180, 0);
  const CoveragePath rows = plow(room, free_cells(room), {0, 0}, {PlowOptions::Sweep::kRows});
  EXPECT_EQ(rows.cells.front(), (Cell{0, 0}));
  EXPECT_EQ(rows.cells[1], (Cell{1, 0}));
  EXPECT_EQ(rows.cells[3], (Cell{2, 1}));  // along the bottom row, then up and back
}

// Behind the pillar the sweep runs into covered cells and walks (by BFS) to the nearest cell left.
TEST(Plow, CoversEveryFreeCellAroundObstacles) {
  const OccupancyGrid map = swarm::test::grid_from({
      "##########",
      "#........#",
      "#..##....#",
      "#..##..#.#",
      "#......#.#",
      "#.#......#",
      "##########",
  });
  for (Cell start : {Cell{1, 1}, Cell{5, 3}, Cell{8, 5}}) {
    const CoveragePath p = plow(map, free_cells(map), start);
    EXPECT_EQ(check_coverage_path(map, free_cells(map), start, p), "");
    EXPECT_TRUE(p.missed.empty());
    EXPECT_GE(p.steps(), count_cells(free_cells(map)) - 1);
  }
}

TEST(Plow, CoversEveryFreeCellOfAMaze) {
  const OccupancyGrid map = swarm::test::grid_from({
      "....#.....",
      ".##.#.###.",
      ".#..#...#.",
      ".#.###.##.",
      "...#......",
      ".#.#.####.",
      ".#........",
  });
  const CellMask all = free_cells(map);
  const CoveragePath p = plow(map, all, {0, 0});
  EXPECT_EQ(check_coverage_path(map, all, {0, 0}, p), "");
  EXPECT_TRUE(p.missed.empty());
}

// A robot's region in two parts (top left 3 x 2 and bottom right 2 x 2 cells): it covers both,
// crossing cells outside the region between them.
TEST(Plow, CoversEveryCellOfARegionAndMayCrossOtherCells) {
  const OccupancyGrid map = swarm::test::grid_from({
      "........",
      "....##..",
      "....##..",
      "........",
  });
  CellMask region(map.size(), 0);
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      if ((x <= 2 && y >= 2) || (x >= 6 && y <= 1)) region[static_cast<std::size_t>(map.index({x, y}))] = 1;
    }
  }
  const CoveragePath p = plow(map, region, {0, 3});
  EXPECT_EQ(check_coverage_path(map, region, {0, 3}, p), "");
  EXPECT_TRUE(p.missed.empty());
  // 6 + 4 region cells, and at least 3 cells crossed between the parts.
  EXPECT_GE(p.steps(), 9 + 3);
  bool left_region = false;
  for (const Cell c : p.cells) left_region |= !region[static_cast<std::size_t>(map.index(c))];
  EXPECT_TRUE(left_region);
}

TEST(Plow, CellsItCannotReachAreMissed) {
  const OccupancyGrid map = swarm::test::grid_from({
      "...#.",
      "...#.",
      "...#.",
  });
  const CoveragePath p = plow(map, free_cells(map), {0, 0});
  EXPECT_EQ(p.missed, (std::vector<Cell>{{4, 0}, {4, 1}, {4, 2}}));
  EXPECT_EQ(check_coverage_path(map, free_cells(map), {0, 0}, p), "");
  EXPECT_EQ(p.steps(), 8);
}

}  // namespace
}  // namespace swarm::planner
