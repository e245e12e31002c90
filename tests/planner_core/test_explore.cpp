#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/big_explore_world.hpp"
#include "swarm/planner/explore/explore.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "swarm/planner/explore/frontier.hpp"

namespace swarm::planner {
namespace {

// Maps drawn in ASCII (swarm_test/ascii_grid.hpp): '#' Occupied, '.' Free, '?' Unknown; any
// other character is a Free cell remembered under that character (robots). First line = top row.
using swarm::test::AsciiMap;
using swarm::test::ascii_map;

std::set<Cell> as_set(const std::vector<Cell>& v) { return {v.begin(), v.end()}; }

bool contains(const std::vector<Cell>& v, Cell c) {
  return std::find(v.begin(), v.end(), c) != v.end();
}

void expect_same_plan(const ExplorePlan& a, const ExplorePlan& b) {
  EXPECT_EQ(a.plan_case, b.plan_case);
  EXPECT_EQ(a.waypoints, b.waypoints);
  EXPECT_EQ(a.group_frontiers, b.group_frontiers);
  EXPECT_EQ(a.group_segments, b.group_segments);
  EXPECT_EQ(a.global_segments, b.global_segments);
  EXPECT_EQ(a.chosen_segment, b.chosen_segment);
  EXPECT_EQ(a.member_segment, b.member_segment);
  EXPECT_EQ(a.group_to_segment, b.group_to_segment);
}

// ------------------------------------------------------------------------------------------------
// Group frontiers

// Stale global map: the group's room is known up to x = 3; everything right of it is unknown.
const std::vector<std::string> kRoomGlobal = {
    "##########",  // y=5
    "#...?????#",  // y=4
    "#.L.?????#",  // y=3
    "#...?????#",  // y=2
    "#...?????#",  // y=1
    "##########",  // y=0
};
// Since the fusion the group has seen x = 4..5 in the two upper rows only.
const std::vector<std::string> kRoomGroup = {
    "##########",  // y=5
    "#.....???#",  // y=4
    "#.L...???#",  // y=3
    "#...?????#",  // y=2
    "#...?????#",  // y=1
    "##########",  // y=0
};

TEST(Explore, GroupFrontiersAreLocalFrontiersThatAreNotGlobalOnes) {
  const AsciiMap global = ascii_map(kRoomGlobal);
  const AsciiMap group = ascii_map(kRoomGroup);
  // Global frontiers: x = 3, y = 1..4 (Free, unknown to the right).
  EXPECT_EQ(as_set(reachable_frontiers(global.grid, {global.at.at('L')})),
            (std::set<Cell>{{3, 1}, {3, 2}, {3, 3}, {3, 4}}));
  // Local frontiers: (3,1), (3,2) still border unknown at x = 4; (3,3), (3,4) no longer do;
  // (4,3) borders unknown (4,2) below; (5,3), (5,4) border unknown x = 6; (4,4) borders nothing.
  ExploreInput in;
  in.global_map = &global.grid;
  in.group_map = &group.grid;
  in.leader_positions = {global.at.at('L')};
  in.member_positions = {group.at.at('L')};
  const ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
  // Group frontiers = {(3,1),(3,2),(4,3),(5,3),(5,4)} minus {(3,1),(3,2),(3,3),(3,4)}, row-major.
  EXPECT_EQ(plan.group_frontiers, (std::vector<Cell>{{4, 3}, {5, 3}, {5, 4}}));
  EXPECT_EQ(plan.plan_case, PlanCase::GroupFrontier);
  ASSERT_EQ(plan.group_segments.size(), 1u);  // the three cells are 8-connected
  EXPECT_EQ(plan.chosen_segment, 0);
  ASSERT_EQ(plan.waypoints.size(), 1u);
  // K-Means k = 1: centroid (14/3, 10/3) = (4.67, 3.33); nearest cell (5,3) (0.47 vs 0.75, 0.75).
  EXPECT_EQ(plan.waypoints[0], Cell({5, 3}));
}

TEST(Explore, BaselineIgnoresGroupFrontiersAndPrefersStillOpenGlobalCells) {
  const AsciiMap global = ascii_map(kRoomGlobal);
  const AsciiMap group = ascii_map(kRoomGroup);
  ExploreInput in;
  in.global_map = &global.grid;
  in.group_map = &group.grid;
  in.leader_positions = {global.at.at('L')};
  in.member_positions = {group.at.at('L')};
  ExploreConfig baseline;
  baseline.use_group_frontiers = false;
  const ExplorePlan plan = plan_group_exploration(in, baseline);
  EXPECT_EQ(plan.plan_case, PlanCase::GlobalAssignment);
  EXPECT_TRUE(plan.group_frontiers.empty());
  ASSERT_EQ(plan.global_segments.size(), 1u);
  EXPECT_EQ(plan.global_segments[0], (std::vector<Cell>{{3, 1}, {3, 2}, {3, 3}, {3, 4}}));
  EXPECT_EQ(plan.chosen_segment, 0);
  EXPECT_EQ(plan.group_to_segment, (std::vector<int>{0}));
  // Of the stale segment only (3,1) and (3,2) are still frontiers in the group map; centroid
  // (3, 1.5) is equidistant from both, the first one in row-major order wins.
  EXPECT_EQ(plan.waypoints[0], Cell({3, 1}));
}

// ------------------------------------------------------------------------------------------------
// Case A

// One room, leader L at (6,3). Openings: right wall x = 14, y = 1..4 -> frontier (13,1..4), W = 4;
// top wall (1,6) -> frontier (1,5), W = 1; top wall (7,6) -> frontier (7,5), W = 1.
// Segments in row-major order of their first cell: 0 = right, 1 = (1,5), 2 = (7,5).
const std::vector<std::string> kCaseA = {
    "#?#####?#######",  // y=6
    "#.............#",  // y=5
    "#..A....B.....?",  // y=4
    "#.....L.......?",  // y=3
    "#.............?",  // y=2
    "#.............?",  // y=1
    "###############",  // y=0
};

struct CaseAFixture {
  AsciiMap group = ascii_map(kCaseA);
  OccupancyGrid global{group.grid.width(), group.grid.height()};  // round 0: nothing fused yet
  ExploreInput input(std::vector<Cell> members) {
    ExploreInput in;
    in.global_map = &global;
    in.group_map = &group.grid;
    in.leader_positions = {group.at.at('L')};
    in.member_positions = std::move(members);
    return in;
  }
};

TEST(Explore, CaseAPicksTheSegmentWithTheLeastDistancePerCell) {
  CaseAFixture f;
  const ExplorePlan plan = plan_group_exploration(f.input({f.group.at.at('L')}), ExploreConfig{});
  ASSERT_EQ(plan.plan_case, PlanCase::GroupFrontier);
  ASSERT_EQ(plan.group_segments.size(), 3u);
  EXPECT_EQ(plan.group_segments[0], (std::vector<Cell>{{13, 1}, {13, 2}, {13, 3}, {13, 4}}));
  EXPECT_EQ(plan.group_segments[1], (std::vector<Cell>{{1, 5}}));
  EXPECT_EQ(plan.group_segments[2], (std::vector<Cell>{{7, 5}}));
  // D/W from L (6,3):  right: D = |(13,3) - (6,3)| = 7,         W = 4 -> 1.75   <- least
  //                    (1,5):  D = sqrt(5^2 + 2^2) = 5.385,   W = 1 -> 5.385
  //                    (7,5):  D = sqrt(1^2 + 2^2) = 2.236,   W = 1 -> 2.236
  // The nearest segment is (7,5), but the right one gives more cells per distance.
  EXPECT_EQ(plan.chosen_segment, 0);
  // A lone leader: no one to send to small segments. K-Means k = 1 -> centroid (13, 2.5);
  // (13,2) and (13,3) tie at 0.5, the first in the segment wins.
  EXPECT_EQ(plan.waypoints, (std::vector<std::optional<Cell>>{Cell{13, 2}}));
  EXPECT_EQ(plan.member_segment, (std::vector<int>{0}));
}

// dbscan_min_points 3: the right column stays a cluster ((13,2) and (13,3) have 3 points within
// eps 1.5), the two lone cells are DBSCAN noise. They are still unexplored space, so each is a
// segment of its own, after the clusters (dropped, they were never visited and the mission never
// completed).
TEST(Explore, DbscanNoiseCellsAreSegmentsOfTheirOwn) {
  CaseAFixture f;
  ExploreConfig config;
  config.dbscan_min_points = 3;
  const ExplorePlan plan = plan_group_exploration(f.input({f.group.at.at('L')}), config);
  ASSERT_EQ(plan.plan_case, PlanCase::GroupFrontier);
  ASSERT_EQ(plan.group_segments.size(), 3u);
  EXPECT_EQ(plan.group_segments[0], (std::vector<Cell>{{13, 1}, {13, 2}, {13, 3}, {13, 4}}));
  EXPECT_EQ(plan.group_segments[1], (std::vector<Cell>{{1, 5}}));
  EXPECT_EQ(plan.group_segments[2], (std::vector<Cell>{{7, 5}}));
  EXPECT_EQ(plan.chosen_segment, 0);  // D/W 1.75 against 5.385 and 2.236, as with min_points 1
}

TEST(Explore, SmallSegmentRuleSendsExactlyOneMemberToTheNearCornerSegment) {
  CaseAFixture f;
  const Cell l = f.group.at.at('L'), a = f.group.at.at('A'), b = f.group.at.at('B');
  ExploreConfig cfg;
  cfg.small_segment_radius_cells = 3;  // only (7,5) (D = 2.236) is near enough; (1,5) is 5.385
  const ExplorePlan plan = plan_group_exploration(f.input({l, a, b}), cfg);
  ASSERT_EQ(plan.plan_case, PlanCase::GroupFrontier);
  EXPECT_EQ(plan.chosen_segment, 0);
  // Hungarian over members A (3,4), B (8,4) for segment (7,5): A 4.123, B 1.414 -> B.
  EXPECT_EQ(plan.member_segment, (std::vector<int>{0, 0, 2}));
  EXPECT_EQ(plan.waypoints[2], Cell({7, 5}));
  // The leader and A share the right segment on two different cells.
  ASSERT_TRUE(plan.waypoints[0] && plan.waypoints[1]);
  EXPECT_TRUE(contains(plan.group_segments[0], *plan.waypoints[0]));
  EXPECT_TRUE(contains(plan.group_segments[0], *plan.waypoints[1]));
  EXPECT_NE(*plan.waypoints[0], *plan.waypoints[1]);
}

TEST(Explore, SmallSegmentsTakeAtMostTheNonLeaderMembersNearestFirst) {
  CaseAFixture f;
  const Cell l = f.group.at.at('L'), a = f.group.at.at('A'), b = f.group.at.at('B');
  // Default radius 15: both small segments qualify, and there are two non-leader members.
  // Hungarian, rows A, B; columns (7,5), (1,5) (nearest to L first):
  //   A: 4.123, 2.236     B: 1.414, 7.071   -> A->(1,5), B->(7,5): 3.650 < 4.123 + 7.071.
  const ExplorePlan three = plan_group_exploration(f.input({l, a, b}), ExploreConfig{});
  EXPECT_EQ(three.member_segment, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(three.waypoints,
            (std::vector<std::optional<Cell>>{Cell{13, 2}, Cell{1, 5}, Cell{7, 5}}));
  // Only one non-leader member: it takes the nearest small segment, (7,5), although A is
  // closer to (1,5); the leader always keeps the main segment.
  const ExplorePlan two = plan_group_exploration(f.input({l, a}), ExploreConfig{});
  EXPECT_EQ(two.member_segment, (std::vector<int>{0, 2}));
  EXPECT_EQ(two.waypoints, (std::vector<std::optional<Cell>>{Cell{13, 2}, Cell{7, 5}}));
}

TEST(Explore, MembersShareWaypointsWhenTheSegmentHasFewerCells) {
  // One group frontier cell (7,5) and three robots: all go there.
  const AsciiMap group = ascii_map({
      "#######?#######",
      "#.............#",
      "#..A....B.....#",
      "#.....L.......#",
      "###############",
  });
  OccupancyGrid global(group.grid.width(), group.grid.height());
  ExploreInput in;
  in.global_map = &global;
  in.group_map = &group.grid;
  in.leader_positions = {group.at.at('L')};
  in.member_positions = {group.at.at('L'), group.at.at('A'), group.at.at('B')};
  const ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
  EXPECT_EQ(plan.plan_case, PlanCase::GroupFrontier);
  EXPECT_EQ(plan.waypoints, std::vector<std::optional<Cell>>(3, Cell{7, 3}));
}

// ------------------------------------------------------------------------------------------------
// Case B

// A known room (x = 1..19, y = 1..9) with three openings, seen identically by every leader.
// Frontier segments, numbered by their first cell in row-major order:
//   0: right wall,  cells (19,2..5), W = 4
//   1: left wall,   cells (1,4..6),  W = 3
//   2: top wall,    cells (9,9), (10,9), W = 2
// Leaders: 0 at (15,8), 1 at (4,5), 2 at (18,3); a fourth, 3, at (17,4) in one test.
const std::vector<std::string> kCaseB = {
    "#########??##########",  // y=10
    "#...................#",  // y=9
    "#..............0....#",  // y=8
    "#...................#",  // y=7
    "?...................#",  // y=6
    "?...1...............?",  // y=5
    "?................3..?",  // y=4
    "#.................2.?",  // y=3
    "#...................?",  // y=2
    "#...................#",  // y=1
    "#####################",  // y=0
};

// Group g: its leader plus two members next to it (below and to the left).
std::vector<Cell> members_of(Cell leader) {
  return {leader, {leader.x, leader.y - 1}, {leader.x - 1, leader.y}};
}

TEST(Explore, CaseBMatchesTheHandSolvedHungarian) {
  const AsciiMap world = ascii_map(kCaseB);
  const std::vector<Cell> leaders = {world.at.at('0'), world.at.at('1'), world.at.at('2')};
  // C_ij = D_ij / W_j (D = Euclidean distance to the segment's nearest cell):
  //            seg 0 (W 4)         seg 1 (W 3)               seg 2 (W 2)
  //   L0 (15,8)  (19,5): 5 -> 1.25   (1,6): 14.142 -> 4.714   (10,9): 5.099 -> 2.550
  //   L1 (4,5)   (19,5): 15 -> 3.75  (1,5): 3 -> 1.000        (9,9): 6.403 -> 3.202
  //   L2 (18,3)  (19,3): 1 -> 0.25   (1,4): 17.029 -> 5.676   (10,9): 10 -> 5.000
  // All six assignments: (0,1,2) 1.25+1+5 = 7.25   (0,2,1) 1.25+3.202+5.676 = 10.13
  //   (1,0,2) 4.714+3.75+5 = 13.46   (1,2,0) 4.714+3.202+0.25 = 8.17
  //   (2,0,1) 2.55+3.75+5.676 = 11.98   (2,1,0) 2.55+1+0.25 = 3.80  <- optimum
  // Greedy by row (L0 takes its cheapest, seg 0) would be 7.25.
  for (int g = 0; g < 3; ++g) {
    ExploreInput in;
    in.global_map = &world.grid;
    in.group_map = &world.grid;  // nothing new since the fusion: no group frontiers
    in.leader_positions = leaders;
    in.group = g;
    in.member_positions = members_of(leaders[g]);
    const ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
    ASSERT_EQ(plan.plan_case, PlanCase::GlobalAssignment);
    EXPECT_TRUE(plan.group_frontiers.empty());
    ASSERT_EQ(plan.global_segments.size(), 3u);
    EXPECT_EQ(plan.global_segments[0], (std::vector<Cell>{{19, 2}, {19, 3}, {19, 4}, {19, 5}}));
    EXPECT_EQ(plan.global_segments[1], (std::vector<Cell>{{1, 4}, {1, 5}, {1, 6}}));
    EXPECT_EQ(plan.global_segments[2], (std::vector<Cell>{{9, 9}, {10, 9}}));
    EXPECT_EQ(plan.group_to_segment, (std::vector<int>{2, 1, 0}));
    EXPECT_EQ(plan.chosen_segment, plan.group_to_segment[g]);
    for (std::size_t m = 0; m < plan.waypoints.size(); ++m) {
      ASSERT_TRUE(plan.waypoints[m]);
      EXPECT_TRUE(contains(plan.global_segments[plan.chosen_segment], *plan.waypoints[m]));
      EXPECT_EQ(plan.member_segment[m], plan.chosen_segment);
    }
    if (g == 0) {
      // Three robots, two cells: K-Means gives (9,9) and (10,9); each is offered twice.
      // Distances to (10,9) / (9,9): (15,8) 5.099 / 6.083, (15,7) 5.385 / 6.325,
      // (14,8) 4.123 / 5.099. One robot must take (9,9); the cheapest extra is (15,7) (+0.940).
      EXPECT_EQ(plan.waypoints,
                (std::vector<std::optional<Cell>>{Cell{10, 9}, Cell{9, 9}, Cell{10, 9}}));
    }
  }
}

TEST(Explore, CaseBEveryLeaderGetsAConsistentAssignment) {
  // Same world as above with the leaders moved around: whatever the positions, all leaders
  // compute the same assignment and no two groups share a segment (3 segments >= 3 groups).
  const AsciiMap world = ascii_map(kCaseB);
  const std::vector<std::vector<Cell>> layouts = {
      {{2, 2}, {2, 3}, {3, 2}},     {{10, 5}, {11, 5}, {12, 5}}, {{18, 8}, {3, 8}, {10, 2}},
      {{15, 8}, {4, 5}, {18, 3}},   {{17, 4}, {18, 4}, {16, 4}}, {{5, 9}, {9, 8}, {18, 9}},
  };
  for (const auto& leaders : layouts) {
    std::vector<int> reference;
    std::set<int> taken;
    for (int g = 0; g < 3; ++g) {
      ExploreInput in;
      in.global_map = &world.grid;
      in.group_map = &world.grid;
      in.leader_positions = leaders;
      in.group = g;
      in.member_positions = {leaders[g]};
      in.round = 4;
      const ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
      ASSERT_EQ(plan.plan_case, PlanCase::GlobalAssignment);
      if (g == 0) reference = plan.group_to_segment;
      EXPECT_EQ(plan.group_to_segment, reference);
      EXPECT_TRUE(taken.insert(plan.chosen_segment).second)
          << "group " << g << " shares segment " << plan.chosen_segment;
    }
  }
}

TEST(Explore, CaseBGroupLeftWithoutASegmentTakesItsCheapest) {
  const AsciiMap world = ascii_map(kCaseB);
  // Four leaders, three segments. L3 (17,4): seg 0 (19,4) 2 -> 0.5, seg 1 (1,4) 16 -> 5.333,
  // seg 2 (10,9) 8.602 -> 4.301. Adding L3 to the optimum above costs at least
  // 0.5 + 1 + 2.55 = 4.05 > 3.80, so L3 is left out (-1) and shares seg 0, its cheapest.
  const std::vector<Cell> leaders = {world.at.at('0'), world.at.at('1'), world.at.at('2'),
                                     world.at.at('3')};
  ExploreInput in;
  in.global_map = &world.grid;
  in.group_map = &world.grid;
  in.leader_positions = leaders;
  in.group = 3;
  in.member_positions = {leaders[3]};
  const ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
  EXPECT_EQ(plan.group_to_segment, (std::vector<int>{2, 1, 0, -1}));
  EXPECT_EQ(plan.chosen_segment, 0);
  EXPECT_TRUE(contains(plan.global_segments[0], *plan.waypoints[0]));
}

// kCaseB as group 2 (leader '2' at (18,3)) sees it after looking through the right-wall opening:
// a wall behind it (x = 20, y = 2..5). Segment 0 is no longer a frontier in this group map, and
// the group found nothing new (no group frontiers), so it plans case B.
const std::vector<std::string> kCaseBRightExplored = {
    "#########??##########",  // y=10
    "#...................#",  // y=9
    "#..............0....#",  // y=8
    "#...................#",  // y=7
    "?...................#",  // y=6
    "?...1...............#",  // y=5
    "?...................#",  // y=4
    "#.................2.#",  // y=3
    "#...................#",  // y=2
    "#...................#",  // y=1
    "#####################",  // y=0
};

TEST(Explore, CaseBGroupSkipsTheSegmentItHasExploredSinceTheFusion) {
  const AsciiMap world = ascii_map(kCaseB);
  const AsciiMap mine = ascii_map(kCaseBRightExplored);
  // Two groups: leader 0 (15,8) and leader 2 (18,3) as group 1. C_ij = D_ij / W_j (see above):
  //   L0: seg 0 1.25, seg 1 4.714, seg 2 2.550;  L2: seg 0 0.25, seg 1 5.676, seg 2 5.000.
  // Optimum (seg 2, seg 0) = 2.80 < (seg 1, seg 0) 4.96 < (seg 0, seg 2) 6.25 < the rest.
  const std::vector<Cell> leaders = {world.at.at('0'), world.at.at('2')};
  for (bool groups : {true, false}) {
    ExploreConfig cfg;
    cfg.use_group_frontiers = groups;
    ExploreInput in;
    in.global_map = &world.grid;
    in.group_map = &mine.grid;
    in.leader_positions = leaders;
    in.group = 1;
    in.member_positions = members_of(leaders[1]);
    const ExplorePlan plan = plan_group_exploration(in, cfg);
    ASSERT_EQ(plan.plan_case, PlanCase::GlobalAssignment);
    EXPECT_TRUE(plan.group_frontiers.empty());
    ASSERT_EQ(plan.global_segments.size(), 3u);
    // The shared assignment, as every leader computes it, is unchanged ...
    EXPECT_EQ(plan.group_to_segment, (std::vector<int>{2, 0}));
    // ... but this group explored segment 0 itself. Of the open segments, 2 (own cost 5.000) is
    // cheaper than 1 (5.676), but the shared assignment gives 2 to group 0, so the group takes 1.
    EXPECT_EQ(plan.chosen_segment, 1);
    for (std::size_t m = 0; m < plan.waypoints.size(); ++m) {
      ASSERT_TRUE(plan.waypoints[m]);
      EXPECT_TRUE(contains(plan.global_segments[1], *plan.waypoints[m]));
      EXPECT_EQ(plan.member_segment[m], 1);
    }
    // Three robots (18,3), (18,2), (17,3) on the three cells (1,4), (1,5), (1,6), one each. The
    // least summed distance: (1,6), (1,4), (1,5) = 17.263 + 17.117 + 16.125 = 50.504; next best
    // (1,5), (1,4), (1,6) = 50.513.
    EXPECT_EQ(plan.waypoints,
              (std::vector<std::optional<Cell>>{Cell{1, 6}, Cell{1, 4}, Cell{1, 5}}));
  }
  // Group 0 does not know what group 1 saw: with the global map as its group map it keeps its
  // row (segment 2), so the two groups do not meet.
  ExploreInput other;
  other.global_map = &world.grid;
  other.group_map = &world.grid;
  other.leader_positions = leaders;
  other.group = 0;
  other.member_positions = {leaders[0]};
  EXPECT_EQ(plan_group_exploration(other, ExploreConfig{}).chosen_segment, 2);
}

TEST(Explore, CaseBTakesASegmentOfAnotherGroupWhenEveryFreeOneIsExplored) {
  // Three groups: the shared assignment is (2, 1, 0) (CaseBMatchesTheHandSolvedHungarian), so
  // segments 1 and 2 both belong to other groups; group 2 explored its own segment 0. It shares
  // the open segment of least own cost: seg 2 (10,9): 10 / 2 = 5.000 < seg 1 (1,4): 17.029 / 3.
  const AsciiMap world = ascii_map(kCaseB);
  const AsciiMap mine = ascii_map(kCaseBRightExplored);
  ExploreInput in;
  in.global_map = &world.grid;
  in.group_map = &mine.grid;
  in.leader_positions = {world.at.at('0'), world.at.at('1'), world.at.at('2')};
  in.group = 2;
  in.member_positions = {world.at.at('2')};
  const ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
  EXPECT_EQ(plan.group_to_segment, (std::vector<int>{2, 1, 0}));
  EXPECT_EQ(plan.plan_case, PlanCase::GlobalAssignment);
  EXPECT_EQ(plan.chosen_segment, 2);
  // K-Means k = 1 on (9,9), (10,9): centre (9.5, 9), the first cell in row-major order wins.
  EXPECT_EQ(plan.waypoints, (std::vector<std::optional<Cell>>{Cell{9, 9}}));
}

TEST(Explore, CaseBOnlyPartlyExploredSegmentKeepsItsOpenCells) {
  // Group 2 has seen behind (20,4) and (20,5) only: segment 0 keeps (19,2), (19,3) open, so the
  // group stays on its row's segment and its robots go to those two cells.
  const AsciiMap world = ascii_map(kCaseB);
  std::vector<std::string> rows = kCaseB;
  rows[5][20] = '#';  // y=5
  rows[6][20] = '#';  // y=4
  const AsciiMap mine = ascii_map(rows);
  ExploreInput in;
  in.global_map = &world.grid;
  in.group_map = &mine.grid;
  in.leader_positions = {world.at.at('0'), world.at.at('1'), world.at.at('2')};
  in.group = 2;
  in.member_positions = {{18, 3}, {18, 2}};
  const ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
  EXPECT_EQ(plan.chosen_segment, 0);
  EXPECT_EQ(plan.waypoints, (std::vector<std::optional<Cell>>{Cell{19, 3}, Cell{19, 2}}));
}

TEST(Explore, CaseBNoFrontierWhenTheGroupHasExploredEverySegment) {
  // Every opening of kCaseB seen by this group to end in a wall: the stale global map still has
  // three segments, but no cell the group can reach is unexplored. Nobody is sent anywhere.
  const AsciiMap world = ascii_map(kCaseB);
  std::vector<std::string> rows = kCaseBRightExplored;
  rows[0] = "#####################";
  for (int y : {4, 5, 6}) rows[10 - y][0] = '#';
  const AsciiMap mine = ascii_map(rows);
  for (bool groups : {true, false}) {
    ExploreConfig cfg;
    cfg.use_group_frontiers = groups;
    ExploreInput in;
    in.global_map = &world.grid;
    in.group_map = &mine.grid;
    in.leader_positions = {world.at.at('0'), world.at.at('1'), world.at.at('2')};
    in.group = 2;
    in.member_positions = members_of(world.at.at('2'));
    const ExplorePlan plan = plan_group_exploration(in, cfg);
    EXPECT_EQ(plan.plan_case, PlanCase::NoFrontier);
    EXPECT_EQ(plan.global_segments.size(), 3u);  // still reported, for pictures
    EXPECT_EQ(plan.chosen_segment, -1);
    EXPECT_EQ(plan.waypoints, std::vector<std::optional<Cell>>(3, std::nullopt));
    EXPECT_EQ(plan.member_segment, std::vector<int>(3, -1));
  }
}

TEST(Explore, BaselineNeverReturnsCaseA) {
  // Every map above, every group, several rounds: with use_group_frontiers = false it is always
  // case B (or NoFrontier), even where case A applies with the full planner.
  const AsciiMap room_global = ascii_map(kRoomGlobal), room_group = ascii_map(kRoomGroup);
  CaseAFixture a;
  const AsciiMap b = ascii_map(kCaseB);
  struct Scene {
    const OccupancyGrid* global;
    const OccupancyGrid* group;
    std::vector<Cell> leaders;
  };
  const std::vector<Scene> scenes = {
      {&room_global.grid, &room_group.grid, {room_global.at.at('L')}},
      {&a.global, &a.group.grid, {a.group.at.at('L')}},
      {&b.grid, &b.grid, {b.at.at('0'), b.at.at('1'), b.at.at('2')}},
  };
  ExploreConfig baseline;
  baseline.use_group_frontiers = false;
  for (const Scene& s : scenes) {
    for (int g = 0; g < static_cast<int>(s.leaders.size()); ++g) {
      for (int round = 0; round < 3; ++round) {
        ExploreInput in;
        in.global_map = s.global;
        in.group_map = s.group;
        in.leader_positions = s.leaders;
        in.group = g;
        in.member_positions = {s.leaders[g]};
        in.round = round;
        const ExplorePlan plan = plan_group_exploration(in, baseline);
        EXPECT_NE(plan.plan_case, PlanCase::GroupFrontier);
        EXPECT_TRUE(plan.group_frontiers.empty());
        EXPECT_TRUE(plan.group_segments.empty());
      }
    }
  }
  // The case-A scene: nothing fused yet, so the baseline has no global frontier at all.
  ExploreInput in;
  in.global_map = &a.global;
  in.group_map = &a.group.grid;
  in.leader_positions = {a.group.at.at('L')};
  in.member_positions = {a.group.at.at('L')};
  EXPECT_EQ(plan_group_exploration(in, baseline).plan_case, PlanCase::NoFrontier);
  EXPECT_EQ(plan_group_exploration(in, ExploreConfig{}).plan_case, PlanCase::GroupFrontier);
}

// ------------------------------------------------------------------------------------------------
// No frontier, determinism, speed

TEST(Explore, NoFrontierOnAFullyKnownMap) {
  const AsciiMap world = ascii_map({
      "########",
      "#..#...#",
      "#.L#.A.#",
      "#......#",
      "########",
  });
  ExploreInput in;
  in.global_map = &world.grid;
  in.group_map = &world.grid;
  in.leader_positions = {world.at.at('L')};
  in.member_positions = {world.at.at('L'), world.at.at('A')};
  for (bool groups : {true, false}) {
    ExploreConfig cfg;
    cfg.use_group_frontiers = groups;
    const ExplorePlan plan = plan_group_exploration(in, cfg);
    EXPECT_EQ(plan.plan_case, PlanCase::NoFrontier);
    EXPECT_EQ(plan.waypoints, std::vector<std::optional<Cell>>(2, std::nullopt));
    EXPECT_EQ(plan.chosen_segment, -1);
    EXPECT_TRUE(plan.group_frontiers.empty());
  }
}

TEST(Explore, UnreachableFrontiersDoNotCount) {
  // The only unknown cell (5,2) is behind walls: its frontier cell (4,2) is a sealed pocket.
  const AsciiMap world = ascii_map({
      "#######",
      "#..#.?#",
      "#.L####",
      "#######",
  });
  ExploreInput in;
  in.global_map = &world.grid;
  in.group_map = &world.grid;
  in.leader_positions = {world.at.at('L')};
  in.member_positions = {world.at.at('L')};
  EXPECT_EQ(plan_group_exploration(in, ExploreConfig{}).plan_case, PlanCase::NoFrontier);
}

// 100 x 100, three groups: the stale global map knows the left half, with unknown specks on a
// lattice (thousands of frontier cells); group 1 has since seen a band of the right half.
TEST(Explore, SameInputGivesTheIdenticalPlan) {
  const swarm::test::BigExploreWorld w;
  ASSERT_GT(find_frontiers(w.global).size(), 2000u);
  for (bool groups : {true, false}) {
    ExploreConfig cfg;
    cfg.use_group_frontiers = groups;
    const ExplorePlan a = plan_group_exploration(w.input(3), cfg);
    const ExplorePlan b = plan_group_exploration(w.input(3), cfg);
    EXPECT_EQ(a.plan_case, groups ? PlanCase::GroupFrontier : PlanCase::GlobalAssignment);
    expect_same_plan(a, b);
    // A copy of the maps (different addresses) changes nothing either.
    const swarm::test::BigExploreWorld copy = w;
    expect_same_plan(a, plan_group_exploration(copy.input(3), cfg));
    for (const auto& wp : a.waypoints) EXPECT_TRUE(wp.has_value());
  }
}

// Its speed is `swarm bench` (BM_ExplorePlan); here, that every round plans.
TEST(Explore, EveryRoundOnAHundredByHundredGridPlans) {
  const swarm::test::BigExploreWorld w;
  for (bool groups : {true, false}) {
    ExploreConfig cfg;
    cfg.use_group_frontiers = groups;
    for (int round = 0; round < 10; ++round) {
      const ExplorePlan p = plan_group_exploration(w.input(round), cfg);
      EXPECT_EQ(p.plan_case, groups ? PlanCase::GroupFrontier : PlanCase::GlobalAssignment) << round;
      for (const auto& wp : p.waypoints) EXPECT_TRUE(wp.has_value()) << round;
    }
  }
}

}  // namespace
}  // namespace swarm::planner
