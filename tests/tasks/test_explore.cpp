// The exploration task on the FakeBus: its planning rounds follow the phase's own settings, and
// rounds are numbered across the run when a mission explores twice.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "swarm_test/fake_swarm.hpp"
#include "swarm_test/metrics_fixture.hpp"
#include "swarm_test/phase_checks.hpp"
#include "swarm/tasks/explore/waypoint_report.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"

namespace swarm::tasks {
namespace {

constexpr const char* kTwoGroups = "map: 'small' groups: 2 robots_per_group: 3 max_ticks: 800 ";

// The start tick of every planning round in metrics.json, checking they are numbered 1, 2, ...
std::vector<int> round_ticks(const nlohmann::json& m) {
  std::vector<int> ticks;
  for (const auto& r : m.at("rounds")) {
    EXPECT_EQ(r.at("round").get<int>(), static_cast<int>(ticks.size()) + 1) << m.at("rounds").dump();
    ticks.push_back(r.at("tick").get<int>());
  }
  return ticks;
}

TEST(ExploreTask, ThePhasesOwnReplanThresholdPacesTheRounds) {
  // The scenario-wide setting says 40 ticks; the phase says 3, and the phase decides.
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      std::string(kTwoGroups) +
      "explore { replan_threshold_steps: 40 } mission { phase { explore { replan_threshold_steps: 3 } } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  const std::vector<int> ticks = round_ticks(m);
  ASSERT_GE(ticks.size(), 5u);
  for (std::size_t i = 1; i < ticks.size(); ++i) EXPECT_LE(ticks[i] - ticks[i - 1], 3) << i;
  EXPECT_EQ(m["planning_rounds"], static_cast<int>(ticks.size()));
}

TEST(ExploreTask, ASecondExplorePhaseGoesOnNumberingTheRunsRounds) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(std::string(kTwoGroups) +
                                                        "mission { phase { explore {} } phase { explore {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  ASSERT_EQ(m["phases"].size(), 2u);
  const int first = m["phases"][0]["task"]["planning_rounds"].get<int>();
  const int second = m["phases"][1]["task"]["planning_rounds"].get<int>();
  EXPECT_GE(first, 2);
  // The map is already explored: the second phase plans once and sees no frontier left.
  EXPECT_EQ(second, 1);
  const std::vector<int> ticks = round_ticks(m);
  EXPECT_EQ(static_cast<int>(ticks.size()), first + second);
  EXPECT_EQ(m["planning_rounds"], first + second);
  // The phase starts at the tick the first one ended; its first step, the tick after, plans.
  EXPECT_EQ(ticks.back(), m["phases"][1]["start_tick"].get<int>() + 1);
}

TEST(WaypointReport, CarriesARoundsWaypointsAndRefusesMalformedOnes) {
  const RoundWaypoints w{7, {3, 5}, {{1, 2}, {4, 6}}};
  const auto back = read_waypoints_report(waypoints_report(w));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->round, 7u);
  EXPECT_EQ(back->robots, w.robots);
  EXPECT_EQ(back->cells, w.cells);
  task::Report r = waypoints_report(w);
  r.cells.pop_back();  // a robot without its cell
  EXPECT_FALSE(read_waypoints_report(r).has_value());
  r = waypoints_report(w);
  r.values[0] = 3;  // another task's report (mapf's progress starts with its plan number)
  EXPECT_FALSE(read_waypoints_report(r).has_value());
  r = waypoints_report(w);
  r.values[1] = -2;  // no round
  EXPECT_FALSE(read_waypoints_report(r).has_value());
  EXPECT_FALSE(read_waypoints_report(task::Report{}).has_value());
}

// Through the traffic layer (the default) every robot drives to its waypoint in the GCS's
// conflict-free windows: the map is explored with no conflict and no blocked move, on maps the
// exploration was not tuned for too.
TEST(ExploreTask, ThroughTheTrafficLayerEveryMapIsExploredWithoutAConflict) {
  for (const std::string map : {"small", "maze1", "warehouse-5x8", "clutter"}) {
    SCOPED_TRACE(map);
    swarm::test::FakeSwarm s(swarm::test::setup_from_text("map: '" + map +
                                                          "' groups: 3 robots_per_group: 3 max_ticks: 3000 "
                                                          "mission { phase { explore {} } }"));
    const auto m = s.run_to_end();
    ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
    const auto& p = swarm::test::phase_named(m, "explore");
    EXPECT_GE(p["task"]["explored_fraction"].get<double>(), 0.97) << p.dump();
    swarm::test::expect_no_conflict(p);
    EXPECT_GT(p["task"]["waypoints_reached"].get<int>(), 0) << p.dump();
    EXPECT_GT(p["task"]["traffic"]["windows"].get<int>(), 1);
  }
}

// A new round's plan starts a new chain of windows. Progress the GCS had received along the old
// chain and not yet relayed must not go out under the new plan's number: the leaders would read it
// as progress along the new routes. On MovingAI room-32-32-4 (seed 1) it did, at tick 209: two
// robots were released into cells that robots of other groups had yet to pass, and four robots
// stood in vertex conflicts for 18 ticks (36 events) until the next round.
TEST(ExploreTask, ANewRoundRelaysNoProgressAlongTheLastPlan) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      std::string("map: '") + SWARM_BENCHMARKS_DIR + "/movingai/room-32-32-4.map' start { x: 3.1 y: 3.3 } seed: 1 "
      "groups: 3 robots_per_group: 3 max_ticks: 3000 mission { phase { explore {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  const auto& p = swarm::test::phase_named(m, "explore");
  EXPECT_GT(p["task"]["planning_rounds"].get<int>(), 10);
  swarm::test::expect_no_conflict(p);
}

// A new round's waypoints continue the plan being driven: each robot drives the rest of it and goes
// on to its new waypoint without a stop. The plan is held, stopping every robot, only once it has
// grown to its limit (MapfGcsTask::kPlanSteps); it starts afresh, too, when every robot has
// reached its waypoint and stands anyway.
TEST(ExploreTask, ThroughTheTrafficLayerANewRoundStopsNoRobot) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'maze1' groups: 3 robots_per_group: 3 max_ticks: 3000 mission { phase { explore {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  const auto& p = swarm::test::phase_named(m, "explore");
  swarm::test::expect_no_conflict(p);
  const auto& traffic = p["task"]["traffic"];
  const int ticks = p["end_tick"].get<int>() - p["start_tick"].get<int>();
  const int window = traffic["window_steps"].get<int>();
  int continued = 0;
  for (const auto& plan : traffic["plans"]) continued += plan.contains("continues") ? 1 : 0;
  EXPECT_EQ(continued, traffic["repicks_continued"].get<int>());
  // Two rounds may come before one window takes them up; most rounds continue the plan.
  EXPECT_GE(2 * continued, p["task"]["planning_rounds"].get<int>()) << traffic.dump();
  // A hold each time the plan has grown to kPlanSteps. The plan's time runs ahead of the clock (a
  // robot drives on past the waits its window planned, and a round's window is planned at once
  // from the plan's end): here 256 steps in about 200 ticks.
  EXPECT_LE(traffic["repicks_held"].get<int>(), 1 + ticks / (gcs::MapfGcsTask::kPlanSteps - 2 * window)) << traffic.dump();
}

// A new round's waypoints follow from where the plan may be cut, not from its end: the limit no
// robot is released past, which the GCS keeps just ahead of the robots. With member<->leader delay
// and jitter every leader takes every cut (a robot already past it would make one drop it), and no
// robot collides.
TEST(ExploreTask, ThroughTheTrafficLayerANewRoundCutsThePlanAtTheLimit) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'maze1' groups: 3 robots_per_group: 3 max_ticks: 3000 "
      "links { member_leader { delay_ticks: 3 jitter_ticks: 2 } } mission { phase { explore {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m["ended"];
  const auto& p = swarm::test::phase_named(m, "explore");
  swarm::test::expect_no_conflict(p);
  const auto& traffic = p["task"]["traffic"];
  const int cut = traffic["repicks_cut"].get<int>();
  // Most rounds cut the plan (a round whose plan ends at the limit, or that keeps a waypoint
  // reached just past it, continues it from its end).
  EXPECT_GE(2 * cut, traffic["repicks_continued"].get<int>()) << traffic.dump();
  EXPECT_LE(cut, traffic["repicks_continued"].get<int>());
  EXPECT_GT(traffic["steps_cut"].get<int>(), cut) << traffic.dump();  // more than a step each
  for (const char* leader : {"leader-0", "leader-1", "leader-2"}) {
    EXPECT_EQ(m["agents"][leader]["traffic"]["plans_cut"].get<int>(), cut) << leader;
  }
}

// Late messages only make robots wait: with member<->leader delay and jitter, and with a member
// and (in another run) a leader lost midway, exploration still ends without a conflict.
TEST(ExploreTask, ThroughTheTrafficLayerWithDelayAndLossesNoRobotCollides) {
  struct Case {
    std::string links;
    int lost_group;  // -1: none
    int lost_index;
  };
  for (const Case& c : {Case{"links { member_leader { delay_ticks: 3 jitter_ticks: 2 } } ", -1, 0},
                        Case{"", 0, 2}, Case{"", 1, 0}}) {
    SCOPED_TRACE(c.links + " lost " + std::to_string(c.lost_group) + "/" + std::to_string(c.lost_index));
    auto setup = swarm::test::setup_from_text("map: 'small' groups: 3 robots_per_group: 3 max_ticks: 3000 " + c.links +
                                              "mission { phase { explore {} } }");
    swarm::test::FakeSwarm s(setup);
    const auto m = s.run_to_end([&](std::uint32_t tick) {
      if (tick == 20 && c.lost_group >= 0) s.disconnect(setup.topology.robot(c.lost_group, c.lost_index));
    });
    ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
    const auto& p = swarm::test::phase_named(m, "explore");
    EXPECT_GE(p["task"]["explored_fraction"].get<double>(), 0.97) << p.dump();
    swarm::test::expect_no_conflict(p);
  }
}

// A rotation's robots set off together at the tick the GCS names. When the next window grows the
// plan before that tick, each robot's route is sent again, grown, and under member<->leader jitter
// the grown version can reach the member first: it must carry the start tick too. Found on clutter
// (seed 1, 1-5 ticks): without it member-0-2 set off four ticks before the rotation and ran into
// member-2-1's cell, 4 conflict events.
TEST(ExploreTask, ARotationsRouteGrownBeforeItSetsOffKeepsItsStartTick) {
  const auto m = swarm::test::FakeSwarm(swarm::test::setup_from_text(
                                            "map: 'clutter' groups: 3 robots_per_group: 3 max_ticks: 3000 seed: 1 "
                                            "start { x: 3.05 y: 2.55 } links { member_leader { delay_ticks: 1 jitter_ticks: 4 } } "
                                            "mission { phase { explore {} } }"))
                     .run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m["ended"];
  const auto& p = swarm::test::phase_named(m, "explore");
  EXPECT_GE(p["task"]["traffic"]["rotations_ordered"].get<int>(), 1);
  swarm::test::expect_no_conflict(p);
}

// A leader<->GCS delay of half the replanning interval or more: each round's waypoints reach the
// GCS after the next round has begun. They are still the group's newest and are driven (before,
// only the current round's were taken, and every robot stood for good: maze1 with 10 ticks each
// way stalled at 5.4 % explored). Here 3 ticks each way against rounds every 3 ticks.
TEST(ExploreTask, ThroughTheTrafficLayerRoundsSlowerThanTheLinkStillMoveTheRobots) {
  for (const int delay : {0, 3}) {
    SCOPED_TRACE("leader<->GCS delay " + std::to_string(delay));
    swarm::test::FakeSwarm s(swarm::test::setup_from_text(
        std::string(kTwoGroups) + "links { leader_gcs { delay_ticks: " + std::to_string(delay) +
        " } } mission { phase { explore { replan_threshold_steps: 3 } } }"));
    const auto m = s.run_to_end();
    ASSERT_TRUE(m["complete"].get<bool>()) << m["ended"];
    const auto& p = swarm::test::phase_named(m, "explore");
    EXPECT_GE(p["task"]["explored_fraction"].get<double>(), 0.97) << p.dump();
    EXPECT_GE(p["task"]["traffic"]["plans"].size(), 2u) << p["task"].dump();  // rounds' waypoints were driven
    swarm::test::expect_no_conflict(p);
  }
}

// With jitter on the member links a route can overtake an older one: the robot keeps the newer
// (before, a stop sent between phases was overtaken by the last window's route, the stop was
// never confirmed and the next phase never started: empty, seed 2).
TEST(ExploreTask, ThroughTheTrafficLayerUnderJitterTheNextPhaseStarts) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'empty' groups: 3 robots_per_group: 3 max_ticks: 3000 seed: 2 "
      "links { member_leader { delay_ticks: 3 jitter_ticks: 2 } } mission { phase { explore {} } phase { cover {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m["phases"].dump();
  for (const auto& p : m["phases"]) swarm::test::expect_no_conflict(p);
}

}  // namespace
}  // namespace swarm::tasks
