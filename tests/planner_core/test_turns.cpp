#include "swarm/planner/tours/turns.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace swarm::planner {
namespace {

TEST(Turns, StepHeadingsAreEighthsCounterClockwiseFromRight) {
  const Cell o{5, 5};
  EXPECT_EQ(step_heading(o, {6, 5}), 0);
  EXPECT_EQ(step_heading(o, {6, 6}), 1);
  EXPECT_EQ(step_heading(o, {5, 6}), 2);
  EXPECT_EQ(step_heading(o, {4, 6}), 3);
  EXPECT_EQ(step_heading(o, {4, 5}), 4);
  EXPECT_EQ(step_heading(o, {4, 4}), 5);
  EXPECT_EQ(step_heading(o, {5, 4}), 6);
  EXPECT_EQ(step_heading(o, {6, 4}), 7);
  EXPECT_EQ(step_heading(o, o), std::nullopt);
}

TEST(Turns, TurnIsTheShorterWayRound) {
  EXPECT_EQ(turn_eighths(0, 0), 0);
  EXPECT_EQ(turn_eighths(0, 4), 4);
  EXPECT_EQ(turn_eighths(1, 7), 2);  // 45 deg to -45 deg: 90 deg, not 270
  EXPECT_EQ(turn_eighths(7, 0), 1);
  EXPECT_EQ(turn_eighths(kHeadingUp, kHeadingLeft), 2);
  EXPECT_EQ(turn_eighths(6, 1), 3);
}

// right, up-right, up, left, (stay), down-left: from "up" 2 + 1 + 1 + 2 + 1 = 7 eighths.
TEST(Turns, RotationOfAHandMadePathInMultiplesOfAnEighth) {
  const std::vector<Cell> path{{0, 0}, {1, 0}, {2, 1}, {2, 2}, {1, 2}, {1, 2}, {0, 1}};
  std::optional<int> last;
  EXPECT_EQ(rotation_eighths(path, kHeadingUp, &last), 7);
  EXPECT_EQ(last, 5);
  EXPECT_NEAR(eighths_to_rad(7), 7 * M_PI / 4, 1e-12);
  // Without an initial heading the first step is free: 7 - 2.
  EXPECT_EQ(rotation_eighths(path, std::nullopt), 5);
  // Facing left first: left -> right is an about-turn (4), then 1 + 1 + 2 + 1.
  EXPECT_EQ(rotation_eighths(path, kHeadingLeft), 9);
}

TEST(Turns, APathThatNeverMovesKeepsItsHeading) {
  std::optional<int> last;
  EXPECT_EQ(rotation_eighths({{3, 3}, {3, 3}}, kHeadingLeft, &last), 0);
  EXPECT_EQ(last, kHeadingLeft);
  EXPECT_EQ(rotation_eighths({}, std::nullopt, &last), 0);
  EXPECT_EQ(last, std::nullopt);
}

TEST(Turns, CountsTurnsBySize) {
  // right, up (90), down (180), right (90), right, up-right (45).
  const std::vector<Cell> path{{0, 0}, {1, 0}, {1, 1}, {1, 0}, {2, 0}, {3, 0}, {4, 1}};
  const TurnCounts t = count_turns(path);
  EXPECT_EQ(t.turns_45, 1);
  EXPECT_EQ(t.turns_90, 2);
  EXPECT_EQ(t.turns_135, 0);
  EXPECT_EQ(t.turns_180, 1);
}

}  // namespace
}  // namespace swarm::planner
