// The mapf task end to end on the FakeBus (the real GCS, leaders, members and simulator, in one
// thread): every robot reaches its goal with no conflict the simulator sees, with and without
// member<->leader delay and jitter, and when a member is lost midway.
#include <gtest/gtest.h>

#include <algorithm>

#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"

namespace swarm::leader {
namespace {

const nlohmann::json& mapf_phase(const nlohmann::json& m) { return swarm::test::phase_named(m, "mapf"); }

constexpr const char* kTwoGroups = "map: 'small' groups: 2 robots_per_group: 3 max_ticks: 600 ";

// The first phase's mapf goals at the centres of `goals` (robot r's at goals[r]), resolved as a
// scenario's are at load.
void set_goals(app::RoleSetup& setup, const planner::OccupancyGrid& truth, const std::vector<planner::Cell>& goals,
               const char* name) {
  auto* mapf = setup.world.scenario.mutable_mission()->mutable_phase(0)->mutable_mapf();
  for (const planner::Cell c : goals) {
    auto* g = mapf->add_goals();
    g->set_x(truth.origin_x() + (c.x + 0.5) * truth.resolution());
    g->set_y(truth.origin_y() + (c.y + 0.5) * truth.resolution());
  }
  tasks::resolve_mission(setup.world, name);
}

TEST(MapfTask, WithoutDelayEveryRobotArrivesWithNoConflict) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(std::string(kTwoGroups) + "mission { phase { mapf {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["solver_status"], "solved");
  EXPECT_EQ(p["task"]["robots_at_goal"], 6);
  EXPECT_EQ(p["motion"]["vertex_conflict_events"], 0);
  EXPECT_EQ(p["motion"]["edge_conflict_events"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
  EXPECT_EQ(p["motion"]["wall_stops"], 0);
  // The plan's timing is kept: from the first move to the last as many ticks as planned.
  EXPECT_EQ(p["task"]["driven_makespan_ticks"], p["task"]["planned_makespan"]);
  std::cerr << "planned makespan " << p["task"]["planned_makespan"] << ", executed " << p["task"]["makespan_ticks"] << " driven " << p["task"]["driven_makespan_ticks"]
            << "\n";
}

// Goals given in the scenario are known to the simulator: it counts, from the robots' true cells,
// every living robot on its goal when the GCS calls the phase complete.
TEST(MapfTask, TheSimulatorAgreesFromGroundTruthThatEveryRobotIsOnItsGoal) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 1 robots_per_group: 3 max_ticks: 600 mission { phase { mapf { "
      "goals { x: 1.1 y: 1.1 } goals { x: 6.9 y: 6.9 } goals { x: 1.1 y: 6.9 } } } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["robots_at_goal"], 3);
  EXPECT_EQ(p["task"]["ground_truth_at_goal"], 3);
  EXPECT_EQ(p["task"]["ground_truth_living"], 3);
}

// CBS out of time leaves nothing safe to drive: the GCS tries LaCAM (complete) within another such
// limit, and both attempts are in the phase's numbers.
TEST(MapfTask, ATimedOutSolverFallsBackToLacam) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      std::string(kTwoGroups) + "mission { phase { mapf { solver: MAPF_CBS time_limit_s: 1e-9 } } }"));
  const auto m = s.run_to_end();
  const auto& plans = mapf_phase(m)["task"]["plans"];
  ASSERT_GE(plans.size(), 2u) << plans;
  EXPECT_EQ(plans[0]["status"], "timeout");
  EXPECT_EQ(plans[1]["why"], "LaCAM after a timeout");
  // The phase's planned numbers are those of the plan after the fallback.
  EXPECT_EQ(mapf_phase(m)["task"]["solver_status"], plans[1]["status"]);
}

TEST(MapfTask, WithMemberLeaderDelayAndJitterStillNoConflict) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      std::string(kTwoGroups) +
      "links { member_leader { delay_ticks: 3 jitter_ticks: 4 } } mission { phase { mapf {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["robots_at_goal"], 6);
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
  std::cerr << "planned makespan " << p["task"]["planned_makespan"] << ", executed " << p["task"]["makespan_ticks"] << " driven " << p["task"]["driven_makespan_ticks"]
            << "\n";
}

// Nine robots: driven by its timing from one start tick the plan takes exactly as long as planned,
// without a conflict; with exact links and no fault the default (AUTO) drives so. Driven by the
// graph the robots wait for each other, but each member sees in the clock when the robots it waits
// on have gone and sets off in that tick (its release's watch), so the plan keeps its pace there
// too (49 ticks while every wait took the release's way from the leader).
TEST(MapfTask, TimedExecutionKeepsThePlansMakespanExactly) {
  const std::string team = "map: 'small' groups: 3 robots_per_group: 3 max_ticks: 600 ";
  swarm::test::FakeSwarm adg(
      swarm::test::setup_from_text(team + "mission { phase { mapf { execution: MAPF_EXECUTE_ADG } } }"));
  const auto by_graph = mapf_phase(adg.run_to_end());
  swarm::test::FakeSwarm timed(swarm::test::setup_from_text(team + "mission { phase { mapf {} } }"));
  const auto m = timed.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["robots_at_goal"], 9);
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["task"]["driven_makespan_ticks"], p["task"]["planned_makespan"]);
  EXPECT_EQ(by_graph["task"]["driven_makespan_ticks"], p["task"]["planned_makespan"]);
  EXPECT_EQ(by_graph["task"]["conflicts"], 0);
}

// A mapf phase after exploration: the robots are still driving exploration routes when
// exploration ends, so the phase starts once the leaders have stopped them all, and the GCS plans
// at its start from where they stand (a plan made from the cells of a tick when robots still
// moved would send routes that no longer start where the robots are: measured before, 2 of 4
// robots never arrived and the run stopped at max_ticks).
TEST(MapfTask, APhaseAfterExplorationPlansOnceEveryRobotStands) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 600 mission { phase { explore {} } phase { mapf {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["robots_at_goal"], 4);
  ASSERT_EQ(p["task"]["plans"].size(), 1u);
  EXPECT_EQ(p["task"]["plans"][0]["tick"].get<int>(), p["start_tick"].get<int>());
  EXPECT_GT(p["start_tick"].get<int>(), m["phases"][0]["end_tick"].get<int>());
  EXPECT_EQ(p["motion"]["routes_rejected"], 0);
}

// An unscheduled loss (the scenario names no fault, so AUTO would drive by timing, which does
// not stop for a dead robot): driven by the graph, the others are planned again.
TEST(MapfTask, AMemberLostMidwayTheOthersArePlannedAgain) {
  auto setup = swarm::test::setup_from_text(std::string(kTwoGroups) +
                                            "mission { phase { mapf { execution: MAPF_EXECUTE_ADG } } }");
  swarm::test::FakeSwarm s(setup);
  const auto m = s.run_to_end([&](std::uint32_t tick) {
    if (tick == 20) s.disconnect(setup.topology.robot(1, 2));
  });
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  ASSERT_EQ(p["task"]["plans"].size(), 2u);
  EXPECT_EQ(p["task"]["plans"][1]["why"], "robot lost");
  EXPECT_EQ(p["task"]["plans"][1]["robots"], 5);
  EXPECT_EQ(p["task"]["robots_at_goal"], 5);
  EXPECT_EQ(p["task"]["conflicts"], 0);
}

// Four robots of two groups in a closed 2 x 2 room, each to go to the next cell round it: the only
// plan is one rotation of all four (no cell is free). `links`: the scenario's links block.
// Returns the mission's metrics.
nlohmann::json drive_a_ring_of_four(const std::string& links, std::uint32_t seed) {
  const auto truth = swarm::test::grid_from({"####", "#..#", "#..#", "####"});
  auto sc = config::parse_scenario_text("groups: 2 robots_per_group: 2 max_ticks: 300 seed: " + std::to_string(seed) +
                                            " " + links +
                                            " mission { phase { mapf { execution: MAPF_EXECUTE_ADG solver: MAPF_CBS } } }",
                                        "rotation test");
  auto setup = swarm::test::setup_for(truth, {1, 1}, sc);
  const std::vector<planner::Cell> ring{{1, 1}, {1, 2}, {2, 2}, {2, 1}};
  std::vector<planner::Cell> goals;
  for (const planner::Cell c : setup.world.robot_cells) {
    const auto at = std::find(ring.begin(), ring.end(), c);
    EXPECT_NE(at, ring.end());
    goals.push_back(ring[static_cast<std::size_t>(at - ring.begin() + 1) % ring.size()]);
  }
  set_goals(setup, truth, goals, "rotation test");
  swarm::test::FakeSwarm s(setup);
  return s.run_to_end();
}

// The ring's four robots went round in one rotation ordered by the GCS: each made its one move,
// none ran into another.
void expect_one_rotation_of_four(const nlohmann::json& m) {
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["rotations_ordered"], 1);
  EXPECT_EQ(p["task"]["robots_at_goal"], 4);
  EXPECT_EQ(p["motion"]["vertex_conflict_events"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
  EXPECT_EQ(p["motion"]["moves"], 4);
}

// Driven by the graph under member<->leader delay and jitter, the leaders learn of the rotation
// at different ticks, so they never release it themselves: the GCS orders it with one start tick,
// and all four move in one tick.
TEST(MapfTask, ARotationAcrossGroupsMovesInOneTickUnderDelayAndJitter) {
  const auto m = drive_a_ring_of_four("links { member_leader { delay_ticks: 2 jitter_ticks: 3 } }", 1);
  expect_one_rotation_of_four(m);
  EXPECT_EQ(mapf_phase(m)["task"]["planned_makespan"], 1);
  EXPECT_EQ(mapf_phase(m)["task"]["conflicts"], 0);
}

// The same with a third of the transmissions lost on every link, the simulator's too: each
// robot's command goes to the simulator at once, held there for the rotation's tick, which allows
// for repeats of lost transmissions on the way; all four still move in one tick.
TEST(MapfTask, ARotationAcrossGroupsMovesInOneTickWhenCommandsToTheSimulatorAreLost) {
  for (const std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_one_rotation_of_four(drive_a_ring_of_four(
        "links { sim_robot { loss: 0.3 } member_leader { loss: 0.3 } leader_gcs { loss: 0.3 } }", seed));
  }
}

// The 2 x 2 rotation across two groups (`on_ring`: its robots, two of each group) under
// member<->leader delay 2 + 0..3, and beside it the two other robots crossing a room (`beside`),
// `lost` of them lost at tick `lost_at`: the mission's metrics. Whenever the loss, the rotation
// must go whole or not at all, and the living reach their goals.
nlohmann::json a_ring_and_a_loss(const std::vector<std::pair<int, int>>& on_ring,
                                 const std::vector<std::pair<int, int>>& beside, comm::AgentId lost,
                                 std::uint32_t lost_at) {
  const auto truth = swarm::test::grid_from({"##########", "#..#.....#", "#........#", "##########"});
  auto sc = config::parse_scenario_text(
      "groups: 2 robots_per_group: 3 max_ticks: 300 links { member_leader { delay_ticks: 2 jitter_ticks: 3 } } "
      "mission { phase { mapf { execution: MAPF_EXECUTE_ADG solver: MAPF_CBS } } }",
      "rotation and loss test");
  auto setup = swarm::test::setup_for(truth, {1, 1}, sc);
  const comm::Topology& t = setup.topology;
  const std::vector<planner::Cell> ring{{1, 1}, {1, 2}, {2, 2}, {2, 1}};
  std::vector<planner::Cell> goals(static_cast<std::size_t>(t.robots()));
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const comm::AgentId r = t.robot(on_ring[i].first, on_ring[i].second);
    setup.world.robot_cells[r] = ring[i];
    goals[r] = ring[(i + 1) % ring.size()];
  }
  for (std::size_t i = 0; i < beside.size(); ++i) {
    const comm::AgentId r = t.robot(beside[i].first, beside[i].second);
    setup.world.robot_cells[r] = {4, static_cast<int>(i) + 1};
    goals[r] = {8, static_cast<int>(i) + 1};
  }
  set_goals(setup, truth, goals, "rotation and loss test");
  swarm::test::FakeSwarm s(setup);
  return s.run_to_end([&](std::uint32_t tick) {
    if (tick == lost_at) s.disconnect(lost);
  });
}

void expect_the_rotation_whole(const nlohmann::json& m) {
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["robots_at_goal"], 5);
  EXPECT_EQ(p["motion"]["vertex_conflict_events"], 0) << p["motion"];
  EXPECT_EQ(p["motion"]["edge_conflict_events"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
}

// One of the robots beside the rotation is lost at some tick round the rotation's: the plan is
// held, and the Hold must not reach some of the rotation's robots before its tick and others after
// (those would move into robots that stopped).
TEST(MapfTask, ARobotLostRoundARotationsTickNeverSplitsTheRotation) {
  for (std::uint32_t lost_at = 1; lost_at <= 10; ++lost_at) {
    SCOPED_TRACE("robot lost at tick " + std::to_string(lost_at));
    const comm::Topology t(2, 3);
    expect_the_rotation_whole(a_ring_and_a_loss({{0, 0}, {0, 1}, {1, 0}, {1, 1}}, {{0, 2}, {1, 2}}, t.robot(0, 2), lost_at));
  }
}

// Group 1's leader, beside the rotation, is lost at some tick round the rotation's: its standby
// member-1-1, one of the rotation's robots, takes the group over from the GCS's orders it kept,
// the Rotate among them. It stops its robots where they stand, but a rotation already ordered goes
// first (the GCS's Hold waits for it too): stopped at once, its robots would stand while the other
// group's moved into them (7 vertex conflicts for each loss at ticks 1-7, before).
TEST(MapfTask, AStandbyTakingOverRoundARotationsTickNeverSplitsTheRotation) {
  for (std::uint32_t lost_at = 1; lost_at <= 11; ++lost_at) {  // the plan's end is at 12
    SCOPED_TRACE("leader-1 lost at tick " + std::to_string(lost_at));
    const comm::Topology t(2, 3);
    const auto m = a_ring_and_a_loss({{0, 0}, {0, 1}, {1, 1}, {1, 2}}, {{0, 2}, {1, 0}}, t.leader(1), lost_at);
    expect_the_rotation_whole(m);
    EXPECT_EQ(m["faults"]["leader_handovers"].size(), 1u);
  }
}

// leader-1 is lost midway (its robot with it): member-1-1, its standby, takes the group over. It
// cannot know how far its robots got along the old leader's routes, so it stops them where they
// stand; the GCS holds the plan of a group whose leader changed, and once every group stands still
// it plans again for the five living robots. Driven by the graph under delay, and by the plan's
// timing without.
TEST(MapfTask, ALeaderLostMidwayItsStandbyStopsTheGroupAndAllArePlannedAgain) {
  for (const std::string links : {"", "links { member_leader { delay_ticks: 2 jitter_ticks: 2 } } "}) {
    SCOPED_TRACE(links.empty() ? "timed" : "graph under delay");
    auto setup = swarm::test::setup_from_text(std::string(kTwoGroups) + links + "mission { phase { mapf {} } }");
    swarm::test::FakeSwarm s(setup);
    const auto m = s.run_to_end([&](std::uint32_t tick) {
      if (tick == 6) s.disconnect(setup.topology.leader(1));
    });
    ASSERT_TRUE(m["complete"].get<bool>());
    const auto& h = m["faults"]["leader_handovers"];
    ASSERT_EQ(h.size(), 1u) << h;
    EXPECT_EQ(h[0]["to"], "member-1-1");
    const auto& p = mapf_phase(m);
    ASSERT_EQ(p["task"]["plans"].size(), 2u) << p["task"]["plans"];
    EXPECT_EQ(p["task"]["plans"][1]["why"], "robot lost");
    EXPECT_EQ(p["task"]["plans"][1]["robots"], 5);
    EXPECT_EQ(p["task"]["robots_at_goal"], 5);
    EXPECT_EQ(p["task"]["conflicts"], 0) << p["motion"];
    EXPECT_EQ(p["motion"]["blocked_moves"], 0);
    EXPECT_EQ(p["motion"]["routes_rejected"], 0);
  }
}

// A file of robots down a one-cell corridor, two groups mixed: each robot follows the one ahead,
// and driven by the graph each of its steps waits for that robot to have left the cell. Robot
// positions are shared in real time (the clock): a member sees the cell left in the tick it is,
// whatever the group, and its release's watch lets it step on at once. The file drives its 6
// planned steps in 9 ticks, the members setting off a tick after the leaders' robots, which get
// their routes first (10 while the follower's leader saw the cell left and sent the release, 15
// while progress came only from reports, another group's through the GCS).
TEST(MapfTask, ByTheGraphAFollowerWaitsOnlyTheTickItsReleaseTakes) {
  const auto truth = swarm::test::grid_from({"############", "#..........#", "############"});
  auto sc = config::parse_scenario_text(
      "groups: 2 robots_per_group: 2 max_ticks: 300 mission { phase { mapf { execution: MAPF_EXECUTE_ADG } } }",
      "file test");
  auto setup = swarm::test::setup_for(truth, {1, 1}, sc);
  ASSERT_EQ(setup.world.robot_cells.size(), 4u);
  std::vector<planner::Cell> goals;
  for (const planner::Cell c : setup.world.robot_cells) {  // every robot 6 cells east
    ASSERT_EQ(c.y, 1);
    ASSERT_LE(c.x, 4);
    goals.push_back({c.x + 6, c.y});
  }
  set_goals(setup, truth, goals, "file test");
  swarm::test::FakeSwarm s(setup);
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& p = mapf_phase(m);
  EXPECT_EQ(p["task"]["robots_at_goal"], 4);
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
  EXPECT_EQ(p["task"]["planned_makespan"], 6);
  EXPECT_EQ(p["task"]["driven_makespan_ticks"], 9);
}

// Two robots in a one-cell-wide corridor, each to the other's end: they can never pass. LaCAM
// explores every configuration and proves it; the phase, and with it the mission, ends at once,
// incomplete and saying why, instead of running on to max_ticks.
TEST(MapfTask, AnInfeasiblePlanEndsThePhaseAndTheMissionAtOnce) {
  const auto truth = swarm::test::grid_from({"######", "#....#", "######"});
  auto sc = config::parse_scenario_text(
      "groups: 1 robots_per_group: 2 max_ticks: 300 mission { phase { mapf { solver: MAPF_LACAM } } }",
      "corridor test");
  auto setup = swarm::test::setup_for(truth, {1, 1}, sc);
  ASSERT_EQ(setup.world.robot_cells.size(), 2u);
  // Each robot's goal: the other's start.
  set_goals(setup, truth, {setup.world.robot_cells[1], setup.world.robot_cells[0]}, "corridor test");
  swarm::test::FakeSwarm s(setup);
  const auto m = s.run_to_end();
  EXPECT_FALSE(m["complete"].get<bool>());
  EXPECT_LT(m["ticks_run"].get<int>(), 5);
  const auto& p = mapf_phase(m);
  EXPECT_FALSE(p["complete"].get<bool>());
  EXPECT_EQ(p["end_tick"], 0);
  EXPECT_EQ(p["task"]["solver_status"], "infeasible");
  const std::string why = p["gave_up"].get<std::string>();
  EXPECT_NE(why.find("infeasible"), std::string::npos) << why;
  EXPECT_EQ(p["motion"]["moves"], 0);
}

}  // namespace
}  // namespace swarm::leader
