// The task seam's plain messages on the wire and back (app/task_wire.hpp): what a task sends is
// what the other side's task receives, and bytes that do not decode are refused.
#include "swarm/app/task_wire.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "swarm/app/convert.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace swarm::app {
namespace {

using planner::Cell;

const planner::OccupancyGrid& hall() {
  static const planner::OccupancyGrid g = swarm::test::grid_from({"#######", "#.....#", "#..#..#", "#######"});
  return g;
}

config::MapFrame frame() { return config::MapFrame::of(hall()); }

TEST(TaskWire, AnOrderWithMapCellsValuesAndRoutesComesBackAsSent) {
  task::Order o;
  o.group = 2;
  o.kind = task::OrderKind::Resume;
  o.seq = 7;
  o.known_map = hall();
  o.cells.assign(hall().size(), 0);
  o.cells[8] = o.cells[9] = 1;
  o.values = {3, -1, 40};
  o.routes = {{4, {{1, 1}, {2, 1}}, {0}, {1}}, {5, {}}};
  for (const auto encoding : {planner::PatchEncoding::RunLength, planner::PatchEncoding::ZstdRunLength}) {
    const msgs::TaskOrder m = order_msg(o, 3, encoding);
    EXPECT_EQ(m.phase(), 3u);
    EXPECT_EQ(m.map_encoding(), static_cast<std::uint8_t>(encoding));
    EXPECT_EQ(m.width(), 7);
    EXPECT_EQ(m.height(), 4);
    const task::Order back = order_from(m, frame());
    EXPECT_EQ(back.group, 2);
    EXPECT_EQ(back.kind, task::OrderKind::Resume);
    EXPECT_EQ(back.seq, 7u);
    ASSERT_TRUE(back.known_map.has_value());
    for (int i = 0; i < static_cast<int>(hall().size()); ++i) EXPECT_EQ(back.known_map->at(i), hall().at(i)) << i;
    EXPECT_EQ(back.cells, o.cells);
    EXPECT_EQ(back.values, o.values);
    ASSERT_EQ(back.routes.size(), 2u);
    EXPECT_EQ(back.routes[0].robot, 4);
    EXPECT_EQ(back.routes[0].path, (std::vector<Cell>{{1, 1}, {2, 1}}));
    EXPECT_EQ(back.routes[0].pick_steps, (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(back.routes[0].drop_steps, (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(back.routes[1].robot, 5);
    EXPECT_TRUE(back.routes[1].path.empty());
    EXPECT_TRUE(back.routes[1].pick_steps.empty());
  }
  // Routes that act nowhere send no steps at all.
  o.routes = {{4, {{1, 1}, {2, 1}}}};
  EXPECT_TRUE(order_msg(o, 3, planner::PatchEncoding::RunLength).routes_picks().empty());
}

TEST(TaskWire, TheMapCacheEncodesAMapOnceAndAChangedMapAgain) {
  task::Order o;
  o.known_map = hall();
  EncodedMapCache cache;
  const auto zstd = planner::PatchEncoding::ZstdRunLength;
  const msgs::TaskOrder first = order_msg(o, 0, zstd, &cache);
  EXPECT_EQ(first.known_map(), encode_map(hall(), zstd));
  ASSERT_TRUE(cache.map.has_value());
  // The same map again: the cached bytes (poisoned here to see that they are the ones sent).
  cache.bytes = {42};
  EXPECT_EQ(order_msg(o, 0, zstd, &cache).known_map(), (std::vector<std::uint8_t>{42}));
  // Another encoding, or another map, is encoded afresh.
  EXPECT_EQ(order_msg(o, 0, planner::PatchEncoding::RunLength, &cache).known_map(),
            encode_map(hall(), planner::PatchEncoding::RunLength));
  o.known_map->set(Cell{1, 1}, planner::CellState::Occupied);
  const msgs::TaskOrder changed = order_msg(o, 0, planner::PatchEncoding::RunLength, &cache);
  EXPECT_EQ(changed.known_map(), encode_map(*o.known_map, planner::PatchEncoding::RunLength));
  EXPECT_EQ(order_from(changed, frame()).known_map->at(Cell{1, 1}), planner::CellState::Occupied);
}

TEST(TaskWire, AnOrderWithoutAMapLeavesTheMapFieldsEmpty) {
  task::Order o;
  o.group = task::kAllGroups;
  o.kind = task::OrderKind::Hold;
  o.values = {1};
  const msgs::TaskOrder m = order_msg(o, 0, planner::PatchEncoding::RunLength);
  EXPECT_EQ(m.width(), 0);
  EXPECT_EQ(m.height(), 0);
  EXPECT_EQ(m.map_encoding(), 0);
  EXPECT_TRUE(m.known_map().empty());
  EXPECT_TRUE(m.cells().empty());
  const task::Order back = order_from(m, frame());
  EXPECT_FALSE(back.known_map.has_value());
  EXPECT_EQ(back.group, task::kAllGroups);
  EXPECT_EQ(back.kind, task::OrderKind::Hold);
  // A cell set means nothing without its map.
  o.cells = {1};
  EXPECT_THROW(order_msg(o, 0, planner::PatchEncoding::RunLength), std::logic_error);
}

TEST(TaskWire, OrdersThatDoNotDecodeAreRefusedWithTheReason) {
  task::Order o;
  o.known_map = hall();
  o.cells.assign(hall().size(), 1);
  const msgs::TaskOrder good = order_msg(o, 0, planner::PatchEncoding::RunLength);
  const auto refused = [&](msgs::TaskOrder m, const std::string& why) {
    try {
      (void)order_from(m, frame());
      ADD_FAILURE() << "accepted; expected: " << why;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  msgs::TaskOrder m = good;
  m.width(9);
  refused(m, "an order for a 9 x 4 map; the run's map is 7 x 4");
  m = good;
  m.cells({0xff, 0xff, 0xff});
  refused(m, "does not decode to 7 x 4 cells");
  m = good;
  m.known_map({7, 1, 200, 3});
  refused(m, "malformed global map");
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
  const msgs::Route m = route_msg(r, 2, 5, 99);
  EXPECT_EQ(m.phase(), 2u);
  EXPECT_EQ(m.robot(), 5);
  EXPECT_EQ(m.route_id(), 99u);
  EXPECT_EQ(from_xy(m.path_xy()), r.path);
  EXPECT_EQ(m.release(), 1u);
  EXPECT_EQ(m.pick_steps(), r.pick_steps);
  EXPECT_EQ(m.drop_steps(), r.drop_steps);
  EXPECT_EQ(m.start_tick(), 30u);
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
