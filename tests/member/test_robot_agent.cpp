#include "swarm/member/robot_agent.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "swarm/planner/sensing/raycast.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace swarm::member {
namespace {

using planner::Cell;
using planner::CellChange;
using planner::CellState;
using planner::OccupancyGrid;
using swarm::test::ascii_map;

constexpr int kBeams = 360;  // one beam per degree, as the shipped scenarios

// What the simulator would report on the robot's latest route with the robot at `at`: the
// route's first cell at or after where it stood last (tests move robots by hand along routes
// that never pass a cell twice).
planner::RouteProgress report_at(const RobotAgent& robot, Cell at) {
  const auto& route = robot.route();
  planner::RouteProgress r;
  r.id = robot.route_id();
  if (route.empty()) {
    r.state = planner::RouteState::Stopped;
    return r;
  }
  const auto it = std::find(route.begin(), route.end(), at);
  r.step = it == route.end() ? 0 : static_cast<std::uint32_t>(it - route.begin());
  r.state = it == route.end()         ? planner::RouteState::Rejected
            : it + 1 == route.end() ? planner::RouteState::Finished
                                    : planner::RouteState::Active;
  return r;
}

// One tick of a robot's loop as swarm-member runs it: the simulator's scan of the truth from
// `at` is integrated with the simulator's report on the route, then the agent steps.
RobotAgent::Step tick_at(RobotAgent& robot, const OccupancyGrid& truth, Cell at, float range) {
  std::vector<float> ranges(kBeams);
  planner::scan(truth, at, kBeams, range, ranges.data());
  robot.sense(at, ranges, range, report_at(robot, at));
  return robot.step();
}

RobotAgent agent_for(const OccupancyGrid& truth) {
  return RobotAgent(truth.width(), truth.height(), truth.resolution());
}

TEST(RobotAgent, ScanAndStepGiveTheExactAStarPathAndArrivalIsReportedOnce) {
  const auto art = ascii_map({
      "##G##",  // y = 4
      "##.##",  // y = 3: the only way up is the gap (2, 3)
      ".....",  // y = 2
      ".....",  // y = 1
      "R....",  // y = 0
  });
  const Cell start = art.at.at('R');  // (0, 0)
  const Cell goal = art.at.at('G');   // (2, 4)
  RobotAgent robot = agent_for(art.grid);

  std::vector<float> ranges(kBeams);
  planner::scan(art.grid, start, kBeams, 10.0f, ranges.data());
  const std::vector<CellChange> changes = robot.sense(start, ranges, 10.0f);
  // sense() returns exactly the cells it changed: replaying them on an empty map gives its map.
  OccupancyGrid replay(5, 5);
  EXPECT_EQ(replay.apply(changes), static_cast<int>(changes.size()));
  EXPECT_EQ(replay, robot.map());
  // The walls beside the gap are seen from (0.5, 0.5): the beam at 72 deg enters (1, 3) from
  // (1, 2) at x = 1.31; the beam at 44 deg enters (3, 3) from (3, 2) at x = 3.09; the beam at
  // 32 deg enters (4, 3) from (4, 2) at x = 4.5; the beam at 90 deg enters (0, 3).
  for (const Cell wall : {Cell{0, 3}, Cell{1, 3}, Cell{3, 3}, Cell{4, 3}}) {
    EXPECT_EQ(robot.map().at(wall), CellState::Occupied) << wall.x << "," << wall.y;
  }

  robot.assign(7, goal);
  const RobotAgent::Step first = robot.step();
  // Row 3 is known to be wall except (2, 3), and (1,2)->(2,3), (3,2)->(2,3) would cut the corners
  // (1, 3), (3, 3): every path enters (2, 3) from (2, 2) and (2, 4) from (2, 3). (0,0)->(2,2)
  // costs 2*sqrt2 only along the diagonal. So the one cheapest path (2 + 2*sqrt2) is:
  const std::vector<Cell> expected = {{0, 0}, {1, 1}, {2, 2}, {2, 3}, {2, 4}};
  EXPECT_TRUE(first.path_changed);
  EXPECT_EQ(first.path, expected);
  EXPECT_FALSE(first.report);
  EXPECT_EQ(robot.replans(), 1u);

  // Driving along it keeps the path: no new command, no report, until the goal.
  for (std::size_t i = 1; i + 1 < expected.size(); ++i) {
    const RobotAgent::Step s = tick_at(robot, art.grid, expected[i], 10.0f);
    EXPECT_FALSE(s.path_changed) << "at path cell " << i;
    EXPECT_FALSE(s.report) << "at path cell " << i;
  }
  // On the goal: Arrived for round 7 and one stop (an empty path), in the same step.
  const RobotAgent::Step arrived = tick_at(robot, art.grid, goal, 10.0f);
  ASSERT_TRUE(arrived.report);
  EXPECT_EQ(*arrived.report, WaypointState::Arrived);
  EXPECT_EQ(arrived.round, 7u);
  EXPECT_TRUE(arrived.path_changed);
  EXPECT_TRUE(arrived.path.empty());
  EXPECT_FALSE(robot.waypoint());
  // Afterwards: neither a second report nor a second stop.
  for (int i = 0; i < 3; ++i) {
    const RobotAgent::Step idle = tick_at(robot, art.grid, goal, 10.0f);
    EXPECT_FALSE(idle.report);
    EXPECT_FALSE(idle.path_changed);
  }
  EXPECT_EQ(robot.replans(), 1u);
}

TEST(RobotAgent, AWaypointOnTheRobotsCellIsArrivedAtOnceAndStopsOnlyAMovingRobot) {
  const OccupancyGrid truth = swarm::test::grid_from({"....."});
  RobotAgent robot = agent_for(truth);
  // Never sent a path: Arrived at once and no stop (there is nothing to stop).
  tick_at(robot, truth, {0, 0}, 10.0f);
  robot.assign(1, Cell{0, 0});
  RobotAgent::Step s = robot.step();
  ASSERT_TRUE(s.report);
  EXPECT_EQ(*s.report, WaypointState::Arrived);
  EXPECT_FALSE(s.path_changed);

  // Moving towards (4, 0), then told its current cell: Arrived and one stop.
  robot.assign(2, Cell{4, 0});
  s = robot.step();
  EXPECT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}));
  EXPECT_FALSE(tick_at(robot, truth, {1, 0}, 10.0f).path_changed);
  robot.assign(3, Cell{1, 0});
  s = robot.step();
  ASSERT_TRUE(s.report);
  EXPECT_EQ(*s.report, WaypointState::Arrived);
  EXPECT_EQ(s.round, 3u);
  EXPECT_TRUE(s.path_changed);
  EXPECT_TRUE(s.path.empty());
}

TEST(RobotAgent, NoWaypointStopsAMovingRobotOnceWithoutAReport) {
  const OccupancyGrid truth = swarm::test::grid_from({"....."});
  RobotAgent robot = agent_for(truth);
  tick_at(robot, truth, {0, 0}, 10.0f);
  robot.assign(1, Cell{4, 0});
  EXPECT_TRUE(robot.step().path_changed);
  robot.assign(2, std::nullopt);  // "stay"
  RobotAgent::Step s = robot.step();
  EXPECT_FALSE(s.report);
  EXPECT_TRUE(s.path_changed);
  EXPECT_TRUE(s.path.empty());
  s = robot.step();
  EXPECT_FALSE(s.report);
  EXPECT_FALSE(s.path_changed);
}

TEST(RobotAgent, AWaypointThatTurnsOutOccupiedIsUnreachable) {
  const auto art = ascii_map({"R....#"});  // (5, 0) is a wall; range 2 cells
  const OccupancyGrid& truth = art.grid;
  RobotAgent robot = agent_for(truth);
  // From (0.5, 0.5) the +x beam crosses x = 1, 2 at 0.5, 1.5 and ends at 2.0 inside (2, 0):
  // (5, 0) is Unknown, so the optimistic plan runs straight to it (dy = 0: the only cheapest).
  tick_at(robot, truth, {0, 0}, 2.0f);
  EXPECT_EQ(robot.map().at(Cell{5, 0}), CellState::Unknown);
  robot.assign(4, Cell{5, 0});
  RobotAgent::Step s = robot.step();
  EXPECT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}}));
  // From (1, 0) and (2, 0) the beam ends at 2.0 before x = 5: still Unknown, keep driving.
  for (const Cell at : {Cell{1, 0}, Cell{2, 0}}) {
    s = tick_at(robot, truth, at, 2.0f);
    EXPECT_FALSE(s.report);
    EXPECT_FALSE(s.path_changed);
  }
  // From (3, 0) the beam enters (5, 0) at 1.5 < 2: Occupied -> Unreachable, and one stop.
  s = tick_at(robot, truth, {3, 0}, 2.0f);
  EXPECT_EQ(robot.map().at(Cell{5, 0}), CellState::Occupied);
  ASSERT_TRUE(s.report);
  EXPECT_EQ(*s.report, WaypointState::Unreachable);
  EXPECT_EQ(s.round, 4u);
  EXPECT_TRUE(s.path_changed);
  EXPECT_TRUE(s.path.empty());
  EXPECT_FALSE(robot.waypoint());
  EXPECT_FALSE(tick_at(robot, truth, {3, 0}, 2.0f).path_changed);
}

TEST(RobotAgent, AFreeWaypointWithoutAPathIsUnreachable) {
  // Known map (learned, not scanned): the goal (4, 2) is walled in by (3, 2), (3, 1), (4, 1).
  const OccupancyGrid known = swarm::test::grid_from({
      "...#.",  // y = 2
      "...##",  // y = 1
      ".....",  // y = 0
  });
  RobotAgent robot = agent_for(known);
  std::vector<CellChange> all;
  for (int i = 0; i < static_cast<int>(known.size()); ++i) all.push_back({i, known.at(i)});
  EXPECT_EQ(robot.learn(all), 15);
  std::vector<float> ranges(kBeams);
  planner::scan(known, {0, 0}, kBeams, 10.0f, ranges.data());
  EXPECT_TRUE(robot.sense({0, 0}, ranges, 10.0f).empty());  // nothing new to a full map
  robot.assign(2, Cell{4, 2});
  const RobotAgent::Step s = robot.step();
  ASSERT_TRUE(s.report);
  EXPECT_EQ(*s.report, WaypointState::Unreachable);
  EXPECT_EQ(s.round, 2u);
  EXPECT_FALSE(s.path_changed);  // no path was ever sent, so no stop either
}

TEST(RobotAgent, AWallSeenOnThePathTriggersAReplanAroundIt) {
  const auto art = ascii_map({
      "......",  // y = 1
      "R..#.G",  // y = 0
  });
  const OccupancyGrid& truth = art.grid;
  RobotAgent robot = agent_for(truth);
  // Range 2: from (0, 0) the wall (3, 0) is out of sight (the farthest point is x = 2.5).
  tick_at(robot, truth, {0, 0}, 2.0f);
  EXPECT_EQ(robot.map().at(Cell{3, 0}), CellState::Unknown);
  robot.assign(1, art.at.at('G'));
  RobotAgent::Step s = robot.step();
  const std::vector<Cell> straight = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}};
  EXPECT_EQ(s.path, straight);

  // At (1, 0) the +x beam enters (3, 0) at 1.5 < 2: a wall on the path. Re-planned from (1, 0):
  // (3, 0) can be passed only in row 1, and neither (2,0)->(3,1) nor (3,1)->(4,0) may cut its
  // corner, so the cheapest is (1,0)->(2,1) sqrt2, ->(3,1) 1, ->(4,1) 1, ->(5,0) sqrt2 = 2+2sqrt2;
  // every other way takes at least one more orthogonal step (4 + sqrt2).
  s = tick_at(robot, truth, {1, 0}, 2.0f);
  EXPECT_EQ(robot.map().at(Cell{3, 0}), CellState::Occupied);
  EXPECT_TRUE(s.path_changed);
  const std::vector<Cell> around = {{1, 0}, {2, 1}, {3, 1}, {4, 1}, {5, 0}};
  EXPECT_EQ(s.path, around);
  EXPECT_FALSE(s.report);
  EXPECT_EQ(robot.replans(), 2u);

  for (std::size_t i = 1; i + 1 < around.size(); ++i) {
    EXPECT_FALSE(tick_at(robot, truth, around[i], 2.0f).path_changed) << i;
  }
  s = tick_at(robot, truth, around.back(), 2.0f);
  ASSERT_TRUE(s.report);
  EXPECT_EQ(*s.report, WaypointState::Arrived);
  EXPECT_EQ(robot.replans(), 2u);
}

TEST(RobotAgent, BeingStuckForKStuckTicksStepsTriesADetour) {
  const auto art = ascii_map({
      ".....",  // y = 2
      ".###.",  // y = 1
      "R...G",  // y = 0
  });
  const OccupancyGrid& truth = art.grid;
  RobotAgent robot = agent_for(truth);
  tick_at(robot, truth, {0, 0}, 10.0f);
  // From (0.5, 0.5): the beam at 50 deg enters (1, 1) from (0, 1); beams at 12..18 deg cross
  // y = 1 in x = (2, 3); beams at 9..11 deg cross it in x = (3, 4).
  for (const Cell wall : {Cell{1, 1}, Cell{2, 1}, Cell{3, 1}}) {
    EXPECT_EQ(robot.map().at(wall), CellState::Occupied) << wall.x;
  }
  robot.assign(1, art.at.at('G'));
  RobotAgent::Step s = robot.step();
  const std::vector<Cell> straight = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
  EXPECT_EQ(s.path, straight);

  // The robot does not move (another robot in (1, 0), say). Steps 2..kStuckTicks count 1..3.
  for (int i = 1; i < RobotAgent::kStuckTicks; ++i) {
    s = tick_at(robot, truth, {0, 0}, 10.0f);
    EXPECT_FALSE(s.path_changed) << "stuck step " << i;
    EXPECT_FALSE(s.report);
  }
  // The kStuckTicks-th step without motion: detour with (1, 0) blocked. (1, 1) is a wall and
  // (0,1)->(1,2), (3,2)->(4,1) would cut the walls' corners: the one way is around the ring.
  s = tick_at(robot, truth, {0, 0}, 10.0f);
  EXPECT_TRUE(s.path_changed);
  const std::vector<Cell> detour = {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2},
                                    {3, 2}, {4, 2}, {4, 1}, {4, 0}};
  EXPECT_EQ(s.path, detour);
  EXPECT_FALSE(s.report);
  EXPECT_EQ(robot.replans(), 2u);

  // The count restarts: kStuckTicks more steps in place and it detours around (0, 1) instead,
  // which is the straight path again.
  for (int i = 1; i < RobotAgent::kStuckTicks; ++i) {
    EXPECT_FALSE(tick_at(robot, truth, {0, 0}, 10.0f).path_changed) << i;
  }
  s = tick_at(robot, truth, {0, 0}, 10.0f);
  EXPECT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, straight);
  EXPECT_EQ(robot.replans(), 3u);
}

// Regression: a robot blocked next to its goal used to report Arrived; it never stood on it.
TEST(RobotAgent, StuckWithinTwoCellsOfTheGoalIsBlockedNearNotArrived) {
  const OccupancyGrid truth = swarm::test::grid_from({"......"});
  RobotAgent near = agent_for(truth);
  tick_at(near, truth, {0, 0}, 10.0f);
  near.assign(5, Cell{2, 0});  // Chebyshev distance 2
  EXPECT_TRUE(near.step().path_changed);
  for (int i = 1; i < RobotAgent::kStuckTicks; ++i) EXPECT_FALSE(tick_at(near, truth, {0, 0}, 10.0f).report);
  RobotAgent::Step s = tick_at(near, truth, {0, 0}, 10.0f);
  ASSERT_TRUE(s.report);
  EXPECT_EQ(*s.report, WaypointState::BlockedNear);
  EXPECT_EQ(s.round, 5u);
  EXPECT_TRUE(s.path_changed);
  EXPECT_TRUE(s.path.empty());

  // Three cells away it is not arrived; a 1-cell-high corridor has no detour, so the robot keeps
  // its path and reports nothing.
  RobotAgent far = agent_for(truth);
  tick_at(far, truth, {0, 0}, 10.0f);
  far.assign(5, Cell{3, 0});
  EXPECT_TRUE(far.step().path_changed);
  for (int i = 0; i < 2 * RobotAgent::kStuckTicks; ++i) {
    s = tick_at(far, truth, {0, 0}, 10.0f);
    EXPECT_FALSE(s.report) << i;
    EXPECT_FALSE(s.path_changed) << i;
  }
  EXPECT_EQ(far.waypoint(), (std::optional<Cell>{Cell{3, 0}}));
}

// A corridor of five cells, robot 'A' at its west end.
auto corridor() {
  return ascii_map({
      "#######",
      "#A....#",
      "#######",
  });
}

// One tick of a robot following a route, standing on `at`, the simulator at `step` of the part it
// was sent last.
RobotAgent::Step following_tick(RobotAgent& robot, const OccupancyGrid& truth, Cell at, std::uint32_t step,
                                planner::RouteState state) {
  std::vector<float> ranges(kBeams);
  planner::scan(truth, at, kBeams, 3.0f, ranges.data());
  robot.sense(at, ranges, 3.0f, {robot.route_id(), step, state});
  return robot.step();
}

// A release can arrive before its route (another topic; a lost message is sent again later): it
// is kept, and the route is driven as far as it says when it comes. Releases of other routes
// change nothing.
TEST(RobotAgent, AReleaseThatArrivesBeforeItsRouteIsKeptForIt) {
  const auto art = corridor();
  RobotAgent robot = agent_for(art.grid);
  const Cell a = art.at.at('A');
  const std::vector<Cell> route = {a, {a.x + 1, a.y}, {a.x + 2, a.y}, {a.x + 3, a.y}};
  robot.release(7, 3);  // route 7's release, early
  robot.release(9, 1);  // another route's
  robot.follow(7, route, 1);
  const RobotAgent::Step s = tick_at(robot, art.grid, a, 3.0f);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, route);  // to index 3, not only 1
}

// A robot at the west end of the corridor that follows routes along it.
class RobotInACorridor : public ::testing::Test {
 protected:
  // The corridor's i-th cell from the robot's start.
  Cell along(int i) const { return Cell{start_.x + i, start_.y}; }
  // One tick on `at`, the simulator at `step` of the part the robot was sent last.
  RobotAgent::Step tick(Cell at, std::uint32_t step, planner::RouteState state) {
    return following_tick(robot, art_.grid, at, step, state);
  }

  decltype(corridor()) art_ = corridor();
  Cell start_ = art_.at.at('A');
  RobotAgent robot = agent_for(art_.grid);
};

// A leader extending its plan by the next window sends the route again under its id with more
// cells at its end: the robot keeps its place on it and drives on from where it stands, even after
// it had finished the shorter one; the shorter one arriving after it (link jitter) is ignored.
TEST_F(RobotInACorridor, TheRouteItFollowsGrownAtItsEndIsDrivenOnFromWhereItStands) {
  robot.follow(7, {along(0), along(1), along(2)}, 2);
  RobotAgent::Step s = tick(along(0), 0, planner::RouteState::Active);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(0), along(1), along(2)}));
  (void)tick(along(1), 1, planner::RouteState::Active);
  (void)tick(along(2), 2, planner::RouteState::Finished);
  EXPECT_EQ(robot.following().state, planner::RouteState::Finished);
  EXPECT_EQ(robot.following().step, 2u);

  robot.follow(7, {along(0), along(1), along(2), along(3), along(4)}, 3);
  EXPECT_EQ(robot.following().id, 7u);
  EXPECT_EQ(robot.following().step, 2u);  // its place kept
  EXPECT_EQ(robot.following().state, planner::RouteState::Active);
  s = tick(along(2), 2, planner::RouteState::Finished);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(2), along(3)}));  // as far as released
  robot.release(7, 4);
  s = tick(along(3), 1, planner::RouteState::Finished);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(3), along(4)}));
  EXPECT_EQ(robot.following().step, 3u);

  // The shorter version overtaken on the way changes nothing.
  robot.follow(7, {along(0), along(1), along(2)}, 2);
  EXPECT_EQ(robot.following().step, 3u);
  EXPECT_EQ(robot.following().state, planner::RouteState::Active);

  // The same id with other cells is not its route grown: it starts anew from its first cell.
  robot.follow(7, {along(3), along(2), along(1), along(0)}, 3);
  EXPECT_EQ(robot.following().step, 0u);
}

// A release can reach into the route's next window before the grown route itself comes (they
// travel on different topics, each with its own jitter): it is kept whole, and the robot drives
// that far once the route has grown. Cut at the route's end, it was lost, and the robot stood one
// step short for good (the chain on rectangle with member<->leader delay 3 +- 2 ticks, seed 5:
// collect stalled at 14 of 15 objects, the last drop's cell under that robot).
TEST_F(RobotInACorridor, AReleaseIntoTheNextWindowIsKeptUntilTheRouteGrows) {
  robot.follow(7, {along(0), along(1), along(2)}, 2);
  RobotAgent::Step s = tick(along(0), 0, planner::RouteState::Active);
  ASSERT_TRUE(s.path_changed);
  (void)tick(along(1), 1, planner::RouteState::Active);
  robot.release(7, 4);  // past the route it has: the next window's, early
  s = tick(along(2), 2, planner::RouteState::Finished);
  EXPECT_FALSE(s.path_changed);  // nothing more to drive yet
  robot.follow(7, {along(0), along(1), along(2), along(3), along(4)}, 2);  // grown, released to 2
  s = tick(along(2), 2, planner::RouteState::Finished);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(2), along(3), along(4)}));  // as the early release said
}

// A leader whose plan was cut short sends each changed route under a new id that replaces the
// routes from one id on: the robot keeps its place and drives the new cells, whichever version comes
// first; a version that differs where the robot may already have got (its release) is a new route;
// an older version arriving later is ignored.
TEST_F(RobotInACorridor, ARouteCutShortAndContinuedOtherwiseIsDrivenOnFromWhereItStands) {
  robot.follow(7, {along(0), along(1), along(2), along(3), along(4)}, 2);
  RobotAgent::Step s = tick(along(0), 0, planner::RouteState::Active);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(0), along(1), along(2)}));
  (void)tick(along(1), 1, planner::RouteState::Active);

  // Differs at index 2, which the robot is released to: not a cut it may take.
  RobotAgent before = robot;
  before.follow(9, {along(0), along(1), along(0)}, 2, {}, {}, 0, 7);
  EXPECT_EQ(before.following().id, 9u);
  EXPECT_EQ(before.following().step, 0u);  // a new route, from its first cell

  // Cut after index 2: the robot keeps its place and turns back there.
  robot.follow(10, {along(0), along(1), along(2), along(1), along(0)}, 3, {}, {}, 0, 7);
  EXPECT_EQ(robot.following().id, 10u);
  EXPECT_EQ(robot.following().step, 1u);
  s = tick(along(2), 2, planner::RouteState::Finished);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(2), along(1)}));  // the new cells, as far as released
  EXPECT_EQ(robot.following().step, 2u);

  // A later version, grown, replaces the one followed; the version it grows, late, changes nothing.
  robot.follow(11, {along(0), along(1), along(2), along(1), along(0)}, 4, {}, {}, 0, 7);
  EXPECT_EQ(robot.following().id, 11u);
  robot.follow(10, {along(0), along(1), along(2), along(1)}, 3, {}, {}, 0, 7);
  EXPECT_EQ(robot.following().id, 11u);
  EXPECT_EQ(robot.following().step, 2u);
}

// A route that does not start where the robot stands (its leader saw it a step back) is abandoned,
// and the robot stops instead of driving on along the part of its last route still in the
// simulator; its leader then routes it from where it stands.
TEST(RobotAgent, ARouteNotStartingWhereItStandsIsAbandonedAndTheRobotStops) {
  const auto art = corridor();
  RobotAgent robot = agent_for(art.grid);
  const Cell a = art.at.at('A');
  const auto along = [a](int i) { return Cell{a.x + i, a.y}; };
  robot.follow(7, {along(0), along(1), along(2), along(3)}, 3);
  RobotAgent::Step s = tick_at(robot, art.grid, along(0), 3.0f);
  ASSERT_TRUE(s.path_changed);
  (void)tick_at(robot, art.grid, along(1), 3.0f);
  robot.follow(8, {along(0), along(1), along(2), along(3), along(4)}, 4);  // from where it was
  s = tick_at(robot, art.grid, along(2), 3.0f);
  EXPECT_EQ(robot.following().state, planner::RouteState::Abandoned);
  ASSERT_TRUE(s.path_changed);
  EXPECT_TRUE(s.path.empty());  // stop
}

TEST(RobotAgent, LearnReturnsHowManyCellsChanged) {
  RobotAgent robot(3, 2, 0.2);
  // Cell 0 twice in one patch counts once; cell 1 becomes Occupied.
  EXPECT_EQ(robot.learn({{0, CellState::Free}, {1, CellState::Occupied}, {0, CellState::Free}}), 2);
  EXPECT_EQ(robot.learn({{0, CellState::Free}, {1, CellState::Occupied}}), 0);
  EXPECT_EQ(robot.learn({{1, CellState::Occupied}, {5, CellState::Free}}), 1);
  EXPECT_EQ(robot.map().at(0), CellState::Free);
  EXPECT_EQ(robot.map().at(1), CellState::Occupied);
  EXPECT_EQ(robot.map().at(Cell{2, 1}), CellState::Free);  // index 5 = (2, 1)
  EXPECT_EQ(robot.map().at(Cell{0, 1}), CellState::Unknown);
}

}  // namespace
}  // namespace swarm::member
