#include "swarm/member/robot_agent.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// The simulator's side of these tests: the part of its route the robot sent last, and what the
// simulator would report on it with the robot at `at` (the part's first cell at `at`; tests move
// robots by hand along parts that never pass a cell twice).
struct SentPart {
  std::vector<Cell> cells;
  std::uint32_t id = 0;
  planner::RouteProgress report_at(Cell at) const {
    planner::RouteProgress r;
    r.id = id;
    if (cells.empty()) {
      r.state = planner::RouteState::Stopped;
      return r;
    }
    const auto it = std::find(cells.begin(), cells.end(), at);
    r.step = it == cells.end() ? 0 : static_cast<std::uint32_t>(it - cells.begin());
    r.state = it == cells.end()         ? planner::RouteState::Rejected
              : it + 1 == cells.end() ? planner::RouteState::Finished
                                      : planner::RouteState::Active;
    return r;
  }
};

// One tick of a robot's loop as swarm-member runs it: the simulator's scan of the truth from
// `at` is integrated with the simulator's report on the part sent last, then the agent steps.
RobotAgent::Step tick_at(RobotAgent& robot, SentPart& sent, const OccupancyGrid& truth, Cell at, float range) {
  std::vector<float> ranges(kBeams);
  planner::scan(truth, at, kBeams, range, ranges.data());
  robot.sense(at, ranges, range, sent.report_at(at));
  RobotAgent::Step s = robot.step();
  if (s.path_changed) sent = {s.path, s.route_id};
  return s;
}

RobotAgent agent_for(const OccupancyGrid& truth) {
  return RobotAgent(truth.width(), truth.height(), truth.resolution());
}

TEST(RobotAgent, SenseMapsWhatTheScanSeesAndReturnsExactlyTheCellsItChanged) {
  const auto art = ascii_map({
      "##.##",  // y = 4
      "##.##",  // y = 3: the only way up is the gap (2, 3)
      ".....",  // y = 2
      ".....",  // y = 1
      "R....",  // y = 0
  });
  const Cell start = art.at.at('R');  // (0, 0)
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
  // The same scan again changes nothing; a robot with no route sends the simulator nothing.
  EXPECT_TRUE(robot.sense(start, ranges, 10.0f).empty());
  EXPECT_FALSE(robot.step().path_changed);
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
  SentPart sent;
  const RobotAgent::Step s = tick_at(robot, sent, art.grid, a, 3.0f);
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

// A pick-up or drop on the cell the robot stands on as its route starts is made at once, even
// before the robot may go on (or on a route of that one cell), and counted as made only once the
// simulator has taken the part that carries it: a robot lost before that never made it, and its
// leader and the GCS must not count it (tasks/mapf/mapf_gcs.hpp). Before, an unreleased route
// sent nothing, and a one-cell route nothing ever.
TEST_F(RobotInACorridor, AnActWhereTheRouteStartsIsMadeAtOnceAndCountedOnceTheSimulatorTookIt) {
  robot.follow(7, {along(0), along(1), along(2)}, 0, {0});  // pick up here; not released yet
  RobotAgent::Step s = tick(along(0), 0, planner::RouteState::None);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(0)}));
  EXPECT_EQ(s.pick_steps, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(robot.following().acted, 0u);  // on its way to the simulator
  EXPECT_EQ(robot.following().state, planner::RouteState::Active);
  s = tick(along(0), 0, planner::RouteState::Finished);  // the simulator took it
  EXPECT_FALSE(s.path_changed);
  EXPECT_EQ(robot.following().acted, 1u);
  robot.release(7, 2);
  s = tick(along(0), 0, planner::RouteState::Finished);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(0), along(1), along(2)}));
  EXPECT_TRUE(s.pick_steps.empty());  // made already
  (void)tick(along(1), 1, planner::RouteState::Active);
  EXPECT_EQ(robot.following().acted, 2u);

  // A route of one cell: its act is sent, and counted once taken; without an act nothing is sent.
  robot.follow(8, {along(1)}, 0, {}, {0});
  s = tick(along(1), 1, planner::RouteState::Active);
  ASSERT_TRUE(s.path_changed);
  EXPECT_EQ(s.path, (std::vector<Cell>{along(1)}));
  EXPECT_EQ(s.drop_steps, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(robot.following().state, planner::RouteState::Finished);
  EXPECT_EQ(robot.following().acted, 0u);
  (void)tick(along(1), 0, planner::RouteState::Finished);
  EXPECT_EQ(robot.following().acted, 1u);
  robot.follow(9, {along(1)}, 0);
  EXPECT_FALSE(tick(along(1), 0, planner::RouteState::Finished).path_changed);
  EXPECT_EQ(robot.following().state, planner::RouteState::Finished);

  // A route without acts is not counted: each new count would be a report to the leader.
  robot.follow(10, {along(1), along(2)}, 1);
  s = tick(along(1), 0, planner::RouteState::Finished);
  ASSERT_TRUE(s.path_changed);
  (void)tick(along(2), 1, planner::RouteState::Finished);
  EXPECT_EQ(robot.following().step, 1u);
  EXPECT_EQ(robot.following().acted, 0u);
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
  SentPart sent;
  RobotAgent::Step s = tick_at(robot, sent, art.grid, along(0), 3.0f);
  ASSERT_TRUE(s.path_changed);
  (void)tick_at(robot, sent, art.grid, along(1), 3.0f);
  robot.follow(8, {along(0), along(1), along(2), along(3), along(4)}, 4);  // from where it was
  s = tick_at(robot, sent, art.grid, along(2), 3.0f);
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
