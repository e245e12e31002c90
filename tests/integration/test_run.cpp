// Whole runs over real DDS: the simulator, the GCS, every leader and member as processes.
#include <filesystem>

#include <gtest/gtest.h>

#include "run_swarm.hpp"
#include "swarm/record/file_hash.hpp"
#include "swarm/record/record.hpp"

namespace swarm::test {
namespace {

namespace fs = std::filesystem;

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
  for (const char* topic : {"sense", "motion", "patch_up", "patch_down", "assign", "status", "patch_gcs", "round",
                            "group_status", "plan_report"}) {
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
