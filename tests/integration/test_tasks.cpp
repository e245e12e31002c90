// The coverage, path-finding and collection tasks over real DDS: every role its own process,
// through `swarm run`. The simulator judges from ground truth (metrics.json phases[].task / motion).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "run_swarm.hpp"
#include "swarm/record/record.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm_test/metrics_fixture.hpp"
#include "swarm_test/phase_checks.hpp"

namespace swarm::test {
namespace {

// Runs `swarm run` on scenarios/<base> with `extra` scenario text appended and `flags` added;
// expects exit 0 and a complete mission; returns metrics.json.
nlohmann::json run_task(const std::string& name, const std::string& base, const std::string& extra,
                        const std::string& flags = "") {
  const std::string dir = fresh_dir(name);
  std::ifstream in(source_path("scenarios/" + base));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir + "/scenario.pbtxt") << text << "\n" << extra << "\n";
  const CommandResult r = run_swarm("run --scenario " + dir + "/scenario.pbtxt " + flags + " --out " + dir + "/run");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  auto m = read_json(dir + "/run/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>()) << name;
  return m;
}

TEST(Tasks, ExploreThenCoverReachesEveryReachableCell) {
  const auto m = run_task("cover", "cover-small.pbtxt", "");
  const auto& cover = phase_named(m, "cover");
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
  // The explored map is not the truth (a few cells seen free are walls): routes through them end
  // in wall stops, counted, and the leaders cover round them.
  EXPECT_EQ(cover["task"]["map_given"], false);

  // The run record names the phase of every frame: each phase starts once, in order, at the tick
  // metrics.json gives, and every pose frame carries the phase its moves were made in (the poses
  // of a phase's start tick are still the previous phase's: the robots moved before it began).
  const auto frames = record::read_record(std::string(SWARM_TEST_RUNS_DIR) + "/cover/run/run.pb");
  std::vector<std::pair<std::uint32_t, std::string>> starts;  // tick, task
  for (const auto& f : frames) {
    if (f.has_phase() && !f.phase().ended()) {
      EXPECT_EQ(f.phase().phase(), starts.size());
      starts.emplace_back(f.phase().tick(), f.phase().task());
    }
  }
  ASSERT_EQ(starts.size(), 2u);
  EXPECT_EQ(starts[0], std::make_pair(0u, std::string("explore")));
  EXPECT_EQ(starts[1].second, "cover");
  EXPECT_EQ(starts[1].first, cover["start_tick"].get<std::uint32_t>());
  std::size_t poses[2] = {0, 0};
  for (const auto& f : frames) {
    if (!f.has_poses()) continue;
    const std::uint32_t expected = f.poses().tick() <= starts[1].first ? 0u : 1u;
    EXPECT_EQ(f.poses().phase(), expected) << "poses at tick " << f.poses().tick();
    ++poses[expected];
  }
  EXPECT_GT(poses[0], 0u);
  EXPECT_GT(poses[1], 0u);

  // Cover starts once every robot stands still: no robot moved in the tick before its start, and
  // exploration ended before (the ticks between are the robots' stops).
  std::map<std::uint32_t, std::vector<std::int32_t>> cells;  // tick -> every robot's x, y
  for (const auto& f : frames) {
    if (f.has_poses()) cells[f.poses().tick()].assign(f.poses().xy().begin(), f.poses().xy().end());
  }
  const std::uint32_t start = starts[1].first;
  ASSERT_TRUE(cells.count(start) && cells.count(start - 1));
  EXPECT_EQ(cells[start], cells[start - 1]);
  EXPECT_GT(start, phase_named(m, "explore")["end_tick"].get<std::uint32_t>());
}

// A member and, in the other group, the leader are killed mid-coverage: the member's cells are
// divided again among the living, group 1's standby takes the group over and drives its windows.
// Every cell is still covered, with no conflict.
TEST(Tasks, CoverWithAMemberAndALeaderKilledMidwayStillCoversEverything) {
  const auto m = run_task("cover_kill", "small.pbtxt", "mission { phase { cover {} } }",
                          "--groups 2 --robots-per-group 3 --max-ticks 3000 --kill member-0-2@40 --kill leader-1@60");
  const auto& cover = phase_named(m, "cover");
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
  EXPECT_EQ(cover["motion"]["vertex_conflict_events"], 0);
  EXPECT_EQ(cover["motion"]["edge_conflict_events"], 0);
  EXPECT_GE(cover["task"]["divisions"].size(), 2u) << cover["task"]["divisions"];
  const auto& h = m["faults"]["leader_handovers"];
  ASSERT_EQ(h.size(), 1u) << h;
  EXPECT_EQ(h[0]["to"], "member-1-1");
  EXPECT_EQ(h[0]["at_tick"], 61);
}

// Item 6 of the coverage issue: link delay and loss slow the task but never break it.
TEST(Tasks, CoverUnderLinkDelayJitterAndLossStillCoversEverything) {
  const auto m = run_task("cover_links", "small.pbtxt",
                          "links { member_leader { delay_ticks: 3 jitter_ticks: 2 loss: 0.1 } "
                          "leader_gcs { delay_ticks: 2 loss: 0.1 } sim_robot { loss: 0.05 } }",
                          "--mission cover --groups 2 --robots-per-group 2 --max-ticks 3000");
  const auto& cover = phase_named(m, "cover");
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
  // Loss really happened (retransmitted reliable messages are counted as lost transmissions).
  EXPECT_GT(m["traffic"]["by_link"]["member_leader"]["lost_transmissions"].get<double>(), 0) << m["traffic"];
}

// The traffic layer (docs/traffic.md) over DDS: the windows are driven by their dependency graphs,
// so member<->leader delay and jitter slow the robots but never make a conflict.
TEST(Tasks, CoverThroughTheTrafficLayerUnderDelayAndJitterHasNoConflict) {
  const auto m = run_task("cover_traffic", "small.pbtxt",
                          "links { member_leader { delay_ticks: 3 jitter_ticks: 2 } leader_gcs { delay_ticks: 2 } } "
                          "mission { phase { cover { traffic: true } } }",
                          "--groups 2 --robots-per-group 3 --max-ticks 3000");
  const auto& cover = phase_named(m, "cover");
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
  swarm::test::expect_no_conflict(cover);
  EXPECT_EQ(cover["task"]["traffic"]["execution"], "MAPF_EXECUTE_ADG");
}

// Collect through the traffic layer over DDS, with link delay and jitter, a member killed while it
// carries objects and then the other group's leader: what the member held is put down beside it
// and delivered by the others, the standby takes its group over, and no robot ever meets another.
TEST(Tasks, CollectThroughTheTrafficLayerWithAMemberAndALeaderKilledDeliversEverythingWithoutAConflict) {
  const auto m = run_task("collect_traffic", "small.pbtxt",
                          "links { member_leader { delay_ticks: 3 jitter_ticks: 2 } leader_gcs { delay_ticks: 2 } } "
                          "mission { phase { collect { traffic: true } } }",
                          "--groups 2 --robots-per-group 3 --max-ticks 3000 --kill member-0-2@40 --kill leader-1@90");
  const auto& p = phase_named(m, "collect");
  EXPECT_EQ(p["task"]["delivered"], p["task"]["objects"]);
  EXPECT_EQ(p["task"]["reported_delivered"], p["task"]["objects"]);
  EXPECT_EQ(p["task"]["wrong_drops"], 0);
  swarm::test::expect_no_conflict(p);
  EXPECT_GE(p["task"]["tour_plans"].get<int>(), 3);  // again after each loss
  ASSERT_EQ(m["faults"]["leader_handovers"].size(), 1u) << m["faults"];
}

// A member lost before the pick-up its route starts with reached the simulator (member-1-1,
// standing on an object, killed at tick 1): over DDS as on the fake bus
// (CollectTask.APickAtARouteFirstStepCountsOnlyOnceTheRobotMadeIt), the GCS does not count the
// pick-up, sends a robot beside the lost one, where the object would lie had it been picked up,
// and that robot's gripper finds nothing: the object is given up as under the lost robot, the run
// exits 3, and the GCS and the simulator agree on what was delivered.
TEST(Tasks, CollectGivesUpAnObjectUnderARobotLostBeforeItsPickUpAndSaysSo) {
  const std::string base = "map: 'small' groups: 2 robots_per_group: 2 ";
  const auto scenario = config::parse_scenario_text(base, "probe");
  const config::World world = config::resolve_world(scenario, "");
  const comm::Topology topology(2, 2, config::leader_standbys(scenario));
  const auto at = [&](comm::AgentId r) {
    const planner::Cell c = world.robot_cells[r];
    const double m = world.frame.resolution;
    return "{ x: " + std::to_string((c.x + 0.5) * m) + " y: " + std::to_string((c.y + 0.5) * m) + " }";
  };
  const std::string dir = fresh_dir("collect_doubt");
  std::ofstream(dir + "/scenario.pbtxt") << base << "max_ticks: 3000 mission { phase { collect { types: 1 objects { at "
                                         << at(topology.robot(1, 1)) << " type: 0 } objects { at "
                                         << at(topology.robot(0, 1)) << " type: 0 } } } }\n";
  const CommandResult r = run_swarm("run --scenario " + dir + "/scenario.pbtxt --kill member-1-1@1 --out " + dir + "/run");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  const auto m = read_json(dir + "/run/metrics.json");
  const auto& p = phase_named(m, "collect");
  EXPECT_EQ(p["task"]["doubted_pickups"], 1);
  EXPECT_EQ(p["task"]["delivered"], 1);
  EXPECT_EQ(p["task"]["reported_delivered"], 1);
  EXPECT_TRUE(p["disagreement"].is_null()) << p.dump(1);
  EXPECT_EQ(p["gave_up"], "1 objects that no robot's tour reaches (1 under a lost robot)");
  swarm::test::expect_no_conflict(p);
}

// The whole chain over DDS, every phase through the traffic layer: it completes on two maps, each
// phase agreed on by the GCS and the simulator's ground truth, with no conflict in any phase.
TEST(Tasks, TheWholeChainCompletesOnTwoMapsWithoutAConflictInAnyPhase) {
  for (const std::string map : {"small", "warehouse-5x8"}) {
    SCOPED_TRACE(map);
    const auto m = run_task("chain_" + map, "default.pbtxt", "",
                            "--map " + map + " --mission explore,cover,mapf,collect --max-ticks 3000");
    ASSERT_EQ(m["phases"].size(), 4u);
    for (const auto& p : m["phases"]) {
      SCOPED_TRACE(p["name"].get<std::string>());
      EXPECT_TRUE(p["complete"].get<bool>()) << p.dump();
      EXPECT_TRUE(p["disagreement"].is_null()) << p.dump();
      swarm::test::expect_no_conflict(p);
    }
    EXPECT_TRUE(phase_named(m, "explore")["ground_truth_done"].get<bool>());
    EXPECT_TRUE(phase_named(m, "collect")["ground_truth_done"].get<bool>());
  }
}

// maze1 is corridors: a member killed there mid-exploration stands as an obstacle that the
// layer routes round in every later phase; the chain still completes with no conflict.
TEST(Tasks, TheChainWithAMemberKilledInACorridorCompletesWithoutAConflict) {
  const auto m = run_task("chain_killed", "default.pbtxt", "",
                          "--map maze1 --mission explore,cover,collect --max-ticks 4000 --kill member-1-2@60");
  for (const auto& p : m["phases"]) {
    SCOPED_TRACE(p["name"].get<std::string>());
    EXPECT_TRUE(p["complete"].get<bool>()) << p.dump();
    swarm::test::expect_no_conflict(p);
  }
  ASSERT_EQ(m["faults"]["agents_lost"].size(), 1u) << m["faults"];
}

TEST(Tasks, CoverInGroupKOrderReachesEveryReachableCell) {
  const auto m = run_task("cover_group_k", "small.pbtxt", "mission { phase { cover { order: ORDER_GROUP_K } } }",
                          "--max-ticks 3000");
  EXPECT_DOUBLE_EQ(phase_named(m, "cover")["task"]["covered_fraction"].get<double>(), 1.0);
}

TEST(Tasks, CollectDeliversEveryObject) {
  const auto m = run_task("collect", "small.pbtxt", "mission { phase { collect {} } }", "--max-ticks 3000");
  const auto& p = phase_named(m, "collect");
  EXPECT_EQ(p["task"]["objects"], 15);
  EXPECT_EQ(p["task"]["delivered"], 15);
  EXPECT_EQ(p["task"]["wrong_drops"], 0);
  // What was driven, in the tour planner's measures: between 1 and sqrt 2 cells per move, and the
  // rotation the simulator counted in eighths of a turn, in radians.
  const double moves = p["motion"]["moves"].get<double>();
  const double length = p["task"]["driven_length_cells"].get<double>();
  EXPECT_GT(moves, 0);
  EXPECT_GE(length, moves);
  EXPECT_LE(length, moves * std::sqrt(2.0) + 1e-9);
  EXPECT_NEAR(p["task"]["driven_rotation_rad"].get<double>(),
              p["motion"]["turn_eighths"].get<double>() * std::acos(-1.0) / 4.0, 1e-9);
}

TEST(Tasks, MapfWithoutDelayKeepsThePlansTimingWithNoConflict) {
  const auto m = run_task("mapf", "mapf-small.pbtxt", "");
  const auto& p = phase_named(m, "mapf");
  EXPECT_EQ(p["task"]["robots_at_goal"], 6);
  EXPECT_TRUE(p["task"]["ground_truth_at_goal"].is_null());  // random goals: drawn by the GCS
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
  EXPECT_EQ(p["motion"]["longest_blocked_ticks"], 0);
  EXPECT_EQ(p["task"]["driven_makespan_ticks"], p["task"]["planned_makespan"]);
}

TEST(Tasks, MapfWithMemberLeaderDelayAndJitterStillHasNoConflict) {
  const auto m = run_task("mapf_delay", "mapf-small.pbtxt", "links { member_leader { delay_ticks: 3 jitter_ticks: 4 } }");
  const auto& p = phase_named(m, "mapf");
  EXPECT_EQ(p["task"]["robots_at_goal"], 6);
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_GE(p["task"]["driven_makespan_ticks"].get<int>(), p["task"]["planned_makespan"].get<int>());
}

// A leader killed mid-plan: its standby takes the group over and stops its robots, the GCS holds
// the plan of a group whose leader changed and plans again for the five living robots once
// everyone stands still; no conflict.
TEST(Tasks, MapfWithALeaderKilledMidwayItsStandbyTakesOverAndTheOthersArrive) {
  const auto m = run_task("mapf_kill_leader", "mapf-small.pbtxt", "", "--kill leader-1@8");
  const auto& h = m["faults"]["leader_handovers"];
  ASSERT_EQ(h.size(), 1u) << h;
  EXPECT_EQ(h[0]["to"], "member-1-1");
  const auto& p = phase_named(m, "mapf");
  const auto& plans = p["task"]["plans"];
  ASSERT_EQ(plans.size(), 2u) << plans;
  EXPECT_EQ(plans[1]["why"], "robot lost");
  EXPECT_EQ(plans[1]["robots"], 5);
  EXPECT_EQ(p["task"]["robots_at_goal"], 5);
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
}

// A plan proven infeasible ends the mission at once, incomplete and saying why (exit 3: the run
// worked, the mission is not done), instead of running on to max_ticks.
TEST(Tasks, MapfWithAnInfeasiblePlanEndsTheMissionAtOnce) {
  const std::string dir = fresh_dir("mapf_infeasible");
  // A corridor one cell wide, two robots, each to the other's end.
  std::ofstream(dir + "/corridor.pgm") << "P2\n6 3\n255\n0 0 0 0 0 0\n0 254 254 254 254 0\n0 0 0 0 0 0\n";
  std::ofstream(dir + "/corridor.yaml") << "image: corridor.pgm\nresolution: 0.2\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                        << "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  std::ofstream(dir + "/scenario.pbtxt")
      << "map: \"" << dir << "/corridor.yaml\" groups: 1 robots_per_group: 2 max_ticks: 500 leader_standbys: 0\n"
      << "start { x: 0.3 y: 0.3 }\n"  // robots on the corridor's cells 1 and 2, from the west
      << "mission { phase { mapf { solver: MAPF_LACAM goals { x: 0.5 y: 0.3 } goals { x: 0.3 y: 0.3 } } } }\n";
  const CommandResult r = run_swarm("run --scenario " + dir + "/scenario.pbtxt --out " + dir + "/run");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("the mission is incomplete (exit 3)"), std::string::npos) << r.output;
  const auto m = read_json(dir + "/run/metrics.json");
  EXPECT_FALSE(m["complete"].get<bool>());
  EXPECT_LT(m["ticks_run"].get<int>(), 10);
  const auto& p = phase_named(m, "mapf");
  EXPECT_FALSE(p["complete"].get<bool>());
  EXPECT_NE(p["gave_up"].get<std::string>().find("infeasible"), std::string::npos) << p["gave_up"];
  EXPECT_NE(r.output.find("INCOMPLETE: phase mapf given up: no plan for 2 robots"), std::string::npos) << r.output;
  // The goals were the scenario's: the simulator judges them from the robots' true cells.
  EXPECT_EQ(p["task"]["ground_truth_at_goal"], 0);
  EXPECT_EQ(p["task"]["ground_truth_living"], 2);
  EXPECT_NE(r.output.find("0/2 robots at goal (ground truth)"), std::string::npos) << r.output;
}

// The robots explore, then gather around a point: every one on a cell of the tightest cluster the
// true map allows there, judged by the simulator, with no conflict.
TEST(Tasks, ExploreThenRendezvousGathersEveryRobotAroundThePoint) {
  const auto m = run_task("rendezvous", "small.pbtxt",
                          "mission { phase { explore {} } phase { rendezvous { point { x: 6.1 y: 1.1 } } } }",
                          "--max-ticks 3000");
  const auto& p = phase_named(m, "rendezvous");
  EXPECT_EQ(p["task"]["robots_alive"], 4);
  EXPECT_EQ(p["task"]["on_gathering_cells"], 4);
  EXPECT_TRUE(p["task"]["packed"].get<bool>()) << p;
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
}

// A member killed on the way home: the GCS gathers the three others and reports it lost.
TEST(Tasks, RendezvousWithARobotLostOnTheWayGathersTheOthers) {
  const auto m = run_task("rendezvous_kill", "small.pbtxt", "",
                          "--mission mapf,rendezvous --kill member-1-1@40 --max-ticks 3000");
  const auto& p = phase_named(m, "rendezvous");
  EXPECT_EQ(p["task"]["robots_lost"], nlohmann::json::array({3}));
  EXPECT_EQ(p["task"]["robots_alive"], 3);
  EXPECT_EQ(p["task"]["on_gathering_cells"], 3);
  EXPECT_TRUE(p["task"]["packed"].get<bool>()) << p;
  EXPECT_EQ(p["task"]["conflicts"], 0);
}

// The GCS's process killed mid-task and started again 2 s later (gcs/gcs_node.hpp "Restart"): it
// replays its journal, the leaders re-send what it missed (GroupTask::gcs_back: covered cells,
// robots' progress, what is known of each object), and every task still ends complete with the
// simulator's ground truth whole.
TEST(Tasks, EveryTaskCompletesAcrossARestartOfTheGcs) {
  {
    const auto m = run_task("cover_gcs_restart", "cover-given.pbtxt", "", "--kill gcs@40+2");
    EXPECT_EQ(m["faults"]["gcs_restarts"].size(), 1u);
    EXPECT_DOUBLE_EQ(phase_named(m, "cover")["task"]["covered_fraction"].get<double>(), 1.0);
  }
  {
    const auto m = run_task("mapf_gcs_restart", "mapf-small.pbtxt", "", "--kill gcs@10+2");
    EXPECT_EQ(m["faults"]["gcs_restarts"].size(), 1u);
    const auto& p = phase_named(m, "mapf");
    EXPECT_EQ(p["task"]["robots_at_goal"], 6);
    EXPECT_EQ(p["task"]["conflicts"], 0);
  }
  {
    const auto m = run_task("collect_gcs_restart", "small.pbtxt", "", "--mission collect --max-ticks 3000 --kill gcs@30+2");
    EXPECT_EQ(m["faults"]["gcs_restarts"].size(), 1u);
    const auto& p = phase_named(m, "collect");
    EXPECT_EQ(p["task"]["delivered"], p["task"]["objects"]);
    EXPECT_EQ(p["task"]["wrong_drops"], 0);
  }
}

}  // namespace
}  // namespace swarm::test
