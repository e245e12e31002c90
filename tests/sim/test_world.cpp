#include "swarm/sim/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/motion_cases.hpp"

namespace swarm::sim {
namespace {

using planner::Cell;
using planner::CellState;
using planner::OccupancyGrid;
using swarm::test::grid_from;

constexpr LidarConfig kLidar{360, 15.0f};

OccupancyGrid open_room(int w, int h) { return OccupancyGrid(w, h, 0.2, 0.0, 0.0, CellState::Free); }

TEST(World, MovesOneCellPerTickAlongTheRoute) {
  World w(open_room(5, 5), {{0, 0}}, kLidar);
  w.command(0, 7, {{0, 0}, {1, 1}, {2, 1}, {3, 2}});
  EXPECT_EQ(w.route(0).state, RouteState::Active);
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 1}));
  EXPECT_EQ(w.route(0).step, 1u);
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{2, 1}));
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{3, 2}));
  EXPECT_EQ(w.route(0).state, RouteState::Finished);
  EXPECT_EQ(w.route(0).id, 7u);
  w.move();  // the end of the route: stays
  EXPECT_EQ(w.robots()[0], (Cell{3, 2}));
  EXPECT_EQ(w.total_counts().moves, 3u);
  EXPECT_EQ(w.total_counts().wall_stops, 0u);
  EXPECT_EQ(w.total_counts().blocked_moves, 0u);
}

// Robot 0 drives east along a one-cell corridor into robot 1, which waits on (2, 0) until tick 5
// and then drives on: robot 0 is held up on ticks 2, 3 and 4 (each a vertex conflict: both meant
// for (2, 0)), then follows. A phase mark after tick 3 sees 1 of those ticks.
TEST(World, CountsTheLongestRunOfConsecutiveBlockedTicksOverTheRunAndSinceAMark) {
  World w(open_room(8, 1), {{0, 0}, {2, 0}}, kLidar);
  w.command(0, 1, {{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  w.command(1, 2, {{2, 0}, {2, 0}, {2, 0}, {2, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}});
  w.move();  // tick 1: robot 0 to (1, 0); robot 1 waits (a wait is never blocked)
  w.move();  // tick 2: robot 0 held up
  w.move();  // tick 3
  EXPECT_EQ(w.counts()[0].longest_blocked_ticks, 2u);
  w.mark();
  w.move();  // tick 4: held up
  w.move();  // tick 5: robot 1 leaves (2, 0) and robot 0 follows it in
  for (int i = 0; i < 4; ++i) w.move();
  EXPECT_EQ(w.robots()[0], (Cell{3, 0}));
  EXPECT_EQ(w.counts()[0].longest_blocked_ticks, 3u);
  EXPECT_EQ(w.counts()[0].vertex_conflicts, 3u);
  EXPECT_EQ(w.longest_blocked_since_mark()[0], 1u);
  EXPECT_EQ(w.counts()[1].longest_blocked_ticks, 0u);  // took part in the conflicts, but stayed by plan
  EXPECT_EQ(w.total_counts().longest_blocked_ticks, 3u);  // the largest, not a sum
}

TEST(World, ARouteNotStartingOnTheRobotsCellIsRejectedAndStopsIt) {
  World w(open_room(6, 6), {{0, 0}}, kLidar);
  w.command(0, 1, {{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  w.move();
  w.command(0, 2, {{0, 0}, {1, 0}, {2, 0}});  // the robot is on (1, 0) already
  EXPECT_EQ(w.route(0).state, RouteState::Rejected);
  EXPECT_EQ(w.route(0).id, 2u);
  for (int i = 0; i < 3; ++i) w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 0}));
  EXPECT_EQ(w.counts()[0].routes_rejected, 1u);
  w.command(0, 3, {});  // an empty route: stop
  EXPECT_EQ(w.route(0).state, RouteState::Stopped);
}

// A lost command repeated later, or one delayed by jitter, can arrive after a newer one: it was
// overtaken and changes nothing (before, a stop sent after a route part could be undone by the
// part's repeat, and the robot never confirmed its stop).
TEST(World, ACommandOlderThanTheRobotsRouteIsIgnored) {
  World w(open_room(6, 6), {{0, 0}}, kLidar);
  w.command(0, 5, {});  // stop
  w.command(0, 4, {{0, 0}, {1, 0}, {2, 0}});  // the part before it, repeated late
  EXPECT_EQ(w.route(0).id, 5u);
  EXPECT_EQ(w.route(0).state, RouteState::Stopped);
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{0, 0}));
  w.command(0, 5, {{0, 0}, {1, 0}});  // the same again: applied once already
  EXPECT_EQ(w.route(0).state, RouteState::Stopped);
  w.command(0, 6, {{0, 0}, {1, 0}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 0}));
}

// Four robots round a 2 x 2 ring, whose commands come at different ticks (a lost one repeated):
// each is held for the tick it names, and all four step round together then, with no conflict.
// A newer command before that tick replaces a held one; a lost robot's held command is dropped.
TEST(World, CommandsForALaterTickAreHeldAndGivenTogetherThen) {
  const std::vector<Cell> ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  World w(open_room(3, 3), ring, kLidar);
  const auto to_next = [&](int r) { return std::vector<Cell>{ring[r], ring[(r + 1) % 4]}; };
  w.command_at(3, 0, 1, to_next(0));
  w.command_at(3, 1, 1, to_next(1));
  w.start_due(1);
  w.move();  // tick 1: nobody has a route yet
  w.command_at(3, 2, 1, to_next(2));
  w.start_due(2);
  w.move();  // tick 2
  EXPECT_EQ(w.robots(), ring);
  EXPECT_EQ(w.route(0).id, 0u);
  w.command_at(3, 3, 1, to_next(3));  // the last, just in time
  w.start_due(3);
  w.move();  // tick 3: all four round the ring
  for (int r = 0; r < 4; ++r) EXPECT_EQ(w.robots()[r], ring[(r + 1) % 4]) << r;
  EXPECT_EQ(w.events().vertex, 0u);
  EXPECT_EQ(w.events().edge, 0u);
  EXPECT_EQ(w.total_counts().blocked_moves, 0u);

  // Replaced before its tick by a newer command (a stop), and dropped for a lost robot.
  World v(open_room(4, 1), {{0, 0}, {3, 0}}, kLidar);
  v.command_at(5, 0, 1, {{0, 0}, {1, 0}});
  v.command(0, 2, {});
  v.command_at(5, 1, 1, {{3, 0}, {2, 0}});
  v.stop(1);
  v.start_due(5);
  v.move();
  EXPECT_EQ(v.robots()[0], (Cell{0, 0}));
  EXPECT_EQ(v.route(0).id, 2u);
  EXPECT_EQ(v.robots()[1], (Cell{3, 0}));
  EXPECT_EQ(v.route(1).id, 0u);
}

TEST(World, AWaitKeepsTheRobotAndIsNoWallStop) {
  World w(open_room(3, 1), {{0, 0}}, kLidar);
  w.command(0, 1, {{0, 0}, {0, 0}, {0, 0}, {1, 0}});
  w.move();
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{0, 0}));
  EXPECT_EQ(w.route(0).step, 2u);
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 0}));
  EXPECT_EQ(w.route(0).state, RouteState::Finished);
  EXPECT_EQ(w.total_counts().waits, 2u);
  EXPECT_EQ(w.total_counts().moves, 1u);
  EXPECT_EQ(w.total_counts().wall_stops, 0u);
}

// Regression: a route through a cell twice used to skip ahead (the robot's place was looked up
// from the end of the path).
TEST(World, ARouteThroughACellTwiceIsFollowedToItsEnd) {
  World w(open_room(3, 3), {{0, 0}}, kLidar);
  const std::vector<Cell> loop = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {2, 0}};
  w.set_motion(planner::MotionModel::four());
  w.command(0, 1, loop);
  std::vector<Cell> visited = {w.robots()[0]};
  for (int i = 0; i < 8; ++i) {
    w.move();
    visited.push_back(w.robots()[0]);
  }
  EXPECT_EQ(std::vector<Cell>(visited.begin(), visited.begin() + 7), loop);
  EXPECT_EQ(w.robots()[0], (Cell{2, 0}));
  EXPECT_EQ(w.total_counts().moves, 6u);
}

TEST(World, AnIllegalActionIsAWallStopThatAbandonsTheRoute) {
  const OccupancyGrid truth = grid_from({
      "...",  // y = 1
      ".#.",  // y = 0
  });
  World w(truth, {{0, 0}}, kLidar);
  // (0,0)->(1,1) passes the corner of the wall (1, 0): refused, counted, and the route dropped.
  w.command(0, 1, {{0, 0}, {1, 1}, {2, 1}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{0, 0}));
  EXPECT_EQ(w.route(0).state, RouteState::Abandoned);
  EXPECT_EQ(w.total_counts().wall_stops, 1u);
  // The same cell reached without cutting the corner.
  w.command(0, 2, {{0, 0}, {0, 1}, {1, 1}});
  w.move();
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 1}));
  // Under the 4-connected model of coverage and MAPF a diagonal is no action at all.
  w.set_motion(planner::MotionModel::four());
  w.command(0, 3, {{1, 1}, {2, 0}});
  w.move();
  EXPECT_EQ(w.robots()[0], (Cell{1, 1}));
  EXPECT_EQ(w.total_counts().wall_stops, 2u);
}

// The shared table (swarm_test/motion_cases.hpp), as the simulator executes it.
TEST(Resolve, TheSharedMotionCases) {
  for (const auto& c : swarm::test::motion_cases()) {
    const Resolution r = resolve(c.from, c.to);
    EXPECT_EQ(r.events.vertex, static_cast<std::uint64_t>(c.vertex_events)) << c.name;
    EXPECT_EQ(r.events.edge, static_cast<std::uint64_t>(c.edge_events)) << c.name;
    EXPECT_EQ(r.next, c.after) << c.name;
    EXPECT_EQ(std::count(r.blocked.begin(), r.blocked.end(), 1), c.blocked) << c.name;
  }
}

TEST(Resolve, PermutingRobotIdsChangesNoOutcome) {
  for (const auto& c : swarm::test::motion_cases()) {
    std::vector<int> perm(c.from.size());
    std::iota(perm.begin(), perm.end(), 0);
    const Resolution base = resolve(c.from, c.to);
    int tried = 0;
    do {
      std::vector<Cell> from, to;
      for (int i : perm) {
        from.push_back(c.from[i]);
        to.push_back(c.to[i]);
      }
      const Resolution r = resolve(from, to);
      EXPECT_EQ(r.events.vertex, base.events.vertex) << c.name;
      EXPECT_EQ(r.events.edge, base.events.edge) << c.name;
      for (std::size_t k = 0; k < perm.size(); ++k) {
        EXPECT_EQ(r.next[k], base.next[perm[k]]) << c.name;
        EXPECT_EQ(r.blocked[k], base.blocked[perm[k]]) << c.name;
      }
      ++tried;
    } while (std::next_permutation(perm.begin(), perm.end()));
    EXPECT_GE(tried, 1);
  }
}

TEST(World, ConflictsAreCountedPerRobotAndRetriedEveryTick) {
  World w(open_room(3, 1), {{0, 0}, {1, 0}}, kLidar);
  w.command(0, 1, {{0, 0}, {1, 0}});
  w.command(1, 1, {{1, 0}, {0, 0}});
  w.move();
  w.move();  // they try the same swap again
  EXPECT_EQ(w.robots()[0], (Cell{0, 0}));
  EXPECT_EQ(w.events().edge, 2u);
  EXPECT_EQ(w.counts()[0].edge_conflicts, 2u);
  EXPECT_EQ(w.counts()[1].edge_conflicts, 2u);
  EXPECT_EQ(w.route(0).state, RouteState::Active);
}

TEST(World, AFootprintCoversAroundTheRobot) {
  // 5 x 5 open room; radius 1 covers the robot's cell and its 4 orthogonal neighbours.
  World w(open_room(5, 5), {{2, 2}}, kLidar, 1);
  EXPECT_EQ(w.coverage_target_cells(), 25);
  EXPECT_EQ(w.covered_cells(), 5);
  EXPECT_TRUE(w.is_covered({2, 3}));
  EXPECT_FALSE(w.is_covered({3, 3}));
  w.command(0, 1, {{2, 2}, {3, 2}});
  w.move();
  // (3,2) adds (4,2), (3,3), (3,1).
  EXPECT_EQ(w.covered_cells(), 8);
  EXPECT_DOUBLE_EQ(w.covered_fraction(), 8.0 / 25.0);
  World bare(open_room(5, 5), {{2, 2}}, kLidar);  // radius 0: the cell stood on only
  EXPECT_EQ(bare.covered_cells(), 1);
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
  w.command(0, 1, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}});
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
// Collect: a robot picks up what lies on its cell at a pick step and drops all it carries at a
// drop step: delivered at its type's destination, counted as a wrong drop elsewhere (and lying
// there again); a lost robot's load is put down beside it.
TEST(WorldCollect, PickDeliverAndWrongDrop) {
  World w(open_room(6, 1), {{0, 0}}, kLidar);
  w.set_motion(swarm::planner::MotionModel::eight());
  w.set_objects({{{1, 0}, 0}, {{2, 0}, 1}}, {{3, 0}, {5, 0}});
  w.command(0, 1, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}, {1, 2}, {3, 4});
  for (int k = 0; k < 4; ++k) w.move();
  // Both picked at (1, 0) and (2, 0); at (3, 0) type 0 is delivered and type 1 dropped there (its
  // destination is (5, 0)); at (4, 0) nothing is carried any more.
  EXPECT_EQ(w.collect().objects, 2);
  EXPECT_EQ(w.object_states(), (std::vector<int>{3, 0, World::kDelivered, 3, 0, World::kLying}));
  EXPECT_EQ(w.collect().picked, 2);
  EXPECT_EQ(w.collect().delivered, 1);
  EXPECT_EQ(w.collect().wrong_drops, 1);
  // Picked up again where it was dropped and carried to (5, 0).
  w.command(0, 2, {{4, 0}, {3, 0}, {4, 0}, {5, 0}}, {1}, {3});
  for (int k = 0; k < 3; ++k) w.move();
  EXPECT_EQ(w.collect().picked, 3);
  EXPECT_EQ(w.collect().delivered, 2);
}

TEST(WorldCollect, ALostRobotsLoadLiesBesideItForAnotherToDeliver) {
  World w(open_room(3, 2), {{0, 0}, {2, 1}}, kLidar);
  w.set_motion(swarm::planner::MotionModel::eight());
  w.set_objects({{{1, 0}, 0}}, {{0, 1}});
  EXPECT_EQ(w.object_states(), (std::vector<int>{1, 0, World::kLying}));
  w.command(0, 1, {{0, 0}, {1, 0}}, {1}, {});
  w.move();
  EXPECT_EQ(w.collect().picked, 1);
  EXPECT_EQ(w.object_states(), (std::vector<int>{1, 0, 0}));  // carried by robot 0, on its cell
  // Robot 0 is lost on (1, 0): its load goes to the first free cell beside it no robot holds.
  EXPECT_EQ(swarm::planner::put_down_cell(w.truth(), {1, 0}, w.robots()), (Cell{0, 0}));
  w.put_down(0);
  EXPECT_EQ(w.object_states(), (std::vector<int>{0, 0, World::kLying}));
  w.command(1, 2, {{2, 1}, {1, 1}, {0, 0}, {0, 1}}, {2}, {3});
  w.move();
  w.move();
  EXPECT_EQ(w.object_states(), (std::vector<int>{0, 0, 1}));  // robot 1 picked it up at (0, 0)
  w.move();
  EXPECT_EQ(w.object_states(), (std::vector<int>{0, 1, World::kDelivered}));
  EXPECT_EQ(w.collect().picked, 2);
  EXPECT_EQ(w.collect().delivered, 1);
  EXPECT_EQ(w.collect().wrong_drops, 0);
}

}  // namespace swarm::sim
