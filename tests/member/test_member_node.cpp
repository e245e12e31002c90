// The member node on the FakeBus, with a scripted leader: it drives the route it is given exactly
// and reports its progress, sending its map changes up meanwhile.
#include "swarm/member/member_node.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "swarm/app/convert.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"

namespace swarm::member {
namespace {

using comm::LinkClass;
using planner::Cell;
namespace topic = comm::topic;

// A leader and one member (robot 1 starts at (2, 1)) in a 5 x 2 room.
app::RoleSetup two_robots_in_a_room() {
  const auto art = swarm::test::ascii_map({
      "#######",
      "#.....#",
      "#S....#",
      "#######",
  });
  swarm::scenario::Scenario sc;
  sc.set_groups(1);
  sc.set_robots_per_group(2);
  sc.set_max_ticks(60);
  return swarm::test::setup_for(art.grid, art.at.at('S'), sc);
}

// A timed route with a wait and a cell passed twice (issue 13, item 2): the member drives it to
// its end exactly, and its progress messages name the route and climb to its last step.
TEST(MemberNode, FollowsARouteWithAWaitAndARevisitAndReportsItsProgress) {
  auto setup = two_robots_in_a_room();
  const comm::Topology& t = setup.topology;
  swarm::test::FakeSwarm s(setup, {t.leader(0), t.gcs()});
  const Cell start = setup.world.robot_cells[1];
  ASSERT_EQ(start, (Cell{2, 1}));
  ASSERT_NE(setup.world.robot_cells[0], (Cell{3, 1}));
  ASSERT_NE(setup.world.robot_cells[0], (Cell{4, 1}));
  // A wait at the start, then right, right, back (a cell passed twice) and right again.
  const std::vector<Cell> route = {{2, 1}, {2, 1}, {3, 1}, {4, 1}, {3, 1}, {4, 1}};

  auto& leader = s.agent(t.leader(0));
  std::vector<msgs::RouteProgress> progress;
  std::uint64_t patches = 0;
  leader.subscribe<msgs::Sense>(topic::sense(t.leader(0)), LinkClass::SimRobot, [](const msgs::Sense&) {},
                                comm::Delivery::BestEffort, 1);
  leader.subscribe<msgs::MapPatch>(topic::patch_up(0), LinkClass::MemberLeader,
                                   [&](const msgs::MapPatch& p) { patches += !app::decode_patch(p.data(), 1u << 20).empty(); },
                                   comm::Delivery::Reliable, 1);
  leader.subscribe<msgs::RouteProgress>(topic::progress(0), LinkClass::MemberLeader,
                                        [&](const msgs::RouteProgress& p) { progress.push_back(p); },
                                        comm::Delivery::Reliable, 1);
  auto& routes = leader.advertise<msgs::Route>(topic::route(0), LinkClass::MemberLeader, {t.robot(0, 1)});
  leader.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {t.sim()});  // its robot stays
  s.script(t.leader(0), [&](const msgs::Clock& c) {
    if (c.tick() != 2) return;
    msgs::Route r;
    r.robot(t.robot(0, 1));
    r.route_id(7);
    r.path_xy(app::to_xy(route));
    r.release(static_cast<std::uint32_t>(route.size() - 1));
    routes.send(r);
  });

  s.start();
  ASSERT_TRUE(s.run_until(
      [&] { return !progress.empty() && progress.back().state() == static_cast<std::uint8_t>(planner::RouteState::Finished); },
      50));
  EXPECT_EQ(s.sim().world().robots()[1], (Cell{4, 1}));
  const auto counts = s.sim().world().total_counts();
  EXPECT_EQ(counts.moves, 4u);  // (2,1)->(3,1)->(4,1)->(3,1)->(4,1)
  EXPECT_GE(counts.waits, 1u);  // the planned wait is a wait, not a wall stop
  EXPECT_EQ(counts.wall_stops, 0u);
  for (std::size_t i = 0; i < progress.size(); ++i) {
    EXPECT_EQ(progress[i].route_id(), 7u);
    if (i > 0) {
      EXPECT_GE(progress[i].step(), progress[i - 1].step());
    }
  }
  EXPECT_EQ(progress.back().step(), route.size() - 1);
  EXPECT_GT(patches, 0u);  // its scans went up as map changes
}

}  // namespace
}  // namespace swarm::member
