// The task seam's plain messages on the wire and back (app/task_wire.hpp): what a task sends is
// what the other side's task receives, and bytes that do not decode are refused.
#include "swarm/app/task_wire.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "swarm/app/convert.hpp"

namespace swarm::app {
namespace {

using planner::Cell;

TEST(TaskWire, AnOrderWithValuesAndRoutesComesBackAsSent) {
  task::Order o;
  o.group = 2;
  o.kind = task::OrderKind::Rotate;
  o.seq = 7;
  o.values = {3, -1, 40};
  o.routes = {{4, {{1, 1}, {2, 1}}, {0}, {1}}, {5, {}}};
  const msgs::TaskOrder m = order_msg(o, 3);
  EXPECT_EQ(m.phase(), 3u);
  const task::Order back = order_from(m);
  EXPECT_EQ(back.group, 2);
  EXPECT_EQ(back.kind, task::OrderKind::Rotate);
  EXPECT_EQ(back.seq, 7u);
  EXPECT_EQ(back.values, o.values);
  ASSERT_EQ(back.routes.size(), 2u);
  EXPECT_EQ(back.routes[0].robot, 4);
  EXPECT_EQ(back.routes[0].path, (std::vector<Cell>{{1, 1}, {2, 1}}));
  EXPECT_EQ(back.routes[0].pick_steps, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(back.routes[0].drop_steps, (std::vector<std::uint32_t>{1}));
  EXPECT_EQ(back.routes[1].robot, 5);
  EXPECT_TRUE(back.routes[1].path.empty());
  EXPECT_TRUE(back.routes[1].pick_steps.empty());
  // Routes that act nowhere send no steps at all.
  o.routes = {{4, {{1, 1}, {2, 1}}}};
  EXPECT_TRUE(order_msg(o, 3).routes_picks().empty());
}

TEST(TaskWire, OrdersThatDoNotDecodeAreRefusedWithTheReason) {
  task::Order o;
  o.values = {1};
  const msgs::TaskOrder good = order_msg(o, 0);
  const auto refused = [&](msgs::TaskOrder m, const std::string& why) {
    try {
      (void)order_from(m);
      ADD_FAILURE() << "accepted; expected: " << why;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  msgs::TaskOrder m = good;
  m.kind(4);  // Resume, retired with the classic collect drive
  refused(m, "unknown kind 4");
  m = good;
  m.kind(9);
  refused(m, "unknown kind 9");
  m = good;
  m.route_robots({1, 2});
  m.routes_xy({{1, 1}});
  refused(m, "names 2 robots for 1 routes");
  m = good;
  m.route_robots({1});
  m.routes_xy({{1, 1, 2}});
  refused(m, "odd number of coordinates");
  m = good;
  m.route_robots({1});
  m.routes_xy({{1, 1, 2, 1}});
  m.routes_picks({{0}});
  refused(m, "gives pick-up and drop steps for 1 and 0 of its 1 routes");
  m.routes_drops({{2}});
  refused(m, "acts at step 2 of 2");
}

TEST(TaskWire, AReportComesBackAsSentAndAnUnknownStateIsRefused) {
  task::Report r;
  r.group = 1;
  r.state = task::GroupState::Held;
  r.cells = {{2, 1}, {3, 1}};
  r.values = {5, 6};
  const msgs::TaskReport m = report_msg(r, 4);
  EXPECT_EQ(m.phase(), 4u);
  const task::Report back = report_from(m);
  EXPECT_EQ(back.group, 1);
  EXPECT_EQ(back.state, task::GroupState::Held);
  EXPECT_EQ(back.cells, r.cells);
  EXPECT_EQ(back.values, r.values);
  msgs::TaskReport bad = m;
  bad.state(3);
  EXPECT_THROW(report_from(bad), std::runtime_error);
}

TEST(TaskWire, ARouteCarriesEveryFieldAndTheNodesNumbering) {
  task::Route r;
  r.path = {{1, 1}, {2, 1}, {3, 1}};
  r.release = 1;
  r.pick_steps = {1};
  r.drop_steps = {2};
  r.start_tick = 30;
  r.replaces = 97;
  const msgs::Route m = route_msg(r, 2, 5, 99);
  EXPECT_EQ(m.phase(), 2u);
  EXPECT_EQ(m.robot(), 5);
  EXPECT_EQ(m.route_id(), 99u);
  EXPECT_EQ(from_xy(m.path_xy()), r.path);
  EXPECT_EQ(m.release(), 1u);
  EXPECT_EQ(m.pick_steps(), r.pick_steps);
  EXPECT_EQ(m.drop_steps(), r.drop_steps);
  EXPECT_EQ(m.start_tick(), 30u);
  EXPECT_EQ(m.replaces(), 97u);
}

TEST(TaskWire, AReleaseCarriesItsWatchAndAWatchThatDoesNotFitIsRefused) {
  planner::mapf::Watch w;
  w.robots = {7, 2};
  w.routes = {{{1, 1}, {2, 1}, {3, 1}}, {{5, 5}, {5, 6}}};
  w.gates = {{4, {1, 0}}, {5, {2, 1}}};
  const msgs::RouteRelease m = release_msg(6, 99, 3, w);
  EXPECT_EQ(m.robot(), 6);
  EXPECT_EQ(m.route_id(), 99u);
  EXPECT_EQ(m.release(), 3u);
  EXPECT_EQ(watch_from(m), w);
  EXPECT_EQ(watch_from(release_msg(6, 99, 3, {})), planner::mapf::Watch{});  // a release alone
  msgs::RouteRelease short_gates = m;
  short_gates.gate_reached().pop_back();
  EXPECT_THROW(watch_from(short_gates), std::runtime_error);
  msgs::RouteRelease short_route = m;
  short_route.watch_lengths()[1] = 3;
  EXPECT_THROW(watch_from(short_route), std::runtime_error);
  msgs::RouteRelease unpaired = m;
  unpaired.watch_lengths().pop_back();
  EXPECT_THROW(watch_from(unpaired), std::runtime_error);
}

TEST(TaskWire, TheClockGivesEveryRobotAndEachGroupsLeader) {
  const comm::Topology t(2, 2);
  msgs::Clock c;
  c.tick(12);
  c.robots({msgs::RobotState{}, msgs::RobotState{}, msgs::RobotState{}, msgs::RobotState{}});
  c.robots()[3].x(4);
  c.robots()[3].y(2);
  c.robots()[3].alive(true);
  const task::Clock without = task_clock(c, t);  // a hand-made clock names no leaders
  EXPECT_EQ(without.tick, 12u);
  ASSERT_EQ(without.robots.size(), 4u);
  EXPECT_EQ(without.robots[3].cell, (Cell{4, 2}));
  EXPECT_TRUE(without.robots[3].alive);
  EXPECT_FALSE(without.robots[0].alive);
  EXPECT_EQ(without.leaders, (std::vector<int>{static_cast<int>(t.leader(0)), static_cast<int>(t.leader(1))}));
  c.leaders({static_cast<std::uint16_t>(t.leader(0)), 3});
  EXPECT_EQ(task_clock(c, t).leaders[1], 3);
}

}  // namespace
}  // namespace swarm::app
