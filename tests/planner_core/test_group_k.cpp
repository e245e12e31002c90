#include "swarm/planner/coverage/group_k.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/data.hpp"

namespace swarm::planner {
namespace {

using swarm::test::grid_from;

// The room's wall touches the border: not an obstacle. Inside: a 2 x 2 block, an L of three cells
// (8-connected through its corner), and a single cell.
TEST(Obstacles, AreTheBlockedComponentsOffTheWall) {
  const OccupancyGrid map = grid_from({
      "##########",
      "#........#",
      "#.##...#.#",
      "#.##.....#",
      "#......#.#",
      "#.....#..#",
      "##.......#",  // (1, 1) touches the wall: part of it
      "##########",
  });
  const std::vector<Obstacle> obstacles = find_obstacles(map);
  ASSERT_EQ(obstacles.size(), 3u);
  EXPECT_EQ(obstacles[0].cells, (std::vector<Cell>{{6, 2}, {7, 3}}));  // diagonal: one obstacle
  EXPECT_EQ(obstacles[1].lo, (Cell{2, 4}));
  EXPECT_EQ(obstacles[1].hi, (Cell{3, 5}));
  EXPECT_EQ(obstacles[2].cells, (std::vector<Cell>{{7, 5}}));
}

// C of the box [lo, hi] of `map` is ((blocked / cells) + (corners / lattice points)) / 2.
void expect_complexity(const OccupancyGrid& map, Cell lo, Cell hi, int blocked, int cells, int corners,
                       int points) {
  const ComplexityParts c = box_complexity(map, lo, hi);
  EXPECT_NEAR(c.blocked_fraction, static_cast<double>(blocked) / cells, 1e-12);
  EXPECT_EQ(c.vertices, corners);
  EXPECT_EQ(c.possible_vertices, points);
  EXPECT_NEAR(c.complexity, (static_cast<double>(blocked) / cells + static_cast<double>(corners) / points) / 2, 1e-12);
}

TEST(Complexity, OfHandDrawnGroups) {
  // A stool: four legs at the corners of a 3 x 3 box; all 16 lattice points are a leg's corner.
  expect_complexity(grid_from({"#.#", "...", "#.#"}), {0, 0}, {2, 2}, 4, 9, 16, 16);
  // Two 3 x 3 boxes a cell apart: 8 corners of 32 points.
  expect_complexity(grid_from({"###.###", "###.###", "###.###"}), {0, 0}, {6, 2}, 18, 21, 8, 32);
  // An L of three cells: 6 corners (the inner one included) of 9 points; the cells around the box
  // do not count (the box is cut out of the map).
  expect_complexity(grid_from({"####", "#.##", "####"}), {1, 0}, {2, 1}, 3, 4, 6, 9);
  // A diagonal pair touching at a corner: that point is one corner, not two.
  expect_complexity(grid_from({".#", "#."}), {0, 0}, {1, 1}, 2, 4, 7, 9);
}

// Two boxes a cell apart and a lamp two cells above them: Basic_Group links all three
// (C = 0.453 < 0.5); Release drops the longest link (the lamp's) and keeps the boxes (C = 0.554).
TEST(Grouping, ReleaseSplitsOffTheFarthestObstacle) {
  const OccupancyGrid map = grid_from({
      "#########",
      "#.......#",
      "#...#...#",  // the lamp
      "#.......#",
      "#.......#",
      "#..###..#",
      "#..###..#",
      "#..###..#",
      "#.......#",
      "#..###..#",
      "#..###..#",
      "#..###..#",
      "#.......#",
      "#########",
  });
  const Grouping g = group_obstacles(map);
  ASSERT_EQ(g.obstacles.size(), 3u);
  ASSERT_EQ(g.basic.size(), 1u);
  EXPECT_EQ(g.basic[0].obstacles, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(g.basic[0].links.size(), 2u);
  EXPECT_NEAR(g.basic[0].complexity(), (19.0 / 30 + 12.0 / 44) / 2, 1e-12);
  ASSERT_EQ(g.released.size(), 1u);
  EXPECT_EQ(g.released[0].obstacles, (std::vector<int>{0, 1}));
  EXPECT_NEAR(g.released[0].complexity(), (18.0 / 21 + 8.0 / 32) / 2, 1e-12);
  EXPECT_EQ(g.groups.size(), 1u);
  EXPECT_EQ(g.order, (std::vector<int>{0}));
}

// Two pairs of posts (each pair one group, C = (2/3 + 8/8) / 2 = 0.833), five cells apart. Their
// union's C is (4/18 + 16/28) / 2 = 0.397: merged when k = 0.3, not when k = 0.5.
TEST(Grouping, MergeJoinsNearestGroupsWhenTheUnionIsComplexEnough) {
  const OccupancyGrid map = grid_from({
      "#######",
      "#.....#",
      "#.#.#.#",
      "#.....#",
      "#.....#",
      "#.....#",
      "#.....#",
      "#.#.#.#",
      "#.....#",
      "#######",
  });
  GroupKConfig strict;
  const Grouping apart = group_obstacles(map, strict);
  ASSERT_EQ(apart.basic.size(), 2u);
  EXPECT_NEAR(apart.basic[0].complexity(), (2.0 / 3 + 1) / 2, 1e-12);
  EXPECT_EQ(apart.groups.size(), 2u);
  GroupKConfig loose;
  loose.k = 0.3;
  const Grouping joined = group_obstacles(map, loose);
  ASSERT_EQ(joined.groups.size(), 1u);
  EXPECT_EQ(joined.groups[0].obstacles, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(joined.groups[0].links.size(), 3u);  // both pairs' links and the bridge
  EXPECT_NEAR(joined.groups[0].complexity(), (4.0 / 18 + 16.0 / 28) / 2, 1e-12);
}

TEST(Grouping, ALoneLinkBelowKDissolvesTheGroup) {
  const OccupancyGrid map = grid_from({
      "##########",
      "#........#",
      "#.##...#.#",
      "#.##.....#",
      "#........#",
      "##########",
  });
  const Grouping g = group_obstacles(map);
  ASSERT_EQ(g.basic.size(), 1u);
  EXPECT_LT(g.basic[0].complexity(), 0.5);
  EXPECT_TRUE(g.released.empty());
  EXPECT_TRUE(g.groups.empty());
}

// The built-in room of the Group-k experiment: 7 Basic groups spanning 0.24..0.72 (the paper:
// 0.24..0.74); Release dissolves the sofa's group and trims three; no merge.
TEST(Grouping, TheClutterRoom) {
  const OccupancyGrid map = load_map_yaml(swarm::test::source_dir() + "/maps/clutter.yaml");
  const Grouping g = group_obstacles(map);
  EXPECT_EQ(g.obstacles.size(), 25u);
  ASSERT_EQ(g.basic.size(), 7u);
  double lo = 1, hi = 0;
  for (const ObstacleGroup& grp : g.basic) lo = std::min(lo, grp.complexity()), hi = std::max(hi, grp.complexity());
  EXPECT_NEAR(lo, 0.241, 0.001);
  EXPECT_NEAR(hi, 0.722, 0.001);
  EXPECT_EQ(g.released.size(), 6u);
  EXPECT_EQ(g.groups.size(), 6u);
  for (const ObstacleGroup& grp : g.groups) EXPECT_GE(grp.complexity(), 0.5);
  for (std::size_t i = 1; i < g.order.size(); ++i) {
    EXPECT_LE(g.groups[static_cast<std::size_t>(g.order[i - 1])].complexity(),
              g.groups[static_cast<std::size_t>(g.order[i])].complexity());
  }
}

TEST(GroupK, CleansOutsideFirstThenGroupsByComplexityAndCoversEverything) {
  const OccupancyGrid map = load_map_yaml(swarm::test::source_dir() + "/maps/clutter.yaml");
  const CellMask all = free_cells(map);
  const Cell start{1, map.height() - 2};  // the paper's (1, 1), top left
  const GroupKCoverage c = group_k(map, all, start);
  EXPECT_EQ(check_coverage_path(map, all, start, c.path), "");
  EXPECT_TRUE(c.path.missed.empty());
  ASSERT_EQ(c.parts.size(), c.grouping.groups.size() + 1);
  EXPECT_EQ(c.parts[0].group, -1);
  for (std::size_t p = 1; p < c.parts.size(); ++p) {
    EXPECT_EQ(c.parts[p].group, c.grouping.order[p - 1]);
    EXPECT_GE(c.parts[p].first_cell, c.parts[p - 1].first_cell);
  }
  // Every cell of the outside area is clean when the first group starts.
  const std::vector<CellMask> parts = group_k_parts(map, c.grouping, all);
  CellMask seen(map.size(), 0);
  for (std::size_t i = 0; i <= c.parts[1].first_cell; ++i) seen[static_cast<std::size_t>(map.index(c.path.cells[i]))] = 1;
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (parts[0][i]) {
      ASSERT_TRUE(seen[i]) << "outside cell " << i;
    }
  }
}

TEST(GroupK, OnAnEmptyRoomIsPlowing) {
  const OccupancyGrid map = load_map_yaml(swarm::test::source_dir() + "/maps/empty.yaml");
  const CellMask all = free_cells(map);
  const GroupKCoverage g = group_k(map, all, {1, 48});
  EXPECT_TRUE(g.grouping.groups.empty());
  EXPECT_EQ(g.path.cells, plow(map, all, {1, 48}).cells);
}

// A robot's share of the room (the right half): every cell of it, from the robot's cell.
TEST(GroupK, CoversARegion) {
  const OccupancyGrid map = load_map_yaml(swarm::test::source_dir() + "/maps/clutter.yaml");
  CellMask half = free_cells(map);
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (map.cell_of(i).x < 30) half[static_cast<std::size_t>(i)] = 0;
  }
  const GroupKCoverage g = group_k(map, half, {10, 10});
  EXPECT_EQ(check_coverage_path(map, half, {10, 10}, g.path), "");
  const CoveragePath p = plow(map, half, {10, 10});
  EXPECT_EQ(check_coverage_path(map, half, {10, 10}, p), "");
}

TEST(GroupK, CoversEveryFreeCellOfMovingAiMaps) {
  for (const char* name : {"room-32-32-4.map", "random-32-32-20.map"}) {
    const std::string path = swarm::test::benchmarks_dir() + "/movingai/" + name;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
    const OccupancyGrid map = load_movingai_map(path, 0.1);
    const CellMask all = free_cells(map);
    // Cells cut off from the start are listed as missed; the validator checks they really are.
    Cell start{0, 0};
    for (int i = 0; i < static_cast<int>(map.size()); ++i) {
      if (map.at(i) == CellState::Free) {
        start = map.cell_of(i);
        break;
      }
    }
    const GroupKCoverage g = group_k(map, all, start);
    EXPECT_EQ(check_coverage_path(map, all, start, g.path), "") << name;
    EXPECT_EQ(check_coverage_path(map, all, start, plow(map, all, start)), "") << name;
  }
}

TEST(GroupK, SameSeedSamePath) {
  const OccupancyGrid map = load_map_yaml(swarm::test::source_dir() + "/maps/clutter.yaml");
  const CellMask all = free_cells(map);
  EXPECT_EQ(group_k(map, all, {1, 48}).path.cells, group_k(map, all, {1, 48}).path.cells);
}

}  // namespace
}  // namespace swarm::planner
