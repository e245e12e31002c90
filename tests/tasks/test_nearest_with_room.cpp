// Collect's sharing rule (tasks/collect/nearest_with_room.hpp): nearest holder with room left,
// room an even share of what is to be held, what is held already counted.
#include "swarm/tasks/collect/nearest_with_room.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace swarm::collect {
namespace {

using planner::Cell;

TEST(NearestWithRoom, EachObjectGoesToTheNearestHolderUntilItsEvenShareIsFull) {
  // Four objects beside holder 0, one beside holder 1: room is ⌈5 / 2⌉ = 3, so the fourth near
  // holder 0 goes to holder 1.
  const std::vector<Cell> objects = {{1, 0}, {2, 0}, {0, 1}, {1, 1}, {9, 0}};
  const std::vector<Cell> holders = {{0, 0}, {10, 0}};
  std::vector<std::size_t> held;
  EXPECT_EQ(nearest_with_room(objects, holders, held), (std::vector<int>{0, 0, 0, 1, 1}));
  EXPECT_EQ(held, (std::vector<std::size_t>{3, 2}));
}

TEST(NearestWithRoom, WhatIsHeldAlreadyCountsAndTiesGoToTheFirstHolder) {
  // Holder 0 holds 2 already: room is ⌈(2 + 2) / 2⌉ = 2, so both objects, halfway between, go to
  // holder 1 although holder 0 is first on a tie.
  const std::vector<Cell> objects = {{5, 0}, {5, 0}};
  const std::vector<Cell> holders = {{0, 0}, {10, 0}};
  std::vector<std::size_t> held = {2, 0};
  EXPECT_EQ(nearest_with_room(objects, holders, held), (std::vector<int>{1, 1}));
  held = {0, 0};
  EXPECT_EQ(nearest_with_room({{5, 0}}, holders, held), (std::vector<int>{0}));
  // No holder: nobody takes anything.
  std::vector<std::size_t> none;
  EXPECT_EQ(nearest_with_room(objects, {}, none), (std::vector<int>{-1, -1}));
}

}  // namespace
}  // namespace swarm::collect
