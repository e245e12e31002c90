// The collect task end to end on the FakeBus (the real GCS, leaders, members and simulator, in
// one thread): every object reaches its type's destination, as the simulator judges from ground
// truth, none is dropped elsewhere, and when a robot is lost midway its objects (what it carried
// included, put down beside it) are taken on by the others; all through the traffic layer.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "swarm_test/fake_swarm.hpp"
#include "swarm_test/phase_checks.hpp"

namespace swarm::leader {
namespace {

using swarm::test::phase_named;

TEST(CollectTask, EveryObjectReachesItsDestination) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 3000 mission { phase { collect {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = phase_named(m, "collect");
  EXPECT_EQ(p["task"]["objects"], 15);  // 5 of each of 3 types (the defaults)
  EXPECT_EQ(p["task"]["delivered"], 15);
  EXPECT_EQ(p["task"]["picked"], 15);
  EXPECT_EQ(p["task"]["wrong_drops"], 0);
  EXPECT_EQ(p["motion"]["wall_stops"], 0);
  std::cerr << "makespan " << p["task"]["makespan_ticks"] << " moves " << p["motion"]["moves"] << " turns/8 "
            << p["motion"]["turn_eighths"] << " conflicts " << p["motion"]["vertex_conflict_events"] << "\n";
}

// A member lost in the very tick it picks up an object, after exploration (3 x 3 robots on
// small): its last report does not say so, but its true cell in the clock shows how far along its
// route it got, so the GCS knows it carried the object, which the simulator put down beside it
// with the other it held. Both lie on one cell, and a robot picks up everything on the cell it
// picks at: they go to one robot.
TEST(CollectTask, AMemberLostAsItPicksUpStillHasItsLoadCollected) {
  auto setup = swarm::test::setup_from_text(
      "map: 'small' max_ticks: 1500 mission { phase { explore {} } phase { collect {} } }");
  const comm::AgentId robot = setup.topology.robot(0, 2);
  // The tick it first picks up (runs are deterministic): found by a run without the loss, so the
  // test stays on that moment whatever exploration takes before.
  std::uint32_t picks_at = 0;
  {
    swarm::test::FakeSwarm first(setup);
    first.start();
    ASSERT_TRUE(first.run_until([&] { return !first.sim().world().carried_by(robot).empty(); }, 1500));
    picks_at = first.tick();
  }
  swarm::test::FakeSwarm s(setup);
  const auto m = s.run_to_end([&](std::uint32_t tick) {
    if (tick == picks_at) s.disconnect(robot);
  });
  ASSERT_TRUE(m["complete"].get<bool>()) << "lost at tick " << picks_at << ": " << m["phases"].dump(1);
  const auto& p = phase_named(m, "collect");
  EXPECT_EQ(p["task"]["delivered"], p["task"]["objects"]);
  EXPECT_EQ(p["task"]["reported_delivered"], p["task"]["objects"]);
  EXPECT_EQ(p["task"]["wrong_drops"], 0);
  swarm::test::expect_no_conflict(p);
}

// ---- Through the traffic layer (docs/traffic.md), in detail -------------------------------------

// The phase as the simulator judged it: every object delivered, none dropped elsewhere, no
// conflict, and the GCS knows each delivered (its belief and the ground truth agree).
void expect_all_delivered_without_a_conflict(const nlohmann::json& m) {
  const auto& p = phase_named(m, "collect");
  ASSERT_TRUE(m["complete"].get<bool>()) << p.dump(1);
  EXPECT_EQ(p["task"]["delivered"], p["task"]["objects"]);
  EXPECT_EQ(p["task"]["reported_delivered"], p["task"]["objects"]);
  EXPECT_EQ(p["task"]["wrong_drops"], 0);
  swarm::test::expect_no_conflict(p);
}

TEST(CollectTask, ThroughTheTrafficLayerEveryObjectIsDeliveredWithoutAConflict) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 3 robots_per_group: 3 max_ticks: 3000 mission { phase { collect { traffic: true } } }"));
  const auto m = s.run_to_end();
  expect_all_delivered_without_a_conflict(m);
  const auto& p = phase_named(m, "collect");
  EXPECT_EQ(p["task"]["objects"], 15);
  EXPECT_EQ(p["task"]["tour_plans"], 1);
  EXPECT_GT(p["task"]["traffic"]["windows"].get<int>(), 1);
}

TEST(CollectTask, ThroughTheTrafficLayerAfterExplorationWithLinkDelayToo) {
  for (const std::string links : {"", "links { member_leader { delay_ticks: 3 jitter_ticks: 2 } } "}) {
    SCOPED_TRACE(links);
    swarm::test::FakeSwarm s(swarm::test::setup_from_text("map: 'small' groups: 3 robots_per_group: 3 max_ticks: 4000 " +
                                                          links +
                                                          "mission { phase { explore {} } phase { collect { traffic: true } } }"));
    expect_all_delivered_without_a_conflict(s.run_to_end());
  }
}

// A member lost while it carries objects, and (second run) a leader: what the lost robot held lies
// beside it, as the simulator put it down, and the others deliver it.
TEST(CollectTask, ThroughTheTrafficLayerALostRobotsLoadIsDeliveredByTheOthers) {
  for (const bool leader : {false, true}) {
    for (const std::uint32_t at : {25u, 40u}) {
      SCOPED_TRACE(std::string(leader ? "leader" : "member") + " lost at " + std::to_string(at));
      auto setup = swarm::test::setup_from_text(
          "map: 'small' groups: 2 robots_per_group: 3 max_ticks: 4000 mission { phase { collect { traffic: true } } }");
      swarm::test::FakeSwarm s(setup);
      const auto m = s.run_to_end([&](std::uint32_t tick) {
        if (tick == at) s.disconnect(leader ? setup.topology.leader(1) : setup.topology.robot(0, 2));
      });
      expect_all_delivered_without_a_conflict(m);
      EXPECT_GE(phase_named(m, "collect")["task"]["tour_plans"].get<int>(), 2);
    }
  }
}

// An object lies under a robot lost before collect starts (here in a mapf phase that leaves every
// robot where it stands): no living robot can ever pick it up. Once every other object is
// delivered the phase is given up (the mission ends incomplete, exit 3) and says why, instead of
// running on to max_ticks.
TEST(CollectTask, AnObjectUnderALostRobotIsGivenUpSayingWhy) {
  const std::string base = "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 3000 ";
  const auto probe = swarm::test::setup_from_text(base);
  const comm::Topology& t = probe.topology;
  const comm::AgentId lost = t.robot(1, 1);
  const double m_per_cell = probe.world.frame.resolution;
  const auto at = [&](comm::AgentId r) {
    const planner::Cell c = probe.world.robot_cells[r];
    return "{ x: " + std::to_string((c.x + 0.5) * m_per_cell) + " y: " + std::to_string((c.y + 0.5) * m_per_cell) + " }";
  };
  std::string stay;  // every robot's mapf goal: where it stands
  for (int r = 0; r < t.robots(); ++r) stay += "goals " + at(static_cast<comm::AgentId>(r)) + " ";
  const std::string objects = "objects { at " + at(lost) + " type: 0 } objects { at " + at(t.robot(0, 1)) + " type: 0 } ";
  auto setup = swarm::test::setup_from_text(base + "mission { phase { mapf { " + stay + "} } phase { collect { types: 1 " +
                                            objects + "} } }");
  swarm::test::FakeSwarm s(setup);
  const auto m = s.run_to_end([&](std::uint32_t tick) {
    if (tick == 1) s.disconnect(lost);
  });
  EXPECT_FALSE(m["complete"].get<bool>());
  const auto& p = phase_named(m, "collect");
  EXPECT_EQ(p["task"]["delivered"], 1);
  EXPECT_EQ(p["gave_up"], "1 objects that no robot's tour reaches (1 under a lost robot)");
  EXPECT_LT(p["end_tick"].get<int>(), 3000);
}

// A robot that stands on an object picks it up at its route's first step, as the simulator takes
// the route; a robot lost before that never picked it up. The GCS counts such a pick only once the
// robot's member confirms it made it (RouteProgress.acted); lost without a word, the robot may
// have made it in its last tick, and the GCS sends another robot to pick the object up beside it,
// where the simulator would have put it down, whose gripper tells (Report kPickResults). Before,
// an object under member-1-1, lost at tick 1 or 2, was counted as picked, "put down" beside it and
// "delivered" by another robot from an empty cell: the GCS and the simulator disagreed.
// Lost at each of the first ticks, before its pick or after: the GCS's count and the ground truth
// agree, and the phase either delivers both objects or gives up the one truly under the lost robot,
// saying so.
TEST(CollectTask, APickAtARouteFirstStepCountsOnlyOnceTheRobotMadeIt) {
  const std::string base = "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 3000 ";
  const auto probe = swarm::test::setup_from_text(base);
  const comm::Topology& t = probe.topology;
  const comm::AgentId lost = t.robot(1, 1);
  const planner::Cell under = probe.world.robot_cells[lost];
  const double m_per_cell = probe.world.frame.resolution;
  const auto at = [&](comm::AgentId r) {
    const planner::Cell c = probe.world.robot_cells[r];
    return "{ x: " + std::to_string((c.x + 0.5) * m_per_cell) + " y: " + std::to_string((c.y + 0.5) * m_per_cell) + " }";
  };
  const std::string objects = "objects { at " + at(lost) + " type: 0 } objects { at " + at(t.robot(0, 1)) + " type: 0 } ";
  const auto setup = swarm::test::setup_from_text(base + "mission { phase { collect { types: 1 " + objects + "} } }");
  int found_under = 0, found_beside = 0;
  for (std::uint32_t when = 1; when <= 6; ++when) {
    SCOPED_TRACE("lost at tick " + std::to_string(when));
    swarm::test::FakeSwarm s(setup);
    const auto m = s.run_to_end([&](std::uint32_t tick) {
      if (tick == when) s.disconnect(lost);
    });
    const auto& p = phase_named(m, "collect");
    EXPECT_TRUE(p["disagreement"].is_null()) << p.dump(1);
    EXPECT_EQ(p["task"]["reported_delivered"], p["task"]["delivered"]);
    EXPECT_EQ(p["task"]["wrong_drops"], 0);
    swarm::test::expect_no_conflict(p);
    const bool doubted = p["task"]["doubted_pickups"] == 1;
    if (m["complete"].get<bool>()) {
      EXPECT_EQ(p["task"]["delivered"], 2);
      found_beside += doubted ? 1 : 0;
    } else {
      EXPECT_EQ(p["task"]["delivered"], 1);
      EXPECT_EQ(p["gave_up"], "1 objects that no robot's tour reaches (1 under a lost robot)");
      const std::vector<int> states = s.sim().world().object_states();  // x, y, holder per object
      EXPECT_EQ((std::vector<int>{states[0], states[1], states[2]}),
                (std::vector<int>{under.x, under.y, sim::World::kLying}));  // truly under it
      found_under += doubted ? 1 : 0;
    }
  }
  // Each case happens: lost without a word of its pick, before it and after it.
  EXPECT_GT(found_under, 0);
  EXPECT_GT(found_beside, 0);
}

// Under loss a route and its release may arrive out of order (they travel on different topics,
// and a lost message is sent again later): a release that came first is kept for its route. Before,
// seeds 1 and 3 stalled with a robot one step short of a drop it had been released to.
TEST(CollectTask, ThroughTheTrafficLayerUnderLossOnTheMemberLinkEveryObjectIsDelivered) {
  for (const int seed : {1, 3}) {
    SCOPED_TRACE(seed);
    swarm::test::FakeSwarm s(swarm::test::setup_from_text(
        "map: 'open' groups: 3 robots_per_group: 3 max_ticks: 1500 seed: " + std::to_string(seed) +
        " links { member_leader { loss: 0.05 } } mission { phase { collect { } } }"));
    expect_all_delivered_without_a_conflict(s.run_to_end());
  }
}

// Loss on every link, the whole chain: a lost report of a robot's last step (member to leader),
// of a group's done (leader to GCS) or a lost relay of another group's progress (GCS to leader)
// would leave robots waiting on it for ever; members and leaders send their whole state again
// every 16 ticks. Before, this run stalled in collect at 13 of 15 delivered, a leader one report
// short of its robot's last step.
// The whole chain on open, 3 x 3 robots, 5 % loss on every link.
nlohmann::json chain_under_loss(int seed) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'open' groups: 3 robots_per_group: 3 max_ticks: 12000 seed: " + std::to_string(seed) +
      " links { sim_robot { loss: 0.05 } member_leader { loss: 0.05 } leader_gcs { loss: 0.05 } } "
      "mission { phase { explore {} } phase { cover {} } phase { mapf {} } phase { collect {} } }"));
  return s.run_to_end();
}

TEST(CollectTask, ThroughTheTrafficLayerALostLastReportIsSentAgain) {
  const auto m = chain_under_loss(5);
  EXPECT_TRUE(m["complete"].get<bool>());
  expect_all_delivered_without_a_conflict(m);
}

// Loss on every link, collect after the other phases: the simulator switches to collect's
// 8-connected moves before any robot acts on collect's orders (before, a lost and repeated phase
// announcement reached it after a leader's own robot had set off diagonally, the move was refused
// as a wall stop and the robot never moved again: open, seed 2).
TEST(CollectTask, ThroughTheTrafficLayerAfterTheOtherPhasesUnderLossOnEveryLink) {
  const auto m = chain_under_loss(2);
  expect_all_delivered_without_a_conflict(m);
  for (const auto& p : m["phases"]) {
    swarm::test::expect_no_conflict(p);
    for (const auto& [robot, counts] : p["motion"]["per_robot"].items()) EXPECT_EQ(counts["wall_stops"], 0) << robot;
  }
}

}  // namespace
}  // namespace swarm::leader
