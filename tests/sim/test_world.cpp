#include "swarm/sim/world.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::sim {
namespace {

using planner::Cell;
using planner::CellState;
using planner::OccupancyGrid;
using swarm::test::grid_from;

constexpr LidarConfig kLidar{360, 15.0f};

OccupancyGrid open_room(int w, int h) { return OccupancyGrid(w, h, 0.2, 0.0, 0.0, CellState::Free); }

TEST(World, MovesOneCellPerTickAlongTheCommandedPath) {
  World w(open_room(5, 5), {{0, 0}}, kLidar);
  w.command(0, {{0, 0}, {1, 1}, {2, 1}, {3, 2}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 1}));
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{2, 1}));
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{3, 2}));
  w.move();  // end of the path: stays
  EXPECT_EQ(w.robots()[0], (Cell{3, 2}));
  EXPECT_EQ(w.moves(), 3u);
  EXPECT_EQ(w.wall_stops(), 0u);
  EXPECT_EQ(w.blocked_moves(), 0u);
}

TEST(World, APathContinuesFromTheRobotsPlaceInIt) {
  World w(open_room(5, 1), {{2, 0}}, kLidar);
  // The robot is at index 2: it goes on to (3, 0), not back to (0, 0).
  w.command(0, {{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{3, 0}));
  // A path starting next to the robot (Chebyshev distance 1) is taken from its first cell.
  w.command(0, {{4, 0}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{4, 0}));
  EXPECT_EQ(w.moves(), 2u);
}

TEST(World, APathNeitherContainingNorNextToTheRobotIsIgnored) {
  World w(open_room(6, 6), {{0, 0}}, kLidar);
  w.command(0, {{2, 2}, {3, 3}});  // starts 2 cells away
  for (int i = 0; i < 3; ++i) w.move();
  EXPECT_EQ(w.robots()[0], (Cell{0, 0}));
  // It also replaces the path the robot was following: the robot stops (its agent sees that it
  // does not move and re-plans).
  w.command(0, {{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 0}));
  w.command(0, {{5, 5}});
  w.move();
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 0}));
  EXPECT_EQ(w.moves(), 1u);
  EXPECT_EQ(w.wall_stops(), 0u);
  EXPECT_EQ(w.blocked_moves(), 0u);
}

TEST(World, ADiagonalMoveMayNotCutACornerAndStopsTheRobot) {
  const OccupancyGrid truth = grid_from({
      "...",  // y = 1
      ".#.",  // y = 0
  });
  World w(truth, {{0, 0}}, kLidar);
  // (0,0)->(1,1) passes the corner of the wall (1, 0): refused, counted, and the path dropped.
  w.command(0, {{0, 0}, {1, 1}, {2, 1}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{0, 0}));
  EXPECT_EQ(w.wall_stops(), 1u);
  w.move();  // no path left: neither a move nor another wall stop
  EXPECT_EQ(w.robots()[0], (Cell{0, 0}));
  EXPECT_EQ(w.wall_stops(), 1u);
  // The same cell reached without cutting the corner.
  w.command(0, {{0, 0}, {0, 1}, {1, 1}});
  w.move();
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 1}));
  EXPECT_EQ(w.moves(), 2u);
  // Straight into the wall: another stop.
  w.command(0, {{1, 1}, {1, 0}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 1}));
  EXPECT_EQ(w.wall_stops(), 2u);
  EXPECT_EQ(w.blocked_moves(), 0u);
}

TEST(World, TwoRobotsContendingForACellTheLowerIdMovesAndTheOtherWaits) {
  World w(open_room(3, 3), {{0, 1}, {2, 1}}, kLidar);
  w.command(0, {{0, 1}, {1, 1}, {1, 2}});
  w.command(1, {{2, 1}, {1, 1}, {0, 1}});
  // Tick 1: robot 0 takes (1, 1); robot 1 finds it held and waits (one blocked move).
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 1}));
  EXPECT_EQ(w.robots()[1], (Cell{2, 1}));
  EXPECT_EQ(w.blocked_moves(), 1u);
  // Tick 2: robot 0 moves on to (1, 2) first, so robot 1 gets (1, 1) in the same tick.
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 2}));
  EXPECT_EQ(w.robots()[1], (Cell{1, 1}));
  // Tick 3: robot 1 finishes its path.
  w.move();
  EXPECT_EQ(w.robots()[1], (Cell{0, 1}));
  EXPECT_EQ(w.blocked_moves(), 1u);
  EXPECT_EQ(w.moves(), 4u);
  EXPECT_EQ(w.wall_stops(), 0u);
}

TEST(World, IdOrderNotPositionDecidesWhoMovesFirst) {
  // Mirror image of the test above: now robot 1 comes from the left and still loses.
  World w(open_room(3, 1), {{2, 0}, {0, 0}}, kLidar);
  w.command(0, {{2, 0}, {1, 0}});
  w.command(1, {{0, 0}, {1, 0}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 0}));
  EXPECT_EQ(w.robots()[1], (Cell{0, 0}));
  EXPECT_EQ(w.blocked_moves(), 1u);
  // The waiting robot keeps its path and retries every tick: one more blocked move per tick.
  w.move();
  EXPECT_EQ(w.blocked_moves(), 2u);
  EXPECT_EQ(w.robots()[1], (Cell{0, 0}));
}

TEST(World, ExploredFractionAfterOneScanCountsSeenReachableFreeCells) {
  const OccupancyGrid truth = grid_from({
      "###..",  // y = 2
      "###.#",  // y = 1
      "....#",  // y = 0
  });
  // Reachable free cells from (0, 0): (0..3, 0), (3, 1), (3, 2), (4, 2) = 7.
  World w(truth, {{0, 0}}, kLidar);
  EXPECT_EQ(w.reachable_free_cells(), 7);
  EXPECT_DOUBLE_EQ(w.explored_fraction(), 0.0);
  std::vector<float> ranges;
  w.scan(0, ranges);
  ASSERT_EQ(ranges.size(), 360u);
  // From (0.5, 0.5): row 0 is seen by the +x beam (it ends in the wall (4, 0) at 3.5). (3, 1) is
  // entered from below by beams crossing y = 1 in x = [3, 4], i.e. tan(a) in [1/7, 1/5] (the 9..11
  // degree beams). (3, 2) and (4, 2) are hidden: reaching y = 2 before x = 4 needs tan(a) >= 3/7,
  // but crossing y = 1 at x >= 3 needs tan(a) <= 1/5. Seen: 5 of 7.
  EXPECT_FLOAT_EQ(ranges[0], 3.5f);
  EXPECT_DOUBLE_EQ(w.explored_fraction(), 5.0 / 7.0);
  // Scanning the same place again adds nothing.
  w.scan(0, ranges);
  EXPECT_DOUBLE_EQ(w.explored_fraction(), 5.0 / 7.0);
  // From (3, 1) the rest is seen: all 7.
  w.command(0, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}});
  for (int i = 0; i < 4; ++i) w.move();
  ASSERT_EQ(w.robots()[0], (Cell{3, 1}));
  w.scan(0, ranges);
  EXPECT_DOUBLE_EQ(w.explored_fraction(), 1.0);
}

TEST(World, OnlyCellsReachableFromTheStartCount) {
  // The right room (x = 3..4) is closed off: its free cells are neither counted nor explored.
  const OccupancyGrid truth = grid_from({
      "..#..",  // y = 1
      "..#..",  // y = 0
  });
  World w(truth, {{0, 0}}, kLidar);
  EXPECT_EQ(w.reachable_free_cells(), 4);
  std::vector<float> ranges;
  w.scan(0, ranges);
  EXPECT_DOUBLE_EQ(w.explored_fraction(), 1.0);
}

}  // namespace
}  // namespace swarm::sim
