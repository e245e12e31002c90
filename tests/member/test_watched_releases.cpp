// A member's watches (member/watched_releases.hpp): a watch that arrives late is followed from its
// own tick through the clocks kept meanwhile; an older watch, or one on an older route, does not
// replace the one held; each opening is handed out once.
#include "swarm/member/watched_releases.hpp"

#include <gtest/gtest.h>

namespace swarm::member {
namespace {

using planner::Cell;

// Robot 3 is watched along (1, 0) (2, 0) (3, 0); the route opens to step 4 when it has left
// (1, 0), and to step 5 when it has left (2, 0).
planner::mapf::Watch file_watch() {
  planner::mapf::Watch w;
  w.robots = {3};
  w.routes = {{{1, 0}, {2, 0}, {3, 0}}};
  w.gates = {{4, {1}}, {5, {2}}};
  return w;
}

// Every robot's cell, robot 3 at `at` (the others out of the way).
std::vector<Cell> clock_with(Cell at) { return {{9, 9}, {9, 8}, {9, 7}, at}; }

TEST(WatchedReleases, ALateWatchIsFollowedFromItsOwnTick) {
  WatchedReleases w;
  w.see(10, clock_with({1, 0}));
  w.see(11, clock_with({2, 0}));  // robot 3 left (1, 0) while the watch was on its way
  w.see(12, clock_with({3, 0}));
  EXPECT_FALSE(w.opened());
  w.watch(40, 10, file_watch());  // made at tick 10
  const auto open = w.opened();
  ASSERT_TRUE(open);
  EXPECT_EQ(open->route_id, 40u);
  EXPECT_EQ(open->release, 5u);
  EXPECT_FALSE(w.opened());  // handed out once
  EXPECT_EQ(w.releases_opened(), 1u);
}

TEST(WatchedReleases, EachGateOpensInTheTickItsRobotIsSeenGone) {
  WatchedReleases w;
  w.see(10, clock_with({1, 0}));
  w.watch(40, 10, file_watch());
  EXPECT_FALSE(w.opened());
  w.see(11, clock_with({1, 0}));
  EXPECT_FALSE(w.opened());
  w.see(12, clock_with({2, 0}));
  EXPECT_EQ(w.opened()->release, 4u);
  w.see(13, clock_with({3, 0}));
  EXPECT_EQ(w.opened()->release, 5u);
}

TEST(WatchedReleases, AnOlderWatchOrOneOnAnOlderRouteIsIgnored) {
  WatchedReleases w;
  w.see(10, clock_with({1, 0}));
  w.watch(40, 12, file_watch());
  planner::mapf::Watch older = file_watch();
  older.gates = {{9, {1}}};
  w.watch(40, 11, older);  // made before the one held: overtaken on the way
  w.watch(39, 13, older);  // for a route replaced since
  w.see(13, clock_with({2, 0}));
  EXPECT_EQ(w.opened()->release, 4u);
  w.watch(41, 13, older);  // a new route's watch replaces it
  w.see(14, clock_with({2, 0}));
  EXPECT_EQ(w.opened()->release, 9u);
}

TEST(WatchedReleases, OnlyTheLastTicksAreKept) {
  WatchedReleases w;
  w.see(0, clock_with({1, 0}));
  w.see(1, clock_with({2, 0}));
  for (std::uint32_t t = 2; t < 2 * WatchedReleases::kTicksKept; ++t) w.see(t, clock_with({3, 0}));
  // Its ticks are gone, and robot 3 is two steps on: the step between was never seen, so nothing
  // opens (late, never early; the leader's own releases still come).
  w.watch(40, 0, file_watch());
  EXPECT_FALSE(w.opened());
}

}  // namespace
}  // namespace swarm::member
