// A release's watch (planner/mapf/release_watch.hpp) on hand-made plans: a follower's gates, the
// gate limit, a robot that needs two others, a rotation, and looks that are missed or out of order.
// tests/sim/test_adg_drive.cpp drives solvers' plans by watches through the simulator's moves.
#include <gtest/gtest.h>

#include "swarm/planner/mapf/release_watch.hpp"

namespace {

using swarm::planner::Cell;
using namespace swarm::planner::mapf;

// Robot 1 follows robot 0 along a row, one cell behind: each of its steps waits for robot 0 to
// have left the cell.
const std::vector<Path> kFile{{{1, 0}, {2, 0}, {3, 0}, {4, 0}}, {{0, 0}, {1, 0}, {2, 0}, {3, 0}}};

TEST(ReleaseWatch, AFollowerGetsAGateForEachStepOfTheRobotAhead) {
  const Dependencies d = dependencies(kFile);
  ASSERT_EQ(releasable(d, 1, {0, 0}), 0u);
  const Watch w = watch_release(d, 1, {0, 0}, 8);
  EXPECT_EQ(w.robots, (std::vector<int>{0}));
  EXPECT_EQ(w.routes, (std::vector<std::vector<Cell>>{{{1, 0}, {2, 0}, {3, 0}, {4, 0}}}));
  EXPECT_EQ(w.gates, (std::vector<Gate>{{1, {1}}, {2, {2}}, {3, {3}}}));
  // From a later progress the watched route starts where robot 0 is known to be.
  const Watch later = watch_release(d, 1, {2, 1}, 8);
  EXPECT_EQ(later.routes, (std::vector<std::vector<Cell>>{{{3, 0}, {4, 0}}}));
  EXPECT_EQ(later.gates, (std::vector<Gate>{{3, {1}}}));
  // At most as many gates as asked for; none for the robot ahead, which waits on nobody.
  EXPECT_EQ(watch_release(d, 1, {0, 0}, 2).gates, (std::vector<Gate>{{1, {1}}, {2, {2}}}));
  EXPECT_EQ(watch_release(d, 1, {0, 0}, 2).routes[0].size(), 3u);
  EXPECT_TRUE(watch_release(d, 0, {0, 0}, 8).gates.empty());
  EXPECT_TRUE(watch_release(d, 1, {3, 0}, 8).gates.empty());  // released to its end already
  // Its leader knows less of robot 0 than of robot 1, which has made 2 steps: the gates of those
  // steps are there (the caller drops them), and the last holds the needs of all.
  const Watch behind = watch_release(d, 1, {0, 2}, 8);
  EXPECT_EQ(behind.gates, (std::vector<Gate>{{1, {1}}, {2, {2}}, {3, {3}}}));
}

TEST(ReleaseWatch, AGateOpensOnlyOnStepsSeenOneAtATime) {
  const Dependencies d = dependencies(kFile);
  const Watch w = watch_release(d, 1, {0, 0}, 8);
  ReleaseWatch rw(w.routes, w.gates);
  rw.see({{1, 0}});  // still on its known cell
  EXPECT_EQ(rw.opened(), 0u);
  rw.see({{2, 0}});  // robot 0 has left (1, 0)
  EXPECT_EQ(rw.opened(), 1u);
  rw.see({{4, 0}});  // a look missed: (3, 0) was never seen, so nothing further counts
  EXPECT_EQ(rw.opened(), 1u);
  rw.see({{3, 0}});
  EXPECT_EQ(rw.opened(), 2u);
  rw.see({{4, 0}});
  EXPECT_EQ(rw.opened(), 3u);
  EXPECT_TRUE(rw.all_open());
}

TEST(ReleaseWatch, AStepThatNeedsTwoRobotsOpensWhenBothHaveGone) {
  // Robot 2 enters (1, 1) at time 2 after robot 0 (time 0) and robot 1 (time 1) were there.
  const std::vector<Path> plan{{{1, 1}, {2, 1}, {3, 1}, {3, 1}},
                               {{1, 2}, {1, 1}, {0, 1}, {0, 1}},
                               {{1, 0}, {1, 0}, {1, 0}, {1, 1}}};
  const Dependencies d = dependencies(plan);
  const Watch w = watch_release(d, 2, {0, 0, 0}, 8);
  ASSERT_EQ(w.gates.size(), 1u);
  EXPECT_EQ(w.gates[0].release, 1u);
  // Where each watched robot stands, in the watch's order of robots.
  const auto look = [&w](Cell of0, Cell of1) {
    std::vector<Cell> at;
    for (int r : w.robots) at.push_back(r == 0 ? of0 : of1);
    return at;
  };
  ReleaseWatch rw(w.routes, w.gates);
  rw.see(look({2, 1}, {1, 1}));  // robot 0 has gone, robot 1 stands on the cell
  EXPECT_EQ(rw.opened(), 0u);
  rw.see(look({3, 1}, {0, 1}));
  EXPECT_EQ(rw.opened(), 1u);
}

TEST(ReleaseWatch, ARotationIsLeftToTheGcs) {
  // Four robots round the 2 x 2 square in one step: a joint action, never a watch's.
  const std::vector<Path> plan{{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}}, {{0, 1}, {0, 0}}};
  const Dependencies d = dependencies(plan);
  for (int r = 0; r < 4; ++r) EXPECT_TRUE(watch_release(d, r, {0, 0, 0, 0}, 8).gates.empty()) << r;
}

TEST(ReleaseWatch, GatesThatDoNotFitTheirRobotsNeverOpen) {
  ReleaseWatch rw({{{0, 0}, {1, 0}}}, {{1, {1, 1}}});  // a gate naming two robots of one
  rw.see({{1, 0}});
  EXPECT_EQ(rw.opened(), 0u);
  ReleaseWatch past_end({{{0, 0}, {1, 0}}}, {{4, {5}}});
  past_end.see({{1, 0}});
  past_end.see({{1, 0}});
  EXPECT_EQ(past_end.opened(), 0u);
}

}  // namespace
