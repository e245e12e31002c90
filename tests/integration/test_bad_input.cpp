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

// The holes a probe of ~290 hostile inputs found: each is refused with exit 2 and the flag or
// field named.
TEST_F(BadInputs, SeedsOutOfRangeAreRefusedNotWrapped) {
  expect_rejected("--seed -1", {"--seed", "must be a whole number in [0, 18446744073709551615]", "got -1"});
  expect_rejected("--seed 99999999999999999999", {"--seed", "got 99999999999999999999"});
}
TEST_F(BadInputs, AScenarioThatIsADirectory) {
  expect_rejected("--scenario " + dir_, {dir_, "is a directory, not a scenario file"});
}
TEST_F(BadInputs, ExtremeMapResolutions) {
  write(dir_ + "/huge.yaml", "image: pocket.pgm\nresolution: 1e308\norigin: [0.0, 0.0, 0.0]\n");
  write(dir_ + "/tiny.yaml", "image: pocket.pgm\nresolution: 1e-300\norigin: [0.0, 0.0, 0.0]\n");
  expect_rejected("--map " + dir_ + "/huge.yaml", {"huge.yaml:2", "resolution must be a number of metres per cell in [0.001, 1000]"});
  expect_rejected("--map " + dir_ + "/tiny.yaml", {"tiny.yaml:2", "[0.001, 1000]"});
  write(dir_ + "/five.map", "type octile\nheight 2\nwidth 3\nmap\n...\n...\n");
  expect_rejected("--map " + dir_ + "/five.map --map-resolution 1e308", {"--map-resolution", "[0.001, 1000]"});
}
TEST_F(BadInputs, MapFilesWithMoreDataThanTheirHeaderSays) {
  std::string rows;
  for (int r = 0; r < 10; ++r) rows += "..........\n";
  write(dir_ + "/tall.map", "type octile\nheight 5\nwidth 10\nmap\n" + rows);
  expect_rejected("--map " + dir_ + "/tall.map", {"tall.map:10", "past the 5 rows"});
  write(dir_ + "/long.pgm", "P5\n2 2\n255\n" + std::string(6, '\xfe'));
  write(dir_ + "/long.yaml", "image: long.pgm\nresolution: 0.2\norigin: [0.0, 0.0, 0.0]\n");
  expect_rejected("--map " + dir_ + "/long.yaml", {"long.pgm", "expected 4 bytes", "found 6"});
}
TEST_F(BadInputs, ARobotKilledTwiceOrAfterTheLastTick) {
  expect_rejected("--kill member-0-1@5 --kill member-0-1@8", {"faults[1].agent", "killed once"});
  expect_rejected("--kill member-0-1@100000 --max-ticks 20", {"faults[0].kill_at_tick", "below max_ticks (20)"});
}
TEST_F(BadInputs, ABadStartIsTheFlagsNotTheDefaultScenarios) {
  expect_rejected("--map " + dir_ + "/pocket.yaml --start 50,50", {"with --start 50,50", "outside the map"});
}
TEST_F(BadInputs, FootprintAndTimeLimitsInAScenario) {
  write(dir_ + "/footprint.pbtxt", "footprint_radius: 4000000000\n");
  expect_rejected("--scenario " + dir_ + "/footprint.pbtxt", {"footprint_radius", "[0, 64]"});
  write(dir_ + "/w.pbtxt", "mission { phase { mapf { w: nan } } }\n");
  expect_rejected("--scenario " + dir_ + "/w.pbtxt", {"mission.phase[0].mapf.w", "got nan"});
}

TEST(BadCommands, AnUnknownCommandIsNamed) {
  CommandResult r = run_swarm("frobnicate");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("swarm: unknown command 'frobnicate' (expected one of run, render"), std::string::npos) << r.output;
  r = run_swarm("experiment frobnicate");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("swarm experiment: unknown command 'frobnicate'"), std::string::npos) << r.output;
}

TEST(BadCommands, AWholeNumberWithALeadingZeroIsDecimal) {
  // CLI11 reads "010" as octal (8): the check rewrites it first.
  const CommandResult r = run_swarm("run --check --map small --seed 010");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("seed 10;"), std::string::npos) << r.output;
}

TEST(BadCommands, RangesReadAsNumbersAPersonWrites) {
  // Not CLI11's "Value 0 not in range 0.000000 to <309 digits>".
  const CommandResult r = run_swarm("render . --scale 0");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--scale: must be a number in [1, 64] (got 0)"), std::string::npos) << r.output;
  EXPECT_LT(r.output.size(), 300u) << r.output;
}

TEST(BadCommands, OfflineToolsRefuseNaNAndTakeAnyTimeLimit) {
  const std::string dir = fresh_dir("offline_numbers");
  CommandResult r = run_swarm("mapf --map small --random 2 --solver ecbs --w nan --out " + dir + "/w");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--w: must be a finite number >= 1"), std::string::npos) << r.output;
  r = run_swarm("darp --map small --count 2 --seed 99999999999999999999 --out " + dir + "/s");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--seed: must be a whole number"), std::string::npos) << r.output;
  // A limit past the clock's range is no limit, never "timed out after 0 s".
  for (const char* limit : {"1e10", "inf", "1e300"}) {
    r = run_swarm(std::string("mapf --map small --random 2 --time-limit ") + limit + " --out " + dir + "/m");
    EXPECT_EQ(r.exit_code, 0) << limit << ": " << r.output;
    EXPECT_EQ(r.output.find("timeout"), std::string::npos) << limit << ": " << r.output;
  }
  r = run_swarm("darp --map small --count 3 --method darp --time-limit inf --out " + dir + "/d");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_json(dir + "/d/result.json").at("status"), "converged") << r.output;
}

// A run stopped early still ends with metrics.json: what it did up to the stop, and why. Each run
// is stopped 12 s after it starts, not 6: each check wants ticks run before the stop, and starting
// eleven processes and their discovery is slow on a loaded CI machine (a 6 s stop failed there).
TEST(RunStoppedEarly, ATimeoutEndsTheRunWithItsMetrics) {
  const std::string dir = fresh_dir("stopped_by_timeout") + "/run";
  const CommandResult r = run_swarm("run --scenario " + source_path("scenarios/small.pbtxt") +
                                    " --realtime --tick-ms 250 --max-ticks 2000 --timeout 12 --out " + dir);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const nlohmann::json m = read_json(dir + "/metrics.json");
  EXPECT_EQ(m.at("complete"), false) << m.dump();
  EXPECT_EQ(m.at("ended").get<std::string>().rfind("timed out after 12 s", 0), 0u) << m.at("ended");
  EXPECT_GT(m.at("ticks_run").get<int>(), 5) << m.dump();
  EXPECT_FALSE(m.contains("partial")) << "the GCS's own metrics, up to the stop";
}

TEST(RunStoppedEarly, AnInterruptEndsTheRunWithItsMetrics) {
  const std::string dir = fresh_dir("stopped_by_sigint") + "/run";
  // `timeout -s INT` interrupts swarm run as a Ctrl-C would.
  const std::string cmd = "timeout --preserve-status -s INT 12 " + std::string(SWARM_BIN_DIR) + "/swarm run --scenario " +
                          source_path("scenarios/small.pbtxt") + " --realtime --tick-ms 250 --max-ticks 2000 --out " +
                          dir + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const nlohmann::json m = read_json(dir + "/metrics.json");
  EXPECT_EQ(m.at("complete"), false) << m.dump();
  EXPECT_EQ(m.at("ended").get<std::string>().rfind("interrupted", 0), 0u) << m.at("ended");
  EXPECT_GT(m.at("ticks_run").get<int>(), 5) << m.dump();
}

TEST(RunStoppedEarly, AMemberKilledMidRunLeavesTheGcsMetricsSayingSo) {
  const std::string dir = fresh_dir("stopped_by_a_crash") + "/run";
  // kill -9 of a member's process while the run goes on (not a planned fault).
  const std::string cmd = "sh -c '" + std::string(SWARM_BIN_DIR) + "/swarm run --scenario " +
                          source_path("scenarios/small.pbtxt") + " --realtime --tick-ms 250 --max-ticks 2000 --out " + dir +
                          " > /dev/null 2>&1 & p=$!; sleep 12; pkill -9 -f \"[s]warm-member .*" + dir +
                          "\"; wait $p; exit $?'";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const nlohmann::json m = read_json(dir + "/metrics.json");
  EXPECT_EQ(m.at("complete"), false) << m.dump();
  EXPECT_NE(m.at("ended").get<std::string>().find("was killed by signal 9"), std::string::npos) << m.at("ended");
  EXPECT_FALSE(m.contains("partial")) << "the simulator ended the run, and the GCS wrote what it knew";
  EXPECT_GT(m.at("ticks_run").get<int>(), 5) << m.dump();
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
  // Its metrics say the run did not end cleanly, and why.
  const nlohmann::json m = read_json(dir + "/metrics.json");
  EXPECT_EQ(m.at("complete"), false);
  EXPECT_NE(m.at("ended").get<std::string>().find("member-0-1 was killed by signal 6"), std::string::npos) << m.at("ended");
}

}  // namespace
}  // namespace swarm::test
