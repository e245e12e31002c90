#include "swarm_test/ascii_grid.hpp"
#include "swarm/planner/explore/frontier.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

namespace swarm::planner {

void PrintTo(const Cell& c, std::ostream* os) { *os << "(" << c.x << ", " << c.y << ")"; }

namespace {

using swarm::test::grid_from;  // rows top first (swarm_test/ascii_grid.hpp)

TEST(Frontier, FreeCellsWithAnUnknownFourNeighbourInRowMajorOrder) {
  const OccupancyGrid g = grid_from({
      "#####",  // y = 4
      "#..?#",  // y = 3
      "#...#",  // y = 2
      "#.?.#",  // y = 1
      "#####",  // y = 0
  });
  const std::vector<Cell> expected = {{1, 1}, {3, 1}, {2, 2}, {3, 2}, {2, 3}};
  EXPECT_EQ(find_frontiers(g), expected);
  EXPECT_TRUE(is_frontier(g, {2, 3}));
  EXPECT_FALSE(is_frontier(g, {1, 2}));  // Unknown (2, 1) is only diagonal to it
  EXPECT_FALSE(is_frontier(g, {3, 3}));  // Unknown itself
  EXPECT_FALSE(is_frontier(g, {0, 3}));  // Occupied
}

TEST(Frontier, MapEdgeIsNotUnknown) {
  // Out-of-bounds neighbours read as Occupied, so a fully known map has no frontier.
  OccupancyGrid g(3, 2, 0.2, 0.0, 0.0, CellState::Free);
  EXPECT_TRUE(find_frontiers(g).empty());
  g.set(Cell{2, 1}, CellState::Unknown);
  const std::vector<Cell> expected = {{2, 0}, {1, 1}};
  EXPECT_EQ(find_frontiers(g), expected);
}

TEST(Frontier, ReachableMaskFollowsFreeCellsAndSkipsNonFreeSeeds) {
  const OccupancyGrid g = grid_from({
      "..#..",  // y = 2
      "..#..",  // y = 1
      "..#.?",  // y = 0
  });
  const std::vector<std::uint8_t> mask = reachable_mask(g, {{0, 0}});
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(mask[static_cast<std::size_t>(g.index({x, y}))], x < 2 ? 1 : 0) << x << "," << y;
    }
  }
  // Occupied and Unknown seeds are ignored; several seeds union.
  const std::vector<std::uint8_t> none = reachable_mask(g, {{2, 0}, {4, 0}});
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
  const std::vector<std::uint8_t> both = reachable_mask(g, {{0, 2}, {3, 2}});
  EXPECT_EQ(std::count(both.begin(), both.end(), 1), 6 + 5);
}

TEST(Frontier, StepDistancesCountMovesFromTheNearestSeed) {
  const OccupancyGrid g = grid_from({
      ".....",  // y = 2
      ".###.",  // y = 1
      "....?",  // y = 0
  });
  const std::vector<int> d = step_distances(g, {{0, 0}, {4, 2}}, MotionModel::four());
  const auto at = [&](int x, int y) { return d[static_cast<std::size_t>(g.index({x, y}))]; };
  EXPECT_EQ(at(0, 0), 0);
  EXPECT_EQ(at(3, 0), 3);   // along the bottom from (0, 0)
  EXPECT_EQ(at(4, 1), 1);   // down from (4, 2)
  EXPECT_EQ(at(2, 2), 2);   // along the top from (4, 2)
  EXPECT_EQ(at(1, 1), -1);  // a wall
  EXPECT_EQ(at(4, 0), -1);  // unknown
  // The mask is the distances' reach.
  const std::vector<std::uint8_t> mask = reachable_mask(g, {{0, 0}}, MotionModel::four());
  for (std::size_t i = 0; i < mask.size(); ++i) EXPECT_EQ(mask[i] == 1, step_distances(g, {{0, 0}}, MotionModel::four())[i] >= 0);
}

// Regression guard for the motion model: a frontier behind two diagonally touching walls is
// visible but not drivable.
TEST(Frontier, ReachableFrontiersExcludeOneReachableOnlyByCuttingACorner) {
  const OccupancyGrid g = grid_from({
      "#####",  // y = 4
      "##.?#",  // y = 3: (2, 3) is a frontier, only diagonal to (1, 2)
      "#.#.#",  // y = 2
      "#..?#",  // y = 1: (2, 1) is a frontier next to the robot's area
      "#####",  // y = 0
  });
  const std::vector<Cell> all = {{2, 1}, {3, 2}, {2, 3}};
  EXPECT_EQ(find_frontiers(g), all);
  // From (1, 1): (2, 1) is adjacent; (3, 2) is diagonal from (2, 1) but (2, 2) is Occupied and
  // (3, 1) Unknown, so that step cuts a corner too; (2, 3) needs the step (1, 2) -> (2, 3) past
  // Occupied (2, 2) and (1, 3).
  const std::vector<Cell> reachable = {{2, 1}};
  EXPECT_EQ(reachable_frontiers(g, {{1, 1}}), reachable);
  // Opening the wall between them connects everything; (2, 2) has no Unknown 4-neighbour.
  OccupancyGrid opened = g;
  opened.set(Cell{2, 2}, CellState::Free);
  const std::vector<Cell> now = {{2, 1}, {3, 2}, {2, 3}};
  EXPECT_EQ(find_frontiers(opened), now);
  EXPECT_EQ(reachable_frontiers(opened, {{1, 1}}), now);
}

TEST(Frontier, DiagonalThroughFreeCornerIsReachable) {
  const OccupancyGrid g = grid_from({
      "..?",  // y = 2
      "...",  // y = 1
      "..#",  // y = 0
  });
  const std::vector<std::uint8_t> mask = reachable_mask(g, {{0, 0}});
  EXPECT_EQ(mask[static_cast<std::size_t>(g.index({2, 1}))], 1);
  const std::vector<Cell> expected = {{2, 1}, {1, 2}};
  EXPECT_EQ(reachable_frontiers(g, {{0, 0}}), expected);
}

}  // namespace
}  // namespace swarm::planner
