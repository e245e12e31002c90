#include "swarm/gcs/fused_map.hpp"

#include <gtest/gtest.h>

namespace swarm::gcs {
namespace {

using planner::CellState;

constexpr CellState F = CellState::Free;
constexpr CellState O = CellState::Occupied;

TEST(FusedMap, MappedFractionIsKnownCellsOverAllCells) {
  FusedMap m(4, 2, 0.2, 2);
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 0.0);
  m.fuse(0, {{0, F}, {1, F}, {6, O}});
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 3.0 / 8.0);
  // Cells fused again, by the same or another group, count once; a later state replaces the
  // earlier one.
  m.fuse(1, {{0, F}, {6, O}, {1, O}});
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 3.0 / 8.0);
  EXPECT_EQ(m.grid().at(1), O);
  m.fuse(1, {{2, F}, {3, F}, {4, O}, {5, F}, {7, F}});
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 1.0);
}

TEST(FusedMap, HeardFromEveryGroupOnceEachGroupSentAPatchEvenAnEmptyOne) {
  FusedMap m(4, 1, 0.2, 3);
  EXPECT_FALSE(m.heard_from_every_group());
  m.fuse(0, {{0, F}});
  m.fuse(0, {{1, F}});  // the same group again does not count twice
  m.fuse(2, {});
  m.fuse(3, {{2, F}});   // not a group of this mission: fused, but not counted
  m.fuse(-1, {{3, O}});
  EXPECT_FALSE(m.heard_from_every_group());
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 1.0);
  m.fuse(1, {});
  EXPECT_TRUE(m.heard_from_every_group());
}

}  // namespace
}  // namespace swarm::gcs
