// The traffic layer's dry run: alone a robot's makespan is its route's moves; two routes that
// meet head-on cost what the planner makes one robot do to let the other pass.
#include "swarm/planner/traffic/rehearsal.hpp"

#include <gtest/gtest.h>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::planner::traffic {
namespace {

TEST(Rehearsal, ARobotAloneTakesItsRoutesMoves) {
  const auto art = swarm::test::ascii_map({
      "A.....",
      "......",
  });
  std::vector<Agent> agents = {{art.at.at('A'), {{5, 1}, {5, 0}, {0, 0}}}};
  const Rehearsal r = rehearse(art.grid, MotionModel::four(), agents, 4, {}, 100);
  EXPECT_TRUE(r.finished);
  EXPECT_EQ(r.makespan, 11);  // 5 right, 1 down, 5 left, over three windows of 4
  EXPECT_EQ(r.moves, 11);
  EXPECT_EQ(r.skipped, 0);
  EXPECT_EQ(driven_ticks(r.paths, [](int, int) { return 10; }), 11);  // nobody to wait for
}

// Head-on in a corridor two cells wide: each route is 6 moves, but one robot steps aside into
// the other lane, so the plan takes longer than either route, and more moves in all.
TEST(Rehearsal, RoutesThatMeetHeadOnCostMoreThanTheirLength) {
  const auto art = swarm::test::ascii_map({
      ".......",
      "A.....B",
  });
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('B')}}, {art.at.at('B'), {art.at.at('A')}}};
  const Rehearsal r = rehearse(art.grid, MotionModel::four(), agents, 8, {}, 100);
  EXPECT_TRUE(r.finished);
  EXPECT_EQ(r.makespan, 9);  // A waits a step, steps into the other lane and back: 8 moves in 9
  EXPECT_EQ(r.moves, 14);
  // Driven by the dependency graph: with no message delay (a dependency costs the one tick the
  // plan has too) A drives its 8 moves without the plan's wait, which no cell needed; when A
  // learns of B's moves 3 ticks late, later.
  EXPECT_EQ(driven_ticks(r.paths, [](int, int) { return 1; }), 8);
  const int late = driven_ticks(r.paths, [](int, int) { return 3; });
  EXPECT_GT(late, 8);
  EXPECT_LE(late, 8 + 2 * 3);
}

// Three robots in a row that the plan moves as one, each into the cell the one ahead leaves in the
// same step: 3 steps planned. Driven by the graph, each sets off only once it has seen the cell
// ahead left, a lag behind the one ahead, so the last arrives 2 lags later; a robot that may start
// only later (its route still on the way) holds up the ones behind it.
TEST(Rehearsal, AQueueThatThePlanMovesAsOnePaysALagPerRobot) {
  const std::vector<std::vector<Cell>> paths = {
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}},
      {{1, 0}, {2, 0}, {3, 0}, {4, 0}},
      {{2, 0}, {3, 0}, {4, 0}, {5, 0}},
  };
  EXPECT_EQ(driven_ticks(paths, [](int, int) { return 1; }), 5);
  EXPECT_EQ(driven_ticks(paths, [](int, int) { return 2; }), 7);
  EXPECT_EQ(driven_ticks(paths, [](int, int) { return 1; }, {0, 0, 2}), 7);  // the head starts at 2
  EXPECT_EQ(driven_ticks(paths, [](int, int) { return 1; }, {2, 0, 0}), 5);  // the tail's start is no later
  // The same starts at once, the graph built once: the same ticks, in the order given.
  EXPECT_EQ(driven_ticks_per_start(paths, [](int, int) { return 1; }, {{}, {0, 0, 2}, {2, 0, 0}, {0, 4, 0}}),
            (std::vector<int>{5, 7, 5, 8}));  // a late middle holds up the tail: 5, 6, 7, then 6, 7, 8
}

// Four robots round a square in one step: a rotation goes in one tick, with no lag among them.
TEST(Rehearsal, ARotationGoesTogether) {
  const std::vector<std::vector<Cell>> paths = {
      {{0, 0}, {1, 0}},
      {{1, 0}, {1, 1}},
      {{1, 1}, {0, 1}},
      {{0, 1}, {0, 0}},
  };
  EXPECT_EQ(driven_ticks(paths, [](int, int) { return 1; }), 1);
  EXPECT_EQ(driven_ticks(paths, [](int, int) { return 1; }, {0, 0, 3, 0}), 4);  // all wait for the last
}

// A goal behind a robot that never moves is skipped, not chased for ever.
TEST(Rehearsal, AGoalBehindAStandingRobotIsSkipped) {
  const auto art = swarm::test::ascii_map({"A.F.G"});
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('G')}}, {art.at.at('F'), {}, true}};
  const Rehearsal r = rehearse(art.grid, MotionModel::four(), agents, 4, {}, 40);
  EXPECT_TRUE(r.finished);
  EXPECT_EQ(r.skipped, 1);
}

// Two robots that must pass each other in a corridor with no room to do so never finish: the
// rehearsal stops at the cap and says so.
TEST(Rehearsal, AStandOffStopsAtTheCap) {
  const auto art = swarm::test::ascii_map({"A.....B"});
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('B')}}, {art.at.at('B'), {art.at.at('A')}}};
  const Rehearsal r = rehearse(art.grid, MotionModel::four(), agents, 8, {}, 64);
  EXPECT_FALSE(r.finished);
  EXPECT_EQ(r.makespan, 64);
}

// Where the corridor has room beside it, the same meeting ends: PIBT alone pushes them back into
// the dead ends for ever, but its swap lets them pass (traffic.hpp).
TEST(Rehearsal, AStandOffWithRoomBesideItEnds) {
  const auto art = swarm::test::ascii_map({
      "##...##",
      "A.....B",
  });
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('B')}}, {art.at.at('B'), {art.at.at('A')}}};
  const Rehearsal r = rehearse(art.grid, MotionModel::four(), agents, 8, {}, 64);
  EXPECT_TRUE(r.finished);
  EXPECT_EQ(r.makespan, 9);  // 6 along, and one aside and back
}

}  // namespace
}  // namespace swarm::planner::traffic
