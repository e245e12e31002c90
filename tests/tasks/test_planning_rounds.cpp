#include "swarm/tasks/explore/planning_rounds.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::tasks {
namespace {

using planner::Cell;
using planner::CellChange;
using planner::CellState;
using planner::OccupancyGrid;
using gcs::FusedMap;

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

TEST(PlanningRounds, RoundOneStartsOnlyOnceEveryGroupsPatchHasArrived) {
  FusedMap f(6, 1, 0.2, 2);
  PlanningRounds m({.groups = 2, .start_cells = {}, .replan_threshold = 20, .map_delay_rounds = 1});
  const std::vector<Cell> robots = {{0, 0}};
  EXPECT_FALSE(m.tick(0, f, robots).start_round);  // nothing from anyone
  f.fuse(0, {{0, F}});
  f.fuse(7, {{1, F}});  // not a group of this mission: does not count
  EXPECT_FALSE(m.tick(1, f, robots).start_round);
  EXPECT_EQ(m.round(), 0u);
  f.fuse(1, {});  // group 1's first patch, even an empty one
  const PlanningRounds::Decision d = m.tick(2, f, robots);
  ASSERT_TRUE(d.start_round);
  EXPECT_EQ(*d.start_round, 1u);
  EXPECT_FALSE(d.complete);
  ASSERT_NE(d.map, nullptr);
  EXPECT_EQ(d.map_tick, 2u);
  EXPECT_EQ(m.round(), 1u);
  EXPECT_EQ(m.round_ticks(), (std::vector<std::uint32_t>{2}));
}

TEST(PlanningRounds, ARoundEndsWhenAllGroupsArrivedOrAtTheThresholdTick) {
  FusedMap f(6, 1, 0.2, 2);
  PlanningRounds m({.groups = 2, .start_cells = {}, .replan_threshold = 5, .map_delay_rounds = 1});
  // (1, 0) is a reachable frontier (Unknown (2, 0) next to it): the mission is never complete.
  const std::vector<Cell> robots = {{0, 0}};
  f.fuse(0, {{0, F}});
  f.fuse(1, {{1, F}});
  ASSERT_EQ(m.tick(3, f, robots).start_round, std::optional<std::uint32_t>(1));
  // Threshold: round 1 started at 3, so round 2 starts at 3 + 5 = 8, not before.
  for (std::uint32_t k = 4; k < 8; ++k) EXPECT_FALSE(m.tick(k, f, robots).start_round) << k;
  ASSERT_EQ(m.tick(8, f, robots).start_round, std::optional<std::uint32_t>(2));
  EXPECT_EQ(m.frontier_cells(), 1u);
  // All groups arrived: the next tick starts round 3. A report for an old round does not count.
  m.group_arrived(0, 2);
  EXPECT_FALSE(m.tick(9, f, robots).start_round);
  m.group_arrived(1, 1);
  EXPECT_FALSE(m.tick(10, f, robots).start_round);
  m.group_arrived(1, 2);
  ASSERT_EQ(m.tick(11, f, robots).start_round, std::optional<std::uint32_t>(3));
  // Arrivals are per round: round 4 needs new ones, or the threshold 11 + 5 = 16.
  m.group_arrived(0, 4);  // a round that has not started yet: ignored
  for (std::uint32_t k = 12; k < 16; ++k) EXPECT_FALSE(m.tick(k, f, robots).start_round) << k;
  ASSERT_EQ(m.tick(16, f, robots).start_round, std::optional<std::uint32_t>(4));
  EXPECT_FALSE(m.tick(17, f, robots).start_round);
  EXPECT_EQ(m.round_ticks(), (std::vector<std::uint32_t>{3, 8, 11, 16}));
  EXPECT_EQ(m.round(), 4u);
}

TEST(PlanningRounds, WithDelayOneRoundRGetsTheMapFusedAtTheStartOfRoundRMinusOne) {
  FusedMap f(4, 1, 0.2, 1);
  PlanningRounds m({.groups = 1, .start_cells = {}, .replan_threshold = 2, .map_delay_rounds = 1});
  const std::vector<Cell> robots = {{0, 0}};
  OccupancyGrid at_round1(4, 1);
  at_round1.set(0, F);
  OccupancyGrid at_round2 = at_round1;
  at_round2.set(1, F);

  f.fuse(0, {{0, F}});
  PlanningRounds::Decision d = m.tick(0, f, robots);
  // Round 1 has no earlier round: it gets the map fused now (tick 0).
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(1));
  ASSERT_NE(d.map, nullptr);
  EXPECT_EQ(d.map_tick, 0u);
  EXPECT_EQ(*d.map, at_round1);

  f.fuse(0, {{1, F}});
  EXPECT_FALSE(m.tick(1, f, robots).start_round);
  d = m.tick(2, f, robots);  // threshold: 2 - 0 >= 2
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(2));
  EXPECT_EQ(d.map_tick, 0u);       // the snapshot of round 1's start, not the current map
  EXPECT_EQ(*d.map, at_round1);    // cell 1 (fused at tick 1) is not in it
  EXPECT_EQ(f.grid(), at_round2);

  f.fuse(0, {{2, F}});
  EXPECT_FALSE(m.tick(3, f, robots).start_round);
  d = m.tick(4, f, robots);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(3));
  EXPECT_EQ(d.map_tick, 2u);  // round 2 started at tick 2
  EXPECT_EQ(*d.map, at_round2);
}

TEST(PlanningRounds, WithDelayZeroEveryRoundGetsTheCurrentMap) {
  FusedMap f(4, 1, 0.2, 1);
  PlanningRounds m({.groups = 1, .start_cells = {}, .replan_threshold = 2, .map_delay_rounds = 0});
  const std::vector<Cell> robots = {{0, 0}};
  f.fuse(0, {{0, F}});
  PlanningRounds::Decision d = m.tick(5, f, robots);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(1));
  EXPECT_EQ(d.map_tick, 5u);
  EXPECT_EQ(*d.map, f.grid());
  f.fuse(0, {{1, F}, {3, O}});
  d = m.tick(7, f, robots);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(2));
  EXPECT_EQ(d.map_tick, 7u);
  EXPECT_EQ(*d.map, f.grid());
  EXPECT_EQ(d.map->at(3), O);
}

TEST(PlanningRounds, WithDelayTwoTheFirstRoundsShareRoundOnesMap) {
  // (4, 0) stays Unknown, so a frontier is always left and rounds go on.
  FusedMap f(5, 1, 0.2, 1);
  PlanningRounds m({.groups = 1, .start_cells = {}, .replan_threshold = 1, .map_delay_rounds = 2});
  const std::vector<Cell> robots = {{0, 0}};
  // Rounds start at ticks 0, 1, 2, 3; cell k is fused just before tick k.
  // use = round - 2 when round > 2, else 1: rounds 1, 2, 3 -> snapshot 1 (tick 0), 4 -> 2 (tick 1).
  const std::uint32_t expect_tick[] = {0, 0, 0, 1};
  for (std::uint32_t k = 0; k < 4; ++k) {
    f.fuse(0, {{static_cast<int>(k), F}});
    const PlanningRounds::Decision d = m.tick(k, f, robots);
    ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(k + 1)) << k;
    EXPECT_EQ(d.map_tick, expect_tick[k]) << k;
    int known = 0;
    for (int i = 0; i < 5; ++i) known += d.map->at(i) != CellState::Unknown;
    EXPECT_EQ(known, static_cast<int>(expect_tick[k]) + 1) << k;
  }
}

TEST(PlanningRounds, CompleteOnlyAfterRoundOneAndWhenNoReachableFrontierIsLeft) {
  // Everything known except (4, 0); its frontier (3, 0) lies behind the wall (2, 0).
  const OccupancyGrid world = swarm::test::grid_from({"..#.?"});
  FusedMap f(5, 1, 0.2, 1);
  PlanningRounds m({.groups = 1, .start_cells = {}, .replan_threshold = 20, .map_delay_rounds = 1});
  f.fuse(0, known_cells(world));
  // Round 0: never complete, even with nothing left to explore from (0, 0).
  PlanningRounds::Decision d = m.tick(0, f, {{0, 0}});
  EXPECT_FALSE(d.complete);
  ASSERT_EQ(d.start_round, std::optional<std::uint32_t>(1));
  // A robot at (3, 0) can reach the frontier (3, 0): not complete.
  d = m.tick(1, f, {{3, 0}});
  EXPECT_FALSE(d.complete);
  EXPECT_EQ(m.frontier_cells(), 1u);
  // From (0, 0) and (1, 0) it is unreachable: complete, and no new round even though the group
  // has arrived.
  m.group_arrived(0, 1);
  d = m.tick(2, f, {{0, 0}, {1, 0}});
  EXPECT_TRUE(d.complete);
  EXPECT_EQ(m.frontier_cells(), 0u);
  EXPECT_FALSE(d.start_round);
  EXPECT_EQ(d.map, nullptr);
  EXPECT_EQ(m.round(), 1u);
}

TEST(PlanningRounds, AFullyKnownMapCompletesTheTickAfterRoundOne) {
  FusedMap f(3, 2, 0.2, 1);
  PlanningRounds m({.groups = 1, .start_cells = {}, .replan_threshold = 20, .map_delay_rounds = 1});
  f.fuse(0, known_cells(OccupancyGrid(3, 2, 0.2, 0.0, 0.0, F)));
  const PlanningRounds::Decision first = m.tick(0, f, {{0, 0}});
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.start_round, std::optional<std::uint32_t>(1));
  const PlanningRounds::Decision second = m.tick(1, f, {{0, 0}});
  EXPECT_TRUE(second.complete);
  EXPECT_FALSE(second.start_round);
}

}  // namespace
}  // namespace swarm::tasks
