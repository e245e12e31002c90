// The converters of wire bytes (app/convert.hpp) on bad input: each throws std::runtime_error
// naming what is wrong (the mailbox then drops the message), and good input round-trips.
#include "swarm/app/convert.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace swarm::app {
namespace {

using planner::Cell;
using planner::CellChange;
using planner::CellState;

TEST(Convert, APatchOutsideTheMapIsRefused) {
  const auto bytes = encode_patch({{5, CellState::Free}, {99, CellState::Occupied}}, planner::PatchEncoding::RunLength);
  EXPECT_EQ(decode_patch(bytes, 100).size(), 2u);
  try {
    (void)decode_patch(bytes, 50);  // regression: applied blindly, index 99 wrote past a 50-cell map
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "received a malformed map patch, or one with cells outside the map of 50 cells");
  }
  EXPECT_THROW((void)decode_patch({}, 50), std::runtime_error);
  EXPECT_THROW((void)decode_patch({1, 0x80, 0x80, 0x80, 0x80, 0x80, 0x01}, 50), std::runtime_error);
}

TEST(Convert, CellListsOfOddLengthAreRefused) {
  EXPECT_EQ(from_xy(to_xy(std::vector<Cell>{{1, 2}, {3, 4}})), (std::vector<Cell>{{1, 2}, {3, 4}}));
  EXPECT_THROW((void)from_xy({1, 2, 3}), std::runtime_error);
}

TEST(Convert, MapsMustHaveTheReceiversSize) {
  planner::OccupancyGrid g(3, 2);
  g.set(Cell{1, 1}, CellState::Occupied);
  for (auto e : {planner::PatchEncoding::RunLength, planner::PatchEncoding::ZstdRunLength}) {
    planner::OccupancyGrid back(3, 2);
    decode_map(encode_map(g, e), e, back);
    EXPECT_EQ(back.at(Cell{1, 1}), CellState::Occupied);
    planner::OccupancyGrid wrong(4, 4);
    EXPECT_THROW(decode_map(encode_map(g, e), e, wrong), std::runtime_error);
  }
}

}  // namespace
}  // namespace swarm::app
