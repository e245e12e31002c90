// The leader node on the FakeBus with its real members and a scripted GCS: given a global map with
// one unexplored region, it plans case B (no group frontiers) and assigns its three robots three
// distinct frontier cells of that region, nearest first as the Hungarian assignment says.
// Exploration here is the paper's drive (`traffic: false`), where the leader sends its robots
// their waypoints: what these tests watch. Through the traffic layer the waypoints go to the GCS
// (tests/tasks/test_explore.cpp).
#include "swarm/leader/leader_node.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm/planner/explore/explore.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"

namespace swarm::leader {
namespace {

using comm::LinkClass;
using planner::Cell;
using planner::CellState;
namespace topic = comm::topic;

// A 30 x 7 hall; the robots start at its west end.
planner::OccupancyGrid hall() {
  std::vector<std::string> rows(7, std::string(30, '.'));
  for (auto& r : rows) r.front() = r.back() = '#';
  rows.front() = rows.back() = std::string(30, '#');
  return swarm::test::grid_from(rows);
}

TEST(LeaderNode, PlansCaseBOnTheGlobalMapAndAssignsEachRobotAFrontierCellOfTheRegion) {
  const planner::OccupancyGrid truth = hall();
  swarm::scenario::Scenario sc;
  sc.set_groups(1);
  sc.set_robots_per_group(3);
  sc.set_sensing_range_m(0.6);  // 3 cells: the robots see nothing the global map lacks
  sc.set_max_ticks(30);
  sc.mutable_explore()->set_traffic(false);
  auto setup = swarm::test::setup_for(truth, {3, 3}, sc);
  const comm::Topology& t = setup.topology;
  swarm::test::FakeSwarm s(setup, {t.gcs()});

  // The global map the scripted GCS sends: the truth west of x = 20, unknown east of it.
  planner::OccupancyGrid global(truth.width(), truth.height(), truth.resolution());
  for (int y = 0; y < truth.height(); ++y) {
    for (int x = 0; x < 20; ++x) global.set(Cell{x, y}, truth.at(Cell{x, y}));
  }
  auto& gcs = s.agent(t.gcs());
  std::vector<msgs::PlanReport> plans;
  gcs.subscribe<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, [](const msgs::Heartbeat&) {},
                                 comm::Delivery::Reliable, 1);
  gcs.subscribe<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, [](const msgs::MapPatch&) {},
                                comm::Delivery::Reliable, 1);
  gcs.subscribe<msgs::GroupStatus>(topic::kGroupStatus, LinkClass::LeaderGcs, [](const msgs::GroupStatus&) {},
                                   comm::Delivery::Reliable, 1);
  gcs.subscribe<msgs::PlanReport>(topic::kPlanReport, LinkClass::Telemetry,
                                  [&](const msgs::PlanReport& p) { plans.push_back(p); }, comm::Delivery::Reliable, 1);
  auto& round = gcs.advertise<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs, {t.leader(0)});
  s.script(t.gcs(), [&](const msgs::Clock& c) {
    if (c.tick() != 1) return;
    msgs::RoundStart r;
    r.round(1);
    r.fused_tick(1);
    r.width(static_cast<std::uint16_t>(global.width()));
    r.height(static_cast<std::uint16_t>(global.height()));
    r.encoding(static_cast<std::uint8_t>(planner::PatchEncoding::RunLength));
    r.map_rle(app::encode_map(global, planner::PatchEncoding::RunLength));
    round.send(r);
  });
  // A spy on the group's assignments.
  comm::FakeBus spy(s.network());
  std::vector<msgs::Assignment> assignments;
  comm::Reader<msgs::Assignment> reader(spy, topic::assign(0), [&](msgs::Assignment&& a) { assignments.push_back(a); });

  s.start();
  ASSERT_TRUE(s.run_until([&] { return !plans.empty(); }, 10));
  ASSERT_EQ(assignments.size(), 1u);
  EXPECT_EQ(assignments[0].round(), 1u);
  EXPECT_EQ(plans[0].plan_case(), static_cast<std::uint8_t>(planner::PlanCase::GlobalAssignment));

  // Every waypoint is a distinct frontier cell of the global map: the column x = 19, y = 1..5.
  const auto waypoints = app::optional_cells_from_xy(assignments[0].waypoints_xy());
  ASSERT_EQ(waypoints.size(), 3u);
  std::vector<Cell> cells;
  for (const auto& w : waypoints) {
    ASSERT_TRUE(w.has_value());
    EXPECT_EQ(w->x, 19);
    EXPECT_TRUE(planner::is_frontier(global, *w)) << w->x << "," << w->y;
    cells.push_back(*w);
  }
  std::sort(cells.begin(), cells.end());
  EXPECT_TRUE(std::adjacent_find(cells.begin(), cells.end()) == cells.end());
  // The robots' assignment is the cheapest of the 3! ways (Euclidean distance, as the planner).
  const std::vector<Cell>& at = setup.world.robot_cells;
  const auto cost = [&](const std::vector<Cell>& w) {
    double c = 0;
    for (int i = 0; i < 3; ++i) c += std::hypot(at[i].x - w[i].x, at[i].y - w[i].y);
    return c;
  };
  std::vector<Cell> given = {*waypoints[0], *waypoints[1], *waypoints[2]};
  std::vector<Cell> perm = cells;
  double best = std::numeric_limits<double>::infinity();
  do best = std::min(best, cost(perm));
  while (std::next_permutation(perm.begin(), perm.end()));
  EXPECT_NEAR(cost(given), best, 1e-9);
}

TEST(LeaderNode, ALostMemberIsNoticedPlannedWithoutAndTheMissionStillCompletes) {
  auto setup = swarm::test::setup_from_text("map: 'small' groups: 1 robots_per_group: 3 max_ticks: 800 explore { traffic: false }");
  const comm::Topology& t = setup.topology;
  swarm::test::FakeSwarm s(setup);
  comm::FakeBus spy(s.network());
  std::vector<msgs::Assignment> assignments;
  comm::Reader<msgs::Assignment> reader(spy, topic::assign(0), [&](msgs::Assignment&& a) { assignments.push_back(a); });
  s.start();
  for (int k = 0; k < 40; ++k) ASSERT_TRUE(s.step());
  const std::size_t before = assignments.size();
  ASSERT_GT(before, 0u);
  s.disconnect(t.robot(0, 2));  // member-0-2 crashes
  while (s.step()) {
  }
  EXPECT_TRUE(s.complete());
  ASSERT_GT(assignments.size(), before + 1);
  // The clock marks it lost at once on the fake (its writers are gone): from the next round on
  // it gets no waypoint.
  for (std::size_t i = before + 1; i < assignments.size(); ++i) {
    const auto w = app::optional_cells_from_xy(assignments[i].waypoints_xy());
    EXPECT_FALSE(w[2].has_value()) << "round " << assignments[i].round();
  }
  s.finish();
  std::ifstream in(s.run_dir() + "/metrics.json");
  const auto m = nlohmann::json::parse(in);
  ASSERT_EQ(m["faults"]["agents_lost"].size(), 1u);
  EXPECT_EQ(m["faults"]["agents_lost"][0]["agent"], "member-0-2");
  EXPECT_EQ(m["faults"]["agents_lost"][0]["marked_lost_at_tick"], 40);
  EXPECT_EQ(m["agents"]["leader-0"]["members_lost"][0]["agent"], "member-0-2");
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
}

// leader-1 crashes mid-exploration: its standby member-1-1 (leader_standbys 1, the default) is
// named leader by the clock at once on the fake, takes the group over (the GCS hears group 1 from
// it from then on, never from two robots at one tick), plans the next rounds without the dead
// robot, and the mission completes. metrics.json records the hand-over.
TEST(LeaderNode, AStandbyTakesOverALostLeaderAndTheMissionCompletes) {
  auto setup = swarm::test::setup_from_text("map: 'small' groups: 2 robots_per_group: 3 max_ticks: 1500 explore { traffic: false }");
  const comm::Topology& t = setup.topology;
  ASSERT_EQ(t.standbys(), 1);
  swarm::test::FakeSwarm s(setup);
  comm::FakeBus spy(s.network());
  std::map<std::uint32_t, std::set<comm::AgentId>> heard;  // group 1's heartbeat senders per stamp tick
  comm::Reader<msgs::Heartbeat> beats(spy, topic::kHeartbeat, [&](msgs::Heartbeat&& h) {
    if (h.group() == 1) heard[h.header().tick()].insert(h.header().sender());
  });
  std::vector<msgs::Assignment> assignments;
  comm::Reader<msgs::Assignment> reader(spy, topic::assign(1), [&](msgs::Assignment&& a) { assignments.push_back(a); });
  s.start();
  for (int k = 0; k < 40; ++k) ASSERT_TRUE(s.step());
  s.disconnect(t.leader(1));
  while (s.step()) {
  }
  EXPECT_TRUE(s.complete());
  EXPECT_TRUE(s.candidate(t.robot(1, 1)).leader().leading());
  for (const auto& [tick, senders] : heard) {
    ASSERT_EQ(senders.size(), 1u) << "tick " << tick;
    EXPECT_EQ(*senders.begin(), tick < 40 ? t.leader(1) : t.robot(1, 1)) << "tick " << tick;
  }
  // The new leader's rounds: its own robot and member-1-2 get waypoints, the dead one none.
  std::size_t after = 0;
  for (const auto& a : assignments) {
    if (a.header().sender() != t.robot(1, 1)) continue;
    ++after;
    const auto w = app::optional_cells_from_xy(a.waypoints_xy());
    EXPECT_FALSE(w[0].has_value()) << "round " << a.round();
  }
  EXPECT_GT(after, 0u);
  s.finish();
  std::ifstream in(s.run_dir() + "/metrics.json");
  const auto m = nlohmann::json::parse(in);
  const auto& h = m["faults"]["leader_handovers"];
  ASSERT_EQ(h.size(), 1u) << h;
  EXPECT_EQ(h[0]["group"], 1);
  EXPECT_EQ(h[0]["from"], "leader-1");
  EXPECT_EQ(h[0]["to"], "member-1-1");
  EXPECT_EQ(h[0]["at_tick"], 40);
  EXPECT_EQ(m["faults"]["messages_from_deposed_leaders"], 0);
  const auto& led = m["agents"]["member-1-1"]["led"];
  ASSERT_EQ(led.size(), 1u) << led;
  EXPECT_EQ(led[0]["from_tick"], 40);
  EXPECT_TRUE(led[0]["to_tick"].is_null());
  EXPECT_GT(m["agents"]["member-1-1"]["rounds_planned"].get<int>(), 0);
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
}

// Bytes that do not decode: a global map of the wrong size in a RoundStart (decoded in the
// handler) and an order whose route has an odd number of coordinates (decoded as it arrives): each is logged and
// dropped, and the leader goes on with its work; a good window after them is driven.
TEST(LeaderNode, DropsMalformedMessagesAndGoesOn) {
  const planner::OccupancyGrid truth = hall();
  swarm::scenario::Scenario sc;
  sc.set_groups(1);
  sc.set_robots_per_group(2);
  sc.set_max_ticks(40);
  sc.mutable_mission()->add_phase()->mutable_cover();  // a leader that drives the layer's windows
  auto setup = swarm::test::setup_for(truth, {3, 3}, sc);
  const comm::Topology& t = setup.topology;
  swarm::test::FakeSwarm s(setup, {t.gcs()});
  auto& gcs = s.agent(t.gcs());
  auto& round = gcs.advertise<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs, {t.leader(0)});
  auto& order = gcs.advertise<msgs::TaskOrder>(topic::kTaskOrder, LinkClass::LeaderGcs, {t.leader(0)});
  s.script(t.gcs(), [&](const msgs::Clock& c) {
    if (c.tick() == 1) {
      msgs::RoundStart r;
      r.round(1);
      r.width(static_cast<std::uint16_t>(truth.width()));
      r.height(static_cast<std::uint16_t>(truth.height()));
      r.encoding(static_cast<std::uint8_t>(planner::PatchEncoding::RunLength));
      r.map_rle({7, 1, 200, 3});  // 7 cells, then a state that does not exist
      round.send(r);
      msgs::TaskOrder o;
      o.seq(1);
      o.route_robots({static_cast<std::uint16_t>(t.robot(0, 1))});
      o.routes_xy({{1, 1, 2}});  // an odd number of coordinates
      order.send(o);
    }
    if (c.tick() == 3) {
      // A good window: one step for the member, from where it stands to a free neighbour.
      const planner::Cell from = setup.world.robot_cells[static_cast<std::size_t>(t.robot(0, 1))];
      planner::Cell to{from.x + 1, from.y};
      if (!truth.is_free(to)) to = {from.x - 1, from.y};
      msgs::TaskOrder o;
      o.seq(2);
      o.route_robots({static_cast<std::uint16_t>(t.robot(0, 1))});
      o.routes_xy({{static_cast<std::int16_t>(from.x), static_cast<std::int16_t>(from.y), static_cast<std::int16_t>(to.x),
                    static_cast<std::int16_t>(to.y)}});
      order.send(o);
    }
  });
  comm::FakeBus spy(s.network());
  std::vector<msgs::Route> routes;
  comm::Reader<msgs::Route> reader(spy, topic::route(0), [&](msgs::Route&& r) { routes.push_back(r); });

  s.start();
  ASSERT_TRUE(s.run_until([&] { return !routes.empty(); }, 20));
  EXPECT_EQ(s.agent(t.leader(0)).malformed_messages(), 2u);
}

}  // namespace
}  // namespace swarm::leader
