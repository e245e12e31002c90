// The leader node on the FakeBus with its real members and a scripted GCS: given a global map with
// one unexplored region, it plans case B (no group frontiers) and gives its three robots three
// distinct frontier cells of that region, nearest first as the Hungarian assignment says. The
// waypoints go to the GCS (tasks/explore/waypoint_report.hpp), which drives the robots there
// through the traffic layer (tests/tasks/test_explore.cpp): what these tests watch.
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
#include "swarm/app/task_wire.hpp"
#include "swarm/tasks/explore/waypoint_report.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"
#include "swarm_test/metrics_fixture.hpp"
#include "swarm_test/phase_checks.hpp"

namespace swarm::leader {
namespace {

using comm::LinkClass;
using planner::Cell;
using planner::CellState;
namespace topic = comm::topic;

// Collects the leaders' rounds of waypoints, as sent to the GCS (their sender in `from`).
struct WaypointsHeard {
  std::vector<tasks::RoundWaypoints> rounds;
  std::vector<comm::AgentId> from;
  void hear(const msgs::TaskReport& m) {
    if (auto w = tasks::read_waypoints_report(app::report_from(m))) {
      rounds.push_back(std::move(*w));
      from.push_back(m.header().sender());
    }
  }
};

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
  WaypointsHeard heard;
  gcs.subscribe<msgs::TaskReport>(topic::kTaskReport, LinkClass::LeaderGcs,
                                  [&](const msgs::TaskReport& r) { heard.hear(r); }, comm::Delivery::Reliable, 1);
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
  s.start();
  ASSERT_TRUE(s.run_until([&] { return !plans.empty() && !heard.rounds.empty(); }, 10));
  ASSERT_EQ(heard.rounds.size(), 1u);
  EXPECT_EQ(heard.rounds[0].round, 1u);
  EXPECT_EQ(plans[0].plan_case(), static_cast<std::uint8_t>(planner::PlanCase::GlobalAssignment));

  // Every robot of the group, in order, gets a distinct frontier cell of the global map: the
  // column x = 19, y = 1..5.
  EXPECT_EQ(heard.rounds[0].robots, (std::vector<int>{t.robot(0, 0), t.robot(0, 1), t.robot(0, 2)}));
  const std::vector<Cell>& waypoints = heard.rounds[0].cells;
  ASSERT_EQ(waypoints.size(), 3u);
  std::vector<Cell> cells;
  for (const Cell& w : waypoints) {
    EXPECT_EQ(w.x, 19);
    EXPECT_TRUE(planner::is_frontier(global, w)) << w.x << "," << w.y;
    cells.push_back(w);
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
  const std::vector<Cell>& given = waypoints;
  std::vector<Cell> perm = cells;
  double best = std::numeric_limits<double>::infinity();
  do best = std::min(best, cost(perm));
  while (std::next_permutation(perm.begin(), perm.end()));
  EXPECT_NEAR(cost(given), best, 1e-9);
}

TEST(LeaderNode, ALostMemberIsNoticedPlannedWithoutAndTheMissionStillCompletes) {
  auto setup = swarm::test::setup_from_text("map: 'small' groups: 1 robots_per_group: 3 max_ticks: 800");
  const comm::Topology& t = setup.topology;
  swarm::test::FakeSwarm s(setup);
  comm::FakeBus spy(s.network());
  WaypointsHeard heard;
  comm::Reader<msgs::TaskReport> reader(spy, topic::kTaskReport, [&](msgs::TaskReport&& r) { heard.hear(r); });
  s.start();
  for (int k = 0; k < 40; ++k) ASSERT_TRUE(s.step());
  const std::size_t before = heard.rounds.size();
  ASSERT_GT(before, 0u);
  s.disconnect(t.robot(0, 2));  // member-0-2 crashes
  while (s.step()) {
  }
  EXPECT_TRUE(s.complete());
  ASSERT_GT(heard.rounds.size(), before + 1);
  // The clock marks it lost at once on the fake (its writers are gone): from the next round on
  // it gets no waypoint.
  for (std::size_t i = before + 1; i < heard.rounds.size(); ++i) {
    const std::vector<int>& robots = heard.rounds[i].robots;
    EXPECT_FALSE(robots.empty()) << "round " << heard.rounds[i].round;
    EXPECT_EQ(std::count(robots.begin(), robots.end(), t.robot(0, 2)), 0) << "round " << heard.rounds[i].round;
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
  auto setup = swarm::test::setup_from_text("map: 'small' groups: 2 robots_per_group: 3 max_ticks: 1500");
  const comm::Topology& t = setup.topology;
  ASSERT_EQ(t.standbys(), 1);
  swarm::test::FakeSwarm s(setup);
  comm::FakeBus spy(s.network());
  std::map<std::uint32_t, std::set<comm::AgentId>> heard;  // group 1's heartbeat senders per stamp tick
  comm::Reader<msgs::Heartbeat> beats(spy, topic::kHeartbeat, [&](msgs::Heartbeat&& h) {
    if (h.group() == 1) heard[h.header().tick()].insert(h.header().sender());
  });
  WaypointsHeard waypoints;
  comm::Reader<msgs::TaskReport> reader(spy, topic::kTaskReport, [&](msgs::TaskReport&& r) {
    if (r.group() == 1) waypoints.hear(r);
  });
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
  // The new leader's rounds: its own robot gets waypoints, the dead one none.
  std::size_t after = 0, own = 0;
  for (std::size_t i = 0; i < waypoints.rounds.size(); ++i) {
    if (waypoints.from[i] != t.robot(1, 1)) continue;
    ++after;
    const std::vector<int>& robots = waypoints.rounds[i].robots;
    own += static_cast<std::size_t>(std::count(robots.begin(), robots.end(), t.robot(1, 1)));
    EXPECT_EQ(std::count(robots.begin(), robots.end(), t.leader(1)), 0) << "round " << waypoints.rounds[i].round;
  }
  EXPECT_GT(after, 0u);
  EXPECT_GT(own, 0u);
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

// leader-1 is lost in the settling between exploration and cover (its robots being stopped): its
// standby takes the group over, stops the robots itself, and starts cover afresh once the GCS
// starts it, from the plan the GCS makes then (with the new leader in it). Before, it took that
// plan as a plan to adopt mid-drive, stopped its robots and waited for a hold that never came:
// the group never moved and cover stalled (small, member<->leader delay 3 +- 2: 30.5 % covered).
TEST(LeaderNode, AStandbyTakingOverBetweenPhasesStartsTheNextPhaseAfresh) {
  const std::string text = "map: 'small' groups: 2 robots_per_group: 3 max_ticks: 2000 "
                           "links { member_leader { delay_ticks: 3 jitter_ticks: 2 } } "
                           "mission { phase { explore {} } phase { cover {} } }";
  std::uint32_t explored_at = 0;
  {
    swarm::test::FakeSwarm s(swarm::test::setup_from_text(text));
    const auto m = s.run_to_end();
    ASSERT_TRUE(m["complete"].get<bool>());
    explored_at = m["phases"][0]["end_tick"].get<std::uint32_t>();
    ASSERT_GT(m["phases"][1]["start_tick"].get<std::uint32_t>(), explored_at + 2);  // a settling to lose it in
  }
  auto setup = swarm::test::setup_from_text(text);
  swarm::test::FakeSwarm s(setup);
  const auto m = s.run_to_end([&](std::uint32_t tick) {
    if (tick == explored_at + 1) s.disconnect(setup.topology.leader(1));
  });
  ASSERT_TRUE(m["complete"].get<bool>()) << m["phases"][1]["gave_up"];
  const auto& h = m["faults"]["leader_handovers"];
  ASSERT_EQ(h.size(), 1u) << h;
  EXPECT_LT(h[0]["at_tick"].get<std::uint32_t>(), m["phases"][1]["start_tick"].get<std::uint32_t>());
  const auto& cover = swarm::test::phase_named(m, "cover");
  EXPECT_EQ(cover["task"]["covered_fraction"], 1.0);
  for (const char* robot : {"member-1-1", "member-1-2"}) {
    EXPECT_GT(cover["motion"]["per_robot"][robot]["moves"].get<int>(), 0) << robot;
  }
  swarm::test::expect_no_conflict(cover);
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
