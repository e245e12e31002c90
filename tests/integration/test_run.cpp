// Whole runs over real DDS: the simulator, the GCS, every leader and member as processes.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "run_swarm.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/map_patch.hpp"
#include "swarm/record/file_hash.hpp"
#include "swarm/record/record.hpp"
#include "swarm/record/render.hpp"

namespace swarm::test {
namespace {

namespace fs = std::filesystem;

// A MovingAI benchmark map, at the resolution --map-resolution gives: two rooms joined by a door.
TEST(IntegrationRun, ExploresAMovingAiMapAtTheGivenResolution) {
  const std::string dir = fresh_dir("movingai_map");
  std::ofstream(dir + "/rooms.map") << "type octile\nheight 8\nwidth 16\nmap\n"
                                    << "@@@@@@@@@@@@@@@@\n"
                                    << "@......@.......@\n"
                                    << "@......@.......@\n"
                                    << "@..............@\n"
                                    << "@......@.......@\n"
                                    << "@......@.......@\n"
                                    << "@......@.......@\n"
                                    << "@@@@@@@@@@@@@@@@\n";
  const CommandResult r = run_swarm("run --map " + dir + "/rooms.map --map-resolution 0.25 --groups 1 "
                                    "--robots-per-group 2 --max-ticks 400 --out " + dir + "/run");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("run finished: rooms,"), std::string::npos) << r.output;
  const auto m = read_json(dir + "/run/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>());
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
  const auto frames = record::read_record(dir + "/run/run.pb");
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames[0].header().width(), 16u);
  EXPECT_EQ(frames[0].header().height(), 8u);
  EXPECT_DOUBLE_EQ(frames[0].header().resolution(), 0.25);
}

// The small built-in scenario: 2 groups x 2 robots on the 8 m x 8 m three-room map.
TEST(IntegrationRun, SmallMissionCompletesWithEveryOutput) {
  const std::string dir = fresh_dir("small_mission") + "/run";
  const CommandResult r = run_swarm("run --scenario " + source_path("scenarios/small.pbtxt") + " --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;

  for (const char* f : {"scenario.pbtxt", "metrics.json", "run.pb", "map.png", "logs/sim.log", "logs/gcs.log",
                        "logs/leader-0.log", "logs/leader-1.log", "logs/member-0-1.log", "logs/member-1-1.log"}) {
    EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
  }
  const auto m = read_json(dir + "/metrics.json");
  EXPECT_EQ(m["scenario"], "small");
  EXPECT_EQ(m["mode"], "group-frontier");
  EXPECT_EQ(m["groups"], 2);
  EXPECT_EQ(m["robots"], 4);
  EXPECT_TRUE(m["complete"].get<bool>());
  // The GCS declares completion only when nothing reachable is unknown, so the simulator's
  // ground truth must agree that (almost) everything was seen, and 99 % came no later.
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
  const int steps = m["steps"];
  EXPECT_GT(steps, 10);
  EXPECT_LT(steps, 400);
  ASSERT_FALSE(m["steps_to_99"].is_null());
  EXPECT_LE(m["steps_to_99"].get<int>(), steps);
  EXPECT_GE(m["planning_rounds"].get<int>(), 2);
  EXPECT_GT(m["ticks_per_second"].get<double>(), 0.0);
  EXPECT_TRUE(m["reports_missing"].empty()) << m["reports_missing"];
  // Every link class carried traffic, and every role's topics were counted.
  for (const char* link : {"sim_robot", "member_leader", "leader_gcs", "telemetry"}) {
    EXPECT_GT(m["traffic"]["by_link"][link]["bytes"].get<long>(), 0) << link;
  }
  // The busiest sender on each radio link is one agent that sent at least the link's average
  // share (leader_gcs: 2 leaders and the GCS; member_leader: 4 robots) and at most all of it.
  for (const auto& [link, senders] : {std::pair<const char*, long>{"leader_gcs", 3}, {"member_leader", 4}}) {
    const auto& l = m["traffic"]["by_link"][link];
    ASSERT_TRUE(l["busiest_sender"].is_string()) << link << ": " << l;
    EXPECT_LE(l["busiest_sender_bytes"].get<long>(), l["bytes"].get<long>()) << link;
    EXPECT_GE(l["busiest_sender_bytes"].get<long>() * senders, l["bytes"].get<long>()) << link;
  }
  // Exploration drives through the traffic layer: waypoints go to the GCS (task_report), windows
  // come back (task_order) and reach the robots as routes and releases.
  for (const char* topic : {"sense", "motion", "patch_up", "patch_down", "route", "release", "progress", "patch_gcs",
                            "round", "task_report", "task_order", "plan_report"}) {
    EXPECT_GT(m["traffic"]["by_topic"][topic]["messages"].get<long>(), 0) << topic;
  }
  // No message is lost without loss emulation: what was sent was received.
  EXPECT_EQ(m["traffic"]["by_topic"]["patch_gcs"]["messages"], m["traffic"]["by_topic"]["patch_gcs"]["received_messages"]);

  const auto frames = record::read_record(dir + "/run.pb");
  ASSERT_FALSE(frames.empty());
  EXPECT_TRUE(frames.front().has_header());
  EXPECT_TRUE(frames.back().has_summary());
  EXPECT_EQ(frames.back().summary().steps(), static_cast<unsigned>(steps));
}

// Lockstep determinism: one scenario and seed give identical runs, whatever the timing.
TEST(IntegrationRun, TwoRunsWithOneSeedAreIdentical) {
  const std::string dir = fresh_dir("determinism");
  const std::string args = "run --scenario " + source_path("scenarios/small.pbtxt") + " --seed 7 --out ";
  const CommandResult a = run_swarm(args + dir + "/a");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const CommandResult b = run_swarm(args + dir + "/b");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  const auto ma = read_json(dir + "/a/metrics.json");
  const auto mb = read_json(dir + "/b/metrics.json");
  EXPECT_EQ(ma["steps"], mb["steps"]);
  EXPECT_EQ(ma["steps_to_99"], mb["steps_to_99"]);
  EXPECT_EQ(ma["planning_rounds"], mb["planning_rounds"]);
  EXPECT_EQ(ma["traffic"]["total"], mb["traffic"]["total"]);
  EXPECT_EQ(record::sha256_file_hex(dir + "/a/run.pb"), record::sha256_file_hex(dir + "/b/run.pb"));
}

// Frontier pictures draw the map the leaders planned with, which the record names per round
// (MapVersion.planning_map_tick = the map its RoundStart carried). Under the paper's one-round
// delay that is the previous round's version, and every global frontier segment a leader
// reported lies on that map's frontiers, while the fresher fused map of the same round has
// already explored some of them (what made the old pictures look wrong).
TEST(IntegrationRun, RecordNamesTheDelayedMapTheLeadersPlannedWith) {
  const std::string dir = fresh_dir("planning_map") + "/run";
  // The baseline plans case B every round, so every plan reports global segments.
  const CommandResult r =
      run_swarm("run --scenario " + source_path("scenarios/small.pbtxt") + " --mode baseline --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto frames = record::read_record(dir + "/run.pb");
  ASSERT_TRUE(frames.front().has_header());
  const auto& h = frames.front().header();
  auto decode = [&](const record::MapVersion& v) {
    planner::OccupancyGrid g(static_cast<int>(h.width()), static_cast<int>(h.height()));
    EXPECT_TRUE(planner::decode_grid_rle(reinterpret_cast<const std::uint8_t*>(v.rle().data()), v.rle().size(), g));
    return g;
  };
  auto known = [](const planner::OccupancyGrid& g) {
    return std::count_if(g.data().begin(), g.data().end(), [](auto c) { return c != planner::CellState::Unknown; });
  };
  std::vector<const record::MapVersion*> starts;  // round-start versions, round 1, 2, ...
  for (const auto& f : frames) {
    if (f.has_map() && f.map().has_planning_map_tick()) starts.push_back(&f.map());
  }
  ASSERT_GE(starts.size(), 3u);
  std::map<std::uint32_t, planner::OccupancyGrid> planned, fused;  // by round
  long fresher_cells = 0;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    EXPECT_EQ(starts[i]->round(), i + 1);
    // Round 1 has no older map; round r plans with round r-1's.
    const std::size_t use = i == 0 ? 0 : i - 1;
    EXPECT_EQ(starts[i]->planning_map_tick(), starts[use]->tick()) << "round " << i + 1;
    fused[starts[i]->round()] = decode(*starts[i]);
    planned[starts[i]->round()] = decode(*starts[use]);
    const long k_planned = known(planned[starts[i]->round()]), k_fused = known(fused[starts[i]->round()]);
    EXPECT_LE(k_planned, k_fused) << "round " << i + 1;
    fresher_cells += k_fused - k_planned;
  }
  EXPECT_GT(fresher_cells, 0);
  // Every reported global segment cell is a frontier of the recorded planning map; some are no
  // longer frontiers of the same round's fused map.
  long segment_cells = 0, off_planned = 0, off_fused = 0;
  for (const auto& f : frames) {
    if (!f.has_plan()) continue;
    const auto& p = f.plan();
    ASSERT_TRUE(planned.count(p.round())) << "round " << p.round();
    for (const auto& seg : p.global_segments()) {
      for (int k = 0; k + 1 < seg.xy_size(); k += 2) {
        const planner::Cell c{seg.xy(k), seg.xy(k + 1)};
        ++segment_cells;
        off_planned += !planner::is_frontier(planned[p.round()], c);
        off_fused += !planner::is_frontier(fused[p.round()], c);
      }
    }
  }
  RecordProperty("segment_cells", std::to_string(segment_cells));
  RecordProperty("segment_cells_not_frontier_in_fused_map", std::to_string(off_fused));
  EXPECT_GT(segment_cells, 0);
  EXPECT_EQ(off_planned, 0);
  EXPECT_GT(off_fused, 0);

  // `swarm render` draws that planning map: its snapshot at the last round's start matches.
  const std::uint32_t t = starts.back()->tick() + 2;
  const auto maps = record::snapshot_maps(frames, t);
  ASSERT_TRUE(maps.round);
  EXPECT_TRUE(maps.planned_recorded);
  EXPECT_EQ(maps.planned, planned[*maps.round]);
}

// The paper's default mission: 3 groups x 3 robots (11 processes) on maze1, in each mode.
class DefaultMission : public ::testing::TestWithParam<const char*> {};

TEST_P(DefaultMission, CompletesOnMaze1) {
  const std::string mode = GetParam();
  const std::string dir = fresh_dir(std::string("default_") + mode) + "/run";
  const CommandResult r = run_swarm("run --mode " + mode + " --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = read_json(dir + "/metrics.json");
  EXPECT_EQ(m["mode"], mode);
  EXPECT_EQ(m["robots"], 9);
  EXPECT_TRUE(m["complete"].get<bool>());
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
  EXPECT_TRUE(m["reports_missing"].empty()) << m["reports_missing"];
}

INSTANTIATE_TEST_SUITE_P(Modes, DefaultMission, ::testing::Values("group-frontier", "baseline", "ideal"));

}  // namespace
}  // namespace swarm::test
