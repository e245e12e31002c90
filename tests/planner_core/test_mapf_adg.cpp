// The action-dependency graph (planner/mapf/adg.hpp) on hand-made plans: a crossing, a follower, a
// rotation, a plan with a conflict. tests/sim/test_adg_drive.cpp drives solvers' plans with late
// knowledge through the simulator's move resolution.
#include <gtest/gtest.h>

#include "swarm/planner/mapf/adg.hpp"

namespace {

using swarm::planner::Cell;
using namespace swarm::planner::mapf;

TEST(Adg, ACrossingWaitsForTheRobotPlannedFirst) {
  // Robot 0 crosses (1, 1) at time 1; robot 1 waits a step, then crosses it at time 2.
  const std::vector<Path> plan{{{0, 1}, {1, 1}, {2, 1}}, {{1, 0}, {1, 0}, {1, 1}, {1, 2}}};
  const Dependencies d = dependencies(plan);
  EXPECT_EQ(d.routes[1], (std::vector<Cell>{{1, 0}, {1, 1}, {1, 2}}));  // the wait is gone
  EXPECT_EQ(d.planned_time[1], (std::vector<int>{0, 2, 3}));
  EXPECT_TRUE(d.needs[0][1].empty());
  EXPECT_EQ(d.needs[1][1], (std::vector<Need>{{0, 2}}));  // robot 0 has left (1, 1)
  EXPECT_TRUE(d.needs[1][2].empty());
  EXPECT_EQ(releasable(d, 1, {0, 0}), 0u);
  EXPECT_EQ(releasable(d, 1, {1, 0}), 0u);
  EXPECT_EQ(releasable(d, 1, {2, 0}), 2u);
  EXPECT_EQ(releasable(d, 0, {0, 0}), 2u);
}

TEST(Adg, ATimeOfThePlanIsTheRouteStepEnteredByThen) {
  // Robot 1 waits at (1, 0) through times 0 and 1, enters (1, 1) at 2 and (1, 2) at 3, then stays.
  const std::vector<Path> plan{{{0, 1}, {1, 1}, {2, 1}}, {{1, 0}, {1, 0}, {1, 1}, {1, 2}}};
  const Dependencies d = dependencies(plan);
  EXPECT_EQ(step_at(d, 1, 0), 0u);
  EXPECT_EQ(step_at(d, 1, 1), 0u);
  EXPECT_EQ(step_at(d, 1, 2), 1u);
  EXPECT_EQ(step_at(d, 1, 3), 2u);
  EXPECT_EQ(step_at(d, 1, 9), 2u);
  EXPECT_EQ(step_at(d, 0, 1), 1u);
  EXPECT_EQ(last_time(plan), 3u);  // robot 1's path, the longer
  EXPECT_EQ(last_time({}), 0u);
}

// Progress read from where a robot stands: its route (0,0) (1,0) (1,1) (1,0) (2,0) passes (1,0)
// twice, so only the next step's cell moves it on, one step at a time.
TEST(Adg, ProgressFollowsTheRobotsCellOneStepAtATime) {
  const std::vector<Path> plan{{{0, 0}, {1, 0}, {1, 1}, {1, 0}, {2, 0}}};
  const Dependencies d = dependencies(plan);
  EXPECT_EQ(progress_at(d, 0, 0, {0, 0}), 0u);  // still at its start
  EXPECT_EQ(progress_at(d, 0, 0, {1, 0}), 1u);
  EXPECT_EQ(progress_at(d, 0, 1, {1, 1}), 2u);
  EXPECT_EQ(progress_at(d, 0, 2, {1, 0}), 3u);  // (1, 0) again: the fourth step, not the second
  EXPECT_EQ(progress_at(d, 0, 1, {2, 0}), 1u);  // two steps ahead (a look missed): left as known
  EXPECT_EQ(progress_at(d, 0, 3, {0, 0}), 3u);  // off its route: never lowered
  EXPECT_EQ(progress_at(d, 0, 4, {2, 0}), 4u);  // at its end
}

TEST(Adg, AFollowerWaitsUntilTheCellAheadIsLeft) {
  // Robot 1 follows robot 0 along a corridor one step behind: each of its steps needs robot 0's next.
  const std::vector<Path> plan{{{1, 0}, {2, 0}, {3, 0}}, {{0, 0}, {1, 0}, {2, 0}}};
  const Dependencies d = dependencies(plan);
  EXPECT_EQ(d.needs[1][1], (std::vector<Need>{{0, 1}}));
  EXPECT_EQ(d.needs[1][2], (std::vector<Need>{{0, 2}}));
  EXPECT_EQ(releasable(d, 1, {1, 0}), 1u);
}

TEST(Adg, APlanWithAVertexConflictIsRefused) {
  const std::vector<Path> plan{{{0, 0}, {1, 0}}, {{2, 0}, {1, 0}}};
  EXPECT_THROW((void)dependencies(plan), std::invalid_argument);
}

TEST(Adg, ARotationIsOneJointStep) {
  // Four robots go round the 2 x 2 square in one step: each needs the one ahead only to stand there.
  const std::vector<Path> plan{{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}}, {{0, 1}, {0, 0}}};
  const Dependencies d = dependencies(plan);
  EXPECT_EQ(d.needs[0][1], (std::vector<Need>{{1, 0}}));
  EXPECT_EQ(d.needs[3][1], (std::vector<Need>{{0, 0}}));
  for (int r = 0; r < 4; ++r) EXPECT_EQ(releasable(d, r, {0, 0, 0, 0}), 1u) << r;
}

// Held (a live run): no robot is released into the rotation; ready_rotations names it once every
// member stands ready; once made, it is behind each robot, and robot 0 goes on to its next cell.
TEST(Adg, AHeldRotationIsNamedWhenReadyAndIsBehindItsRobotsOnceMade) {
  // Robots 0..3 round the square (0, 0) -> (0, 1) -> (1, 1) -> (1, 0) -> (0, 0) at time 1; robot 0
  // then on to (0, 2).
  const std::vector<Path> plan{{{0, 0}, {0, 1}, {0, 2}}, {{0, 1}, {1, 1}}, {{1, 1}, {1, 0}}, {{1, 0}, {0, 0}}};
  const Dependencies d = dependencies(plan);
  ASSERT_EQ(d.rotations.size(), 1u);
  EXPECT_EQ(releasable(d, 0, {0, 0, 0, 0}), 2u);  // Together: the rotation and the step after it
  EXPECT_EQ(releasable(d, 0, {0, 0, 0, 0}, Rotations::Held), 0u);
  EXPECT_EQ(releasable(d, 1, {0, 0, 0, 0}, Rotations::Held), 0u);
  EXPECT_EQ(ready_rotations(d, {0, 0, 0, 0}), (std::vector<int>{0}));
  EXPECT_TRUE(ready_rotations(d, {1, 1, 1, 1}).empty());  // made
  EXPECT_EQ(releasable(d, 0, {1, 1, 1, 1}, Rotations::Held), 2u);
}

// The traffic layer grows a plan by its next window while it is driven: the grown plan's old steps
// keep their needs, and its old rotations their numbers, so progress, releases and rotation
// orders of the plan as it was hold for it. Window 1 (times 0-2) has a rotation at time 2; window 2
// (times 2-4, from where window 1 ends) one at time 3 that robot 0 is in, so a search robot by
// robot finds it first.
TEST(Adg, APlanGrownAtItsEndKeepsItsStepsNeedsAndItsRotationsNumbers) {
  // Window 1: robots 1, 2, 3, 7 round the square (0, 0)-(1, 1); robots 0, 4, 5, 6 wait.
  const std::vector<Path> window1{{{5, 0}, {5, 0}, {5, 0}}, {{0, 0}, {0, 0}, {1, 0}}, {{1, 0}, {1, 0}, {1, 1}},
                                  {{1, 1}, {1, 1}, {0, 1}}, {{6, 0}, {6, 0}, {6, 0}}, {{6, 1}, {6, 1}, {6, 1}},
                                  {{5, 1}, {5, 1}, {5, 1}}, {{0, 1}, {0, 1}, {0, 0}}};
  // Window 2: robots 0, 4, 5, 6 round the square (5, 0)-(6, 1) at time 3; the others wait.
  const std::vector<Path> window2{{{5, 0}, {6, 0}, {6, 0}}, {{1, 0}, {1, 0}, {1, 0}}, {{1, 1}, {1, 1}, {1, 1}},
                                  {{0, 1}, {0, 1}, {0, 1}}, {{6, 0}, {6, 1}, {6, 1}}, {{6, 1}, {5, 1}, {5, 1}},
                                  {{5, 1}, {5, 0}, {5, 0}}, {{0, 0}, {0, 0}, {0, 0}}};
  std::vector<Path> grown = window1;
  for (std::size_t r = 0; r < grown.size(); ++r) grown[r].insert(grown[r].end(), window2[r].begin() + 1, window2[r].end());
  const Dependencies before = dependencies(window1);
  const Dependencies after = dependencies(grown);
  ASSERT_EQ(before.rotations.size(), 1u);
  ASSERT_EQ(after.rotations.size(), 2u);
  EXPECT_EQ(after.rotations[0], before.rotations[0]);
  EXPECT_EQ(after.rotation_of[0][1], 1);  // the new one after it
  for (std::size_t r = 0; r < window1.size(); ++r) {
    for (std::size_t k = 0; k < before.routes[r].size(); ++k) {
      EXPECT_EQ(after.routes[r][k], before.routes[r][k]) << r << " " << k;
      EXPECT_EQ(after.needs[r][k], before.needs[r][k]) << r << " " << k;
      EXPECT_EQ(after.rotation_of[r][k], before.rotation_of[r][k]) << r << " " << k;
    }
  }
}

// Rotations are numbered by their time step, whatever robot finds them first.
TEST(Adg, RotationsAreNumberedByTheirTimeStep) {
  // Robots 0-3 round the square (4, 0)-(5, 1) at time 2; robots 4-7 round (0, 0)-(1, 1) at time 1.
  const std::vector<Path> plan{{{4, 0}, {4, 0}, {5, 0}}, {{5, 0}, {5, 0}, {5, 1}}, {{5, 1}, {5, 1}, {4, 1}},
                               {{4, 1}, {4, 1}, {4, 0}}, {{0, 0}, {1, 0}, {1, 0}}, {{1, 0}, {1, 1}, {1, 1}},
                               {{1, 1}, {0, 1}, {0, 1}}, {{0, 1}, {0, 0}, {0, 0}}};
  const Dependencies d = dependencies(plan);
  ASSERT_EQ(d.rotations.size(), 2u);
  EXPECT_EQ(d.rotation_of[4][1], 0);  // time 1
  EXPECT_EQ(d.rotation_of[0][1], 1);  // time 2
}

}  // namespace
