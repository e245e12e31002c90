#include "swarm/planner/grid/motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/motion_cases.hpp"

namespace swarm::planner {
namespace {

TEST(MotionModel, WaitsStepsAndJumpsUnderBothConnectivities) {
  const OccupancyGrid g(5, 5, 0.2, 0.0, 0.0, CellState::Free);
  const MotionModel four = MotionModel::four();
  const MotionModel eight = MotionModel::eight();
  EXPECT_EQ(four.check(g, {2, 2}, {2, 2}), MoveCheck::Wait);
  EXPECT_EQ(four.check(g, {2, 2}, {3, 2}), MoveCheck::Ok);
  EXPECT_EQ(four.check(g, {2, 2}, {3, 3}), MoveCheck::NotAdjacent);  // a diagonal is no 4-step
  EXPECT_EQ(eight.check(g, {2, 2}, {3, 3}), MoveCheck::Ok);
  EXPECT_EQ(eight.check(g, {2, 2}, {4, 2}), MoveCheck::NotAdjacent);
  EXPECT_EQ(four.check(g, {0, 0}, {-1, 0}), MoveCheck::Blocked);  // outside the map is a wall
  EXPECT_TRUE(four.legal(g, {1, 1}, {1, 1}));
  EXPECT_FALSE(four.legal(g, {1, 1}, {2, 2}));
}

TEST(MotionModel, CornerCuttingAndUnknownCells) {
  const OccupancyGrid g = swarm::test::grid_from({
      "..?",  // y = 2
      ".#.",  // y = 1
      "...",  // y = 0
  });
  const MotionModel eight = MotionModel::eight();
  // (0,0) -> (1,1): the target is a wall.
  EXPECT_EQ(eight.check(g, {0, 0}, {1, 1}), MoveCheck::Blocked);
  // (1,0) -> (0,1) sweeps (0,0) and (1,1); (1,1) is a wall.
  EXPECT_EQ(eight.check(g, {1, 0}, {0, 1}), MoveCheck::CornerCut);
  // (1,2) -> (2,2): Unknown is passable only when the caller says so.
  EXPECT_EQ(eight.check(g, {1, 2}, {2, 2}), MoveCheck::Blocked);
  EXPECT_EQ(eight.check(g, {1, 2}, {2, 2}, Passability::UnknownIsFree), MoveCheck::Ok);
  // Neighbours of (0,2) in the fixed order: +x (1,2), -y (0,1); diagonal (1,1) is a wall.
  std::vector<Cell> seen;
  eight.for_each_neighbour(g, {0, 2}, [&](Cell c, double) { seen.push_back(c); });
  EXPECT_EQ(seen, (std::vector<Cell>{{1, 2}, {0, 1}}));
  EXPECT_DOUBLE_EQ(eight.heuristic({0, 0}, {3, 1}), 2 + MotionModel::kDiagonalCost);
  EXPECT_DOUBLE_EQ(MotionModel::four().heuristic({0, 0}, {3, 1}), 4.0);
}

// The shared table (swarm_test/motion_cases.hpp): the simulator's tests check the same cases.
TEST(StepConflicts, TheSharedMotionCases) {
  for (const auto& c : swarm::test::motion_cases()) {
    const StepConflicts got = find_step_conflicts(c.from, c.to);
    EXPECT_EQ(static_cast<int>(got.vertex.size()), c.vertex_events) << c.name;
    EXPECT_EQ(static_cast<int>(got.edge.size()), c.edge_events) << c.name;
  }
}

TEST(StepConflicts, NamesTheCellAndTheRobotsInOrder) {
  const StepConflicts c = find_step_conflicts({{0, 1}, {1, 0}, {2, 1}, {5, 5}, {6, 5}},
                                              {{1, 1}, {1, 1}, {1, 1}, {6, 5}, {5, 5}});
  ASSERT_EQ(c.vertex.size(), 1u);
  EXPECT_EQ(c.vertex[0].cell, (Cell{1, 1}));
  EXPECT_EQ(c.vertex[0].robots, (std::vector<int>{0, 1, 2}));
  ASSERT_EQ(c.edge.size(), 1u);
  EXPECT_EQ(c.edge[0].a, 3);
  EXPECT_EQ(c.edge[0].b, 4);
}

}  // namespace
}  // namespace swarm::planner
