// Bad input never crashes or hangs: exit code 2 and one message naming the file, line or field.
// A process that fails at run time stops the whole run: exit 1, the failed process named, and no
// process left behind.
#include <algorithm>
#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "run_swarm.hpp"

namespace swarm::test {
namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

struct BadInput {
  const char* name;
  std::string args;
  std::vector<std::string> message_parts;
};

class BadInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    // An 8 x 6 map: a free room, and a sealed 2 x 2 pocket at cells x 5..6, y 1..2.
    write(dir_ + "/pocket.pgm",
          "P2\n8 6\n255\n"
          "0 0 0 0 0 0 0 0\n"
          "0 254 254 254 0 0 0 0\n"
          "0 254 254 254 0 0 0 0\n"
          "0 254 254 254 0 254 254 0\n"
          "0 254 254 254 0 254 254 0\n"
          "0 0 0 0 0 0 0 0\n");
    write(dir_ + "/pocket.yaml",
          "image: pocket.pgm\nresolution: 0.2\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
          "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
    write(dir_ + "/bad_resolution.yaml", "image: pocket.pgm\nresolution: abc\norigin: [0.0, 0.0, 0.0]\n");
    write(dir_ + "/broken.pgm", "P5\n8 six\n255\n");
    write(dir_ + "/broken_image.yaml", "image: broken.pgm\nresolution: 0.2\norigin: [0.0, 0.0, 0.0]\n");
    write(dir_ + "/zero_robots.pbtxt", "robots_per_group: 0\n");
    write(dir_ + "/negative_range.pbtxt", "sensing_range_m: -3\n");
    write(dir_ + "/malformed.pbtxt", "groups: 3\nexplore {\n  replan_threshold_steps: twenty\n}\n");
  }
  void expect_rejected(const std::string& args, const std::vector<std::string>& parts) {
    const CommandResult r = run_swarm("run " + args + " --out " + dir_ + "/run");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (const auto& p : parts) EXPECT_NE(r.output.find(p), std::string::npos) << "missing '" << p << "' in: " << r.output;
    // One message, not a dump: at most a couple of lines.
    EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 3) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir_ + "/run/metrics.json"));
  }
  std::string dir_;
};

TEST_F(BadInputs, MissingScenarioFile) {
  expect_rejected("--scenario " + dir_ + "/none.pbtxt", {"none.pbtxt", "cannot open"});
}
TEST_F(BadInputs, MalformedScenarioNamesLineAndColumn) {
  // protobuf's parser names the line and column and what it expected (an integer).
  expect_rejected("--scenario " + dir_ + "/malformed.pbtxt", {"malformed.pbtxt:3:27", "integer", "twenty"});
}
TEST_F(BadInputs, ZeroRobots) {
  expect_rejected("--scenario " + dir_ + "/zero_robots.pbtxt", {"zero_robots.pbtxt", "robots_per_group", "got 0"});
}
TEST_F(BadInputs, ZeroGroupsFlag) { expect_rejected("--groups 0", {"groups", "got 0"}); }
TEST_F(BadInputs, NegativeRange) {
  expect_rejected("--scenario " + dir_ + "/negative_range.pbtxt", {"sensing_range_m", "got -3"});
}
TEST_F(BadInputs, MissingMap) { expect_rejected("--map " + dir_ + "/nope.yaml", {"nope.yaml"}); }
TEST_F(BadInputs, UnknownMapName) { expect_rejected("--map maze9", {"maze9", "open, maze1, maze2"}); }
TEST_F(BadInputs, MalformedMapYaml) {
  expect_rejected("--map " + dir_ + "/bad_resolution.yaml", {"bad_resolution.yaml:2", "resolution"});
}
TEST_F(BadInputs, MalformedPgm) { expect_rejected("--map " + dir_ + "/broken_image.yaml", {"broken.pgm"}); }
TEST_F(BadInputs, StartInsideAWall) {
  expect_rejected("--map " + dir_ + "/pocket.yaml --start 0.1,0.1", {"occupied", "pick a free cell"});
}
TEST_F(BadInputs, StartOutsideTheMap) {
  expect_rejected("--map " + dir_ + "/pocket.yaml --start 50,50", {"outside the map"});
}
TEST_F(BadInputs, StartSealedOffForTheRobots) {
  // The pocket has 4 free cells; the default 9 robots cannot stand there.
  expect_rejected("--map " + dir_ + "/pocket.yaml --start 1.1,0.5", {"pocket.yaml"});
}
TEST_F(BadInputs, UnknownMode) { expect_rejected("--mode fastest", {"fastest", "group-frontier, baseline, ideal"}); }
TEST_F(BadInputs, NonNumericSeed) { expect_rejected("--seed abc", {"seed"}); }
TEST_F(BadInputs, MalformedFreeze) {
  expect_rejected("--freeze leader-1@80", {"--freeze", "AGENT@TICK+SECONDS", "leader-1@80"});
}
TEST_F(BadInputs, FreezeOfAGroupThatDoesNotExist) {
  expect_rejected("--freeze leader-7@80+5", {"faults[0].agent", "leader-7"});
}
TEST_F(BadInputs, FaultTickTooLargeForATick) {
  expect_rejected("--kill member-1-2@99999999999", {"--kill member-1-2@99999999999", "too large"});
}
TEST_F(BadInputs, FreezePastTheParticipantLease) {
  expect_rejected("--freeze leader-1@80+45", {"freeze_seconds", "less than 30", "45"});
}

// Every role fails at start-up (its DDS profile does not exist): swarm run names a failed process
// and its log, exits 1, and leaves no process of the run behind.
TEST(RunFailure, AFailingProcessStopsTheRunAndIsNamed) {
  const std::string dir = fresh_dir("failing_process") + "/run";
  // The roles inherit this test's environment through swarm run.
  setenv("SWARM_DDS_PROFILE", (dir + "/missing-profile.xml").c_str(), 1);
  const CommandResult f = run_swarm("run --scenario " + source_path("scenarios/small.pbtxt") + " --out " + dir);
  unsetenv("SWARM_DDS_PROFILE");
  EXPECT_EQ(f.exit_code, 1) << f.output;
  EXPECT_NE(f.output.find("failed"), std::string::npos) << f.output;
  EXPECT_NE(f.output.find("missing-profile.xml"), std::string::npos) << f.output;
  EXPECT_NE(f.output.find(".log"), std::string::npos) << f.output;
  // No process of that run is still alive (all of them carry the run dir in their arguments;
  // "[s]warm" keeps pgrep from matching the shell that runs it).
  const int alive = std::system(("pgrep -f -- '[s]warm-(sim|gcs|leader|member) .*" + dir + "' > /dev/null").c_str());
  EXPECT_NE(WEXITSTATUS(alive), 0) << "processes of the failed run are still running";
}

// Regression: an abort during Fast DDS's teardown, after the process's work, used to be turned
// into exit 0. A process that dies by a signal, whenever, fails the run and is named.
TEST(RunFailure, AProcessDyingByASignalAfterItsWorkFailsTheRun) {
  const std::string dir = fresh_dir("abort_after_work") + "/run";
  setenv("SWARM_ABORT_AFTER_WORK", "member-0-1", 1);
  const CommandResult f = run_swarm("run --scenario " + source_path("scenarios/small.pbtxt") + " --out " + dir);
  unsetenv("SWARM_ABORT_AFTER_WORK");
  EXPECT_EQ(f.exit_code, 1) << f.output;
  EXPECT_NE(f.output.find("member-0-1"), std::string::npos) << f.output;
  EXPECT_NE(f.output.find("signal 6"), std::string::npos) << f.output;
}

}  // namespace
}  // namespace swarm::test
