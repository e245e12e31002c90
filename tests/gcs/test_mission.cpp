#include "swarm/gcs/mission.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::gcs {
namespace {

using planner::Cell;
using planner::CellChange;
using planner::CellState;
using planner::OccupancyGrid;

constexpr CellState F = CellState::Free;
constexpr CellState O = CellState::Occupied;

// Every known cell of `g` as a patch.
std::vector<CellChange> known_cells(const OccupancyGrid& g) {
  std::vector<CellChange> out;
  for (int i = 0; i < static_cast<int>(g.size()); ++i) {
    if (g.at(i) != CellState::Unknown) out.push_back({i, g.at(i)});
  }
  return out;
}

TEST(Mission, RoundOneStartsOnlyOnceEveryGroupsPatchHasArrived) {
  Mission m(6, 1, 0.2, {.groups = 2, .replan_threshold = 20, .map_delay_rounds = 1});
  const std::vector<Cell> robots = {{0, 0}};
  EXPECT_FALSE(m.tick(0, robots).start_round);  // nothing from anyone
  m.fuse(0, {{0, F}});
  m.fuse(7, {{1, F}});  // not a group of this mission: does not count
  EXPECT_FALSE(m.tick(1, robots).start_round);
  EXPECT_EQ(m.round(), 0u);
  m.fuse(1, {});  // group 1's first patch, even an empty one
  const Mission::Decision d = m.tick(2, robots);
  ASSERT_TRUE(d.start_round);
  EXPECT_EQ(*d.start_round, 1u);
  EXPECT_FALSE(d.complete);
  ASSERT_NE(d.map, nullptr);
  EXPECT_EQ(d.map_tick, 2u);
  EXPECT_EQ(m.round(), 1u);
  EXPECT_EQ(m.round_ticks(), (std::vector<std::uint32_t>{2}));
}

TEST(Mission, ARoundEndsWhenAllGroupsArrivedOrAtTheThresholdTick) {
  Mission m(6, 1, 0.2, {.groups = 2, .replan_threshold = 5, .map_delay_rounds = 1});
  // (1, 0) is a reachable frontier (Unknown (2, 0) next to it): the mission is never complete.
  const std::vector<Cell> robots = {{0, 0}};
  m.fuse(0, {{0, F}});
  m.fuse(1, {{1, F}});
  ASSERT_EQ(m.tick(3, robots).start_round, std::optional<std::uint32_t>(1));
  // Threshold: round 1 started at 3, so round 2 starts at 3 + 5 = 8, not before.
  for (std::uint32_t k = 4; k < 8; ++k) EXPECT_FALSE(m.tick(k, robots).start_round) << k;
  ASSERT_EQ(m.tick(8, robots).start_round, std::optional<std::uint32_t>(2));
  EXPECT_EQ(m.frontier_cells(), 1u);
  // All groups arrived: the next tick starts round 3. A report for an old round does not count.
  m.group_arrived(0, 2);
  EXPECT_FALSE(m.tick(9, robots).start_round);
  m.group_arrived(1, 1);
  EXPECT_FALSE(m.tick(10, robots).start_round);
  m.group_arrived(1, 2);
  ASSERT_EQ(m.tick(11, robots).start_round, std::optional<std::uint32_t>(3));
  // Arrivals are per round: round 4 needs new ones, or the threshold 11 + 5 = 16.
  m.group_arrived(0, 4);  // a round that has not started yet: ignored
  for (std::uint32_t k = 12; k < 16; ++k) EXPECT_FALSE(m.tick(k, robots).start_round) << k;
  ASSERT_EQ(m.tick(16, robots).start_round, std::optional<std::uint32_t>(4));
  EXPECT_FALSE(m.tick(17, robots).start_round);
  EXPECT_EQ(m.round_ticks(), (std::vector<std::uint32_t>{3, 8, 11, 16}));
  EXPECT_EQ(m.round(), 4u);
}

TEST(Mission, WithDelayOneRoundRGetsTheMapFusedAtTheStartOfRoundRMinusOne) {
  Mission m(4, 1, 0.2, {.groups = 1, .replan_threshold = 2, .map_delay_rounds = 1});
  const std::vector<Cell> robots = {{0, 0}};
  OccupancyGrid at_round1(4, 1);
  at_round1.set(0, F);
  OccupancyGrid at_round2 = at_round1;
  at_round2.set(1, F);

  m.fuse(0, {{0, F}});
  Mission::Decision d = m.tick(0, robots);
  // Round 1 has no earlier round: it gets the map fused now (tick 0).
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(1));
  ASSERT_NE(d.map, nullptr);
  EXPECT_EQ(d.map_tick, 0u);
  EXPECT_EQ(*d.map, at_round1);

  m.fuse(0, {{1, F}});
  EXPECT_FALSE(m.tick(1, robots).start_round);
  d = m.tick(2, robots);  // threshold: 2 - 0 >= 2
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(2));
  EXPECT_EQ(d.map_tick, 0u);       // the snapshot of round 1's start, not the current map
  EXPECT_EQ(*d.map, at_round1);    // cell 1 (fused at tick 1) is not in it
  EXPECT_EQ(m.fused(), at_round2);

  m.fuse(0, {{2, F}});
  EXPECT_FALSE(m.tick(3, robots).start_round);
  d = m.tick(4, robots);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(3));
  EXPECT_EQ(d.map_tick, 2u);  // round 2 started at tick 2
  EXPECT_EQ(*d.map, at_round2);
}

TEST(Mission, WithDelayZeroEveryRoundGetsTheCurrentMap) {
  Mission m(4, 1, 0.2, {.groups = 1, .replan_threshold = 2, .map_delay_rounds = 0});
  const std::vector<Cell> robots = {{0, 0}};
  m.fuse(0, {{0, F}});
  Mission::Decision d = m.tick(5, robots);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(1));
  EXPECT_EQ(d.map_tick, 5u);
  EXPECT_EQ(*d.map, m.fused());
  m.fuse(0, {{1, F}, {3, O}});
  d = m.tick(7, robots);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(2));
  EXPECT_EQ(d.map_tick, 7u);
  EXPECT_EQ(*d.map, m.fused());
  EXPECT_EQ(d.map->at(3), O);
}

TEST(Mission, WithDelayTwoTheFirstRoundsShareRoundOnesMap) {
  // (4, 0) stays Unknown, so a frontier is always left and rounds go on.
  Mission m(5, 1, 0.2, {.groups = 1, .replan_threshold = 1, .map_delay_rounds = 2});
  const std::vector<Cell> robots = {{0, 0}};
  // Rounds start at ticks 0, 1, 2, 3; cell k is fused just before tick k.
  // use = round - 2 when round > 2, else 1: rounds 1, 2, 3 -> snapshot 1 (tick 0), 4 -> 2 (tick 1).
  const std::uint32_t expect_tick[] = {0, 0, 0, 1};
  for (std::uint32_t k = 0; k < 4; ++k) {
    m.fuse(0, {{static_cast<int>(k), F}});
    const Mission::Decision d = m.tick(k, robots);
    ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(k + 1)) << k;
    EXPECT_EQ(d.map_tick, expect_tick[k]) << k;
    int known = 0;
    for (int i = 0; i < 5; ++i) known += d.map->at(i) != CellState::Unknown;
    EXPECT_EQ(known, static_cast<int>(expect_tick[k]) + 1) << k;
  }
}

TEST(Mission, CompleteOnlyAfterRoundOneAndWhenNoReachableFrontierIsLeft) {
  // Everything known except (4, 0); its frontier (3, 0) lies behind the wall (2, 0).
  const OccupancyGrid world = swarm::test::grid_from({"..#.?"});
  Mission m(5, 1, 0.2, {.groups = 1, .replan_threshold = 20, .map_delay_rounds = 1});
  m.fuse(0, known_cells(world));
  // Round 0: never complete, even with nothing left to explore from (0, 0).
  Mission::Decision d = m.tick(0, {{0, 0}});
  EXPECT_FALSE(d.complete);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(1));
  // A robot at (3, 0) can reach the frontier (3, 0): not complete.
  d = m.tick(1, {{3, 0}});
  EXPECT_FALSE(d.complete);
  EXPECT_EQ(m.frontier_cells(), 1u);
  // From (0, 0) and (1, 0) it is unreachable: complete, and no new round even though the group
  // has arrived.
  m.group_arrived(0, 1);
  d = m.tick(2, {{0, 0}, {1, 0}});
  EXPECT_TRUE(d.complete);
  EXPECT_EQ(m.frontier_cells(), 0u);
  EXPECT_FALSE(d.start_round);
  EXPECT_EQ(d.map, nullptr);
  EXPECT_EQ(m.round(), 1u);
}

TEST(Mission, AFullyKnownMapCompletesTheTickAfterRoundOne) {
  Mission m(3, 2, 0.2, {.groups = 1, .replan_threshold = 20, .map_delay_rounds = 1});
  m.fuse(0, known_cells(OccupancyGrid(3, 2, 0.2, 0.0, 0.0, F)));
  const Mission::Decision first = m.tick(0, {{0, 0}});
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.start_round, std::optional<std::uint32_t>(1));
  const Mission::Decision second = m.tick(1, {{0, 0}});
  EXPECT_TRUE(second.complete);
  EXPECT_FALSE(second.start_round);
}

TEST(Mission, MappedFractionIsKnownCellsOverAllCells) {
  Mission m(4, 2, 0.2, {.groups = 2});
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 0.0);
  m.fuse(0, {{0, F}, {1, F}, {6, O}});
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 3.0 / 8.0);
  // Cells fused again, by the same or another group, count once; a later state replaces the
  // earlier one.
  m.fuse(1, {{0, F}, {6, O}, {1, O}});
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 3.0 / 8.0);
  EXPECT_EQ(m.fused().at(1), O);
  m.fuse(1, {{2, F}, {3, F}, {4, O}, {5, F}, {7, F}});
  EXPECT_DOUBLE_EQ(m.mapped_fraction(), 1.0);
}

}  // namespace
}  // namespace swarm::gcs
