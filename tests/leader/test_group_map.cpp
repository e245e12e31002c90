#include "swarm/leader/group_map.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::leader {
namespace {

using planner::Cell;
using planner::CellChange;
using planner::CellState;
using planner::OccupancyGrid;
using swarm::test::grid_from;

constexpr CellState F = CellState::Free;
constexpr CellState O = CellState::Occupied;
constexpr CellState U = CellState::Unknown;

TEST(GroupMap, StartsUnknownWithTheGivenSize) {
  const GroupMap m(4, 2, 0.25);
  EXPECT_EQ(m.group().width(), 4);
  EXPECT_EQ(m.group().height(), 2);
  EXPECT_EQ(m.global().width(), 4);
  EXPECT_DOUBLE_EQ(m.group().resolution(), 0.25);
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(m.group().at(i), U);
    EXPECT_EQ(m.global().at(i), U);
  }
}

TEST(GroupMap, ObserveReturnsOnlyTheCellsNewToTheGroupMap) {
  GroupMap m(4, 2, 0.2);
  // Everything is new at first.
  const std::vector<CellChange> first = {{0, F}, {1, O}, {5, F}};
  EXPECT_EQ(m.observe(first), first);
  // A second robot saw 0 and 1 too, and 2 for the first time: only 2 is news.
  EXPECT_EQ(m.observe({{0, F}, {2, F}, {1, O}}), (std::vector<CellChange>{{2, F}}));
  // The same cell twice in one patch is news once.
  EXPECT_EQ(m.observe({{7, O}, {7, O}}), (std::vector<CellChange>{{7, O}}));
  EXPECT_TRUE(m.observe(first).empty());
  // Observations do not touch the global map.
  for (int i = 0; i < 8; ++i) EXPECT_EQ(m.global().at(i), U) << i;
  EXPECT_EQ(m.group().at(Cell{1, 1}), F);  // index 5
  EXPECT_EQ(m.group().at(Cell{3, 1}), O);  // index 7
  EXPECT_EQ(m.group().at(Cell{3, 0}), U);
}

TEST(GroupMap, AdoptGlobalFillsOnlyUnknownCellsAndReturnsExactlyThem) {
  GroupMap m(4, 2, 0.2);
  m.observe({{0, F}, {1, F}, {4, O}});
  // The global map (rows top first; index = y * 4 + x):
  //   y = 1: indices 4..7 = O F ? O
  //   y = 0: indices 0..3 = F F O ?
  const OccupancyGrid global = grid_from({
      "#.?#",  // y = 1
      "..#?",  // y = 0
  });
  // Known to the group already: 0, 1, 4. Unknown in the global map: 3, 6. New: 2 (O), 5 (F), 7 (O).
  const std::vector<CellChange> fresh = m.adopt_global(global);
  EXPECT_EQ(fresh, (std::vector<CellChange>{{2, O}, {5, F}, {7, O}}));
  EXPECT_EQ(m.global(), global);
  EXPECT_EQ(m.group().at(3), U);
  EXPECT_EQ(m.group().at(6), U);

  // The next global map knows 3 as well: only 3 is returned, the cells adopted before are not.
  OccupancyGrid newer = global;
  newer.set(3, F);
  EXPECT_EQ(m.adopt_global(newer), (std::vector<CellChange>{{3, F}}));
  EXPECT_EQ(m.global(), newer);
  EXPECT_TRUE(m.adopt_global(newer).empty());
  // Nor are cells known from the global map news when a robot observes them.
  EXPECT_EQ(m.observe({{5, F}, {6, F}}), (std::vector<CellChange>{{6, F}}));
}

TEST(GroupMap, GroupMapIsTheGlobalMapUnionTheGroupsObservations) {
  // A 5 x 3 world. The stale global map knows the left part, the group has seen the middle.
  const OccupancyGrid global = grid_from({
      "##???",  // y = 2
      "..???",  // y = 1
      "##???",  // y = 0
  });
  const OccupancyGrid seen = grid_from({
      "?###?",  // y = 2
      "?...?",  // y = 1
      "?###?",  // y = 0
  });
  std::vector<CellChange> observed;
  for (int i = 0; i < static_cast<int>(seen.size()); ++i) {
    if (seen.at(i) != U) observed.push_back({i, seen.at(i)});
  }
  const OccupancyGrid expected = grid_from({
      "####?",  // y = 2
      "....?",  // y = 1
      "####?",  // y = 0
  });
  // The order of the two sources does not matter (the world is static: they agree where both know).
  GroupMap observe_first(5, 3, 0.2);
  EXPECT_EQ(observe_first.observe(observed).size(), 9u);  // 3 rows x columns 1..3
  // From the global map only column 0 is new: (0,0) O, (0,1) F, (0,2) O.
  EXPECT_EQ(observe_first.adopt_global(global),
            (std::vector<CellChange>{{0, O}, {5, F}, {10, O}}));
  EXPECT_EQ(observe_first.group(), expected);

  GroupMap adopt_first(5, 3, 0.2);
  EXPECT_EQ(adopt_first.adopt_global(global).size(), 6u);  // columns 0 and 1
  // Observed cells in column 1 are known already: only columns 2 and 3 are news (6 cells).
  EXPECT_EQ(adopt_first.observe(observed).size(), 6u);
  EXPECT_EQ(adopt_first.group(), expected);
  EXPECT_EQ(adopt_first.global(), global);
}

}  // namespace
}  // namespace swarm::leader
