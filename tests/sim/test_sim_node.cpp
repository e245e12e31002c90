// The simulator node on the FakeBus: routes from the robots' agents are applied one tick after
// they are sent, every Sense reports the route's progress, and conflicts are counted.
#include "swarm/sim/sim_node.hpp"

#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "swarm/app/convert.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"

namespace swarm::sim {
namespace {

using comm::LinkClass;
using planner::Cell;
namespace topic = comm::topic;

swarm::scenario::Scenario one_group_of(int robots) {
  swarm::scenario::Scenario s;
  s.set_groups(1);
  s.set_robots_per_group(static_cast<std::uint32_t>(robots));
  s.set_sensing_range_m(0.6);
  s.set_max_ticks(40);
  return s;
}

// Every robot is a scripted agent that sends the routes a test gives it and keeps its Senses.
struct Robots {
  explicit Robots(swarm::test::FakeSwarm& s) : swarm(s) {
    const auto& t = s.topology();
    for (comm::AgentId r : t.robot_ids()) {
      auto& agent = s.agent(r);
      agent.subscribe<msgs::Sense>(topic::sense(r), LinkClass::SimRobot,
                                   [this, r](const msgs::Sense& m) { senses[r].push_back(m); },
                                   comm::Delivery::BestEffort, 1);
      motion[r] = &agent.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {t.sim()});
      s.script(r, [this, r](const msgs::Clock& c) {
        auto it = routes.find({r, c.tick()});
        if (it == routes.end()) return;
        msgs::MotionCommand m;
        m.robot(r);
        m.route_id(it->second.first);
        m.path_xy(app::to_xy(it->second.second));
        motion[r]->send(m);
      });
    }
  }
  // Robot r sends route `id` at tick `tick`.
  void send(comm::AgentId r, std::uint32_t tick, std::uint32_t id, std::vector<Cell> route) {
    routes[{r, tick}] = {id, std::move(route)};
  }
  swarm::test::FakeSwarm& swarm;
  std::map<comm::AgentId, std::vector<msgs::Sense>> senses;
  std::map<comm::AgentId, comm::Mailbox::Outlet<msgs::MotionCommand>*> motion;
  std::map<std::pair<comm::AgentId, std::uint32_t>, std::pair<std::uint32_t, std::vector<Cell>>> routes;
};

std::set<comm::AgentId> everyone_but_the_sim(const comm::Topology& t) {
  std::set<comm::AgentId> all;
  for (comm::AgentId a : t.all_but_sim()) all.insert(a);
  return all;
}

TEST(SimNode, ARouteSentAtTickTMovesTheRobotFromTickTPlus1AndSenseReportsItsProgress) {
  const auto art = swarm::test::ascii_map({
      "......",
      "S.....",
  });
  auto setup = swarm::test::setup_for(art.grid, art.at.at('S'), one_group_of(1));
  swarm::test::FakeSwarm s(setup, everyone_but_the_sim(setup.topology));
  Robots robots(s);
  robots.send(0, 2, 5, {{0, 0}, {1, 0}, {1, 0}, {2, 0}});  // a step, a wait, a step
  s.start();
  for (int k = 0; k < 7; ++k) s.step();
  const auto& sense = robots.senses[0];
  ASSERT_EQ(sense.size(), 7u);
  // Ticks 0..2: no route applied yet. Tick 3: applied, one step done.
  EXPECT_EQ(sense[2].route_state(), static_cast<std::uint8_t>(planner::RouteState::None));
  const std::vector<std::pair<int, int>> expect = {{1, 1}, {1, 2}, {2, 3}, {2, 3}};  // (x, step) at ticks 3..6
  for (int k = 3; k < 7; ++k) {
    EXPECT_EQ(sense[k].x(), expect[k - 3].first) << "tick " << k;
    EXPECT_EQ(sense[k].route_id(), 5u);
    EXPECT_EQ(sense[k].route_step(), static_cast<std::uint32_t>(expect[k - 3].second)) << "tick " << k;
  }
  EXPECT_EQ(sense[5].route_state(), static_cast<std::uint8_t>(planner::RouteState::Finished));
  EXPECT_EQ(s.sim().world().total_counts().waits, 1u);
}

TEST(SimNode, TwoRobotsMeaningToSwapAreAnEdgeConflictEveryTickTheyTry) {
  const auto art = swarm::test::ascii_map({"S..."});
  auto setup = swarm::test::setup_for(art.grid, art.at.at('S'), one_group_of(2));
  ASSERT_EQ(setup.world.robot_cells[1], (Cell{1, 0}));
  swarm::test::FakeSwarm s(setup, everyone_but_the_sim(setup.topology));
  Robots robots(s);
  robots.send(0, 0, 1, {{0, 0}, {1, 0}});
  robots.send(1, 0, 1, {{1, 0}, {0, 0}});
  s.start();
  for (int k = 0; k < 4; ++k) s.step();  // ticks 1, 2, 3 try the swap
  EXPECT_EQ(s.sim().world().events().edge, 3u);
  EXPECT_EQ(s.sim().world().robots()[0], (Cell{0, 0}));
  EXPECT_EQ(robots.senses[1].back().route_state(), static_cast<std::uint8_t>(planner::RouteState::Active));
}

}  // namespace
}  // namespace swarm::sim
