// `swarm run` in pieces (flags, process list, metrics summary) and whole, with shell scripts
// standing in for the role binaries; `swarm render` on a run directory.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarm_test/files.hpp"
#include "swarm_test/metrics_fixture.hpp"
#include "commands.hpp"
#include "run_command.hpp"
#include "swarm/record/record.hpp"
#include "swarm_test/text.hpp"

namespace fs = std::filesystem;
using namespace swarm::tools;
namespace cfg = swarm::config;

namespace {

// The numbers the summary tests expect (368 steps, 99 % at 351, 17 rounds, 1.23 MB in 4321 messages).
swarm::record::RunMetrics summary_fixture() {
  swarm::record::RunMetrics m = swarm::test::run_metrics("small", "group-frontier", 1, 368, 17, true, 0.995);
  m.steps_to_99 = 351;
  m.ticks_run = 368;
  m.wall_seconds = 12.5;
  m.ticks_per_second = 368 / 12.5;
  m.traffic.total_messages = 4321;
  m.traffic.total_bytes = 1234567;
  return m;
}

using swarm::test::slurp;
using swarm::test::spit;
using swarm::test::TempDir;

using swarm::test::contains;

// Shell scripts named like the role binaries. Each prints its arguments (into its log); the GCS
// copies a prepared run record and metrics file into --run-dir; `leader_script` is the body of
// every leader.
std::string fake_bin(const TempDir& dir, const std::string& leader_script = "exit 0",
                     const std::string& sim_script = "exit 0", const std::string& gcs_script = "") {
  const std::string bin = dir.file("bin");
  const std::string fixtures = dir.file("fixtures");
  fs::create_directories(bin);
  fs::create_directories(fixtures);
  {
    swarm::record::RecordWriter w(fixtures + "/run.pb");
    swarm::record::Frame f;
    f.mutable_header()->set_width(20);
    f.mutable_header()->set_height(10);
    f.mutable_header()->set_groups(1);
    f.mutable_header()->set_robots_per_group(2);
    f.mutable_header()->mutable_scenario()->set_tick_ms(200);
    w.append(f);
    for (std::uint32_t t = 0; t < 10; ++t) {  // two robots standing for ticks 0..9
      swarm::record::Frame p;
      p.mutable_poses()->set_tick(t);
      for (int xy : {1, 1, 2, 1}) p.mutable_poses()->add_xy(xy);
      // Bytes sent so far per link class (sim_robot, member_leader, leader_gcs, telemetry,
      // control): 1000, 100 and 10 a tick on the first three.
      for (std::uint64_t b : {1000U * t, 100U * t, 10U * t, 0U, 0U}) p.mutable_poses()->mutable_tally()->add_sent_bytes(b);
      w.append(p);
    }
    swarm::record::Frame s;
    s.mutable_summary()->set_steps(368);
    s.mutable_summary()->set_planning_rounds(17);
    w.append(s);
  }
  swarm::record::write_metrics(fixtures + "/metrics.json", summary_fixture());
  const std::string args = "echo \"args: $*\"\n";
  const std::string run_dir =
      "while [ $# -gt 0 ]; do case \"$1\" in --run-dir) RUN=\"$2\"; shift;; esac; shift; done\n";
  auto script = [&](const std::string& name, const std::string& body) {
    const std::string path = bin + "/" + name;
    spit(path, "#!/bin/sh\n" + args + body + "\n");
    ::chmod(path.c_str(), 0755);
  };
  script("swarm-sim", sim_script);
  script("swarm-member", "exit 0");
  script("swarm-leader", leader_script);
  script("swarm-gcs", run_dir + (gcs_script.empty() ? "cp " + fixtures + "/run.pb \"$RUN/run.pb\"\ncp " + fixtures +
                                                          "/metrics.json \"$RUN/metrics.json\"\nprintf 'progress 100%%\\n'"
                                                    : gcs_script));
  return bin;
}

RunOptions small_run(const TempDir& dir, const std::string& bin) {
  RunOptions o;
  o.overrides.map = "small";
  o.overrides.groups = 1;
  o.overrides.robots_per_group = 2;
  o.out_dir = dir.file("run");
  o.bin_dir = bin;
  o.timeout = std::chrono::seconds(60);
  return o;
}

// A run of `small` into DIR/run, by simple discovery (no discovery server to start).
RunOptions local_run(const TempDir& dir) {
  RunOptions o;
  o.overrides.map = "small";
  o.discovery = RunOptions::Discovery::Simple;
  o.out_dir = dir.file("run");
  return o;
}

}  // namespace

TEST(RunOverrides, MapChangeClearsTheStartUnlessStartIsGiven) {
  swarm::scenario::Scenario s;
  s.set_map("maze1");
  s.mutable_start()->set_x(1);
  s.mutable_start()->set_y(2);
  RunOverrides o;
  o.map = "maze1";  // the same map keeps the start
  apply_overrides(s, o);
  EXPECT_TRUE(s.has_start());
  o.map = "maze2";
  apply_overrides(s, o);
  EXPECT_FALSE(s.has_start());
  EXPECT_EQ(s.map(), "maze2");
  o.map = "open";
  o.start = "3.5,-4";
  apply_overrides(s, o);
  ASSERT_TRUE(s.has_start());
  EXPECT_DOUBLE_EQ(s.start().x(), 3.5);
  EXPECT_DOUBLE_EQ(s.start().y(), -4);
}

TEST(RunOverrides, FieldsAndModes) {
  swarm::scenario::Scenario s;
  RunOverrides o;
  o.groups = 4;
  o.robots_per_group = 2;
  o.seed = 99;
  o.max_ticks = 123;
  o.mode = "ideal";
  apply_overrides(s, o);
  EXPECT_EQ(s.groups(), 4u);
  EXPECT_EQ(s.robots_per_group(), 2u);
  EXPECT_EQ(s.seed(), 99u);
  EXPECT_EQ(s.max_ticks(), 123u);
  EXPECT_EQ(s.explore().mode(), swarm::scenario::IDEAL);
}

// A chained --mission without --max-ticks gets the scenario's limit once per phase; --max-ticks wins.
TEST(RunOverrides, AChainedMissionGetsMaxTicksPerPhase) {
  swarm::scenario::Scenario s;
  s.set_max_ticks(3000);
  RunOverrides o;
  o.mission = {"explore", "cover", "mapf", "collect"};
  apply_overrides(s, o);
  EXPECT_EQ(s.max_ticks(), 12000u);
  EXPECT_EQ(s.mission().phase_size(), 4);
  swarm::scenario::Scenario one;
  one.set_max_ticks(3000);
  o.mission = {"cover"};
  apply_overrides(one, o);
  EXPECT_EQ(one.max_ticks(), 3000u);
  swarm::scenario::Scenario given;
  o.mission = {"explore", "cover"};
  o.max_ticks = 500;
  apply_overrides(given, o);
  EXPECT_EQ(given.max_ticks(), 500u);
}

TEST(RunOverrides, MalformedValuesAreConfigErrorsNamingTheFlag) {
  swarm::scenario::Scenario s;
  RunOverrides o;
  o.start = "3;4";
  try {
    apply_overrides(s, o);
    FAIL() << "no error";
  } catch (const cfg::ConfigError& e) {
    EXPECT_TRUE(contains(e.what(), "--start")) << e.what();
    EXPECT_TRUE(contains(e.what(), "3;4")) << e.what();
  }
  RunOverrides m;
  m.mode = "fastest";
  EXPECT_THROW(apply_overrides(s, m), cfg::ConfigError);
}

TEST(RunProcesses, NamesArgumentsAndLogs) {
  swarm::scenario::Scenario s;
  s.set_groups(2);
  s.set_robots_per_group(3);
  RunLaunch l;
  l.run_dir = "/r";
  l.scenario_path = "/r/scenario.pbtxt";
  l.bin_dir = "/b";
  l.domain_id = 42;
  l.partition = "swarm-1-2";
  const auto procs = build_run_processes(l, s);
  std::vector<std::string> names;
  for (const auto& p : procs) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"sim", "gcs", "leader-0", "leader-1", "member-0-1",
                                             "member-0-2", "member-1-1", "member-1-2"}));
  const std::vector<std::string> common = {"--scenario", "/r/scenario.pbtxt", "--run-dir", "/r",
                                           "--domain",   "42",                "--partition",
                                           "swarm-1-2"};
  auto expect_args = [&](const ProcessSpec& p, const std::string& exe,
                         std::vector<std::string> role, std::vector<std::string> tail) {
    std::vector<std::string> want{"/b/" + exe};
    want.insert(want.end(), role.begin(), role.end());
    want.insert(want.end(), common.begin(), common.end());
    want.insert(want.end(), tail.begin(), tail.end());
    EXPECT_EQ(p.argv, want) << p.name;
    EXPECT_EQ(p.log_path, "/r/logs/" + p.name + ".log");
  };
  expect_args(procs[0], "swarm-sim", {}, {});
  expect_args(procs[1], "swarm-gcs", {}, {"--progress", "plain"});
  expect_args(procs[3], "swarm-leader", {"--group", "1"}, {});
  expect_args(procs[5], "swarm-member", {"--group", "0", "--index", "2"}, {});
  EXPECT_TRUE(procs[1].echo_stdout);
  EXPECT_FALSE(procs[0].echo_stdout);
  l.progress_bar = true;
  EXPECT_EQ(build_run_processes(l, s)[1].argv.back(), "bar");
}

TEST(RunProcesses, DomainPartitionAndDefaultDir) {
  EXPECT_EQ(domain_id_for(0), 1);
  EXPECT_EQ(domain_id_for(47), 48);
  EXPECT_EQ(domain_id_for(48), 1);
  EXPECT_EQ(partition_name(77, 123456789), "swarm-77-123456789");
  swarm::scenario::Scenario s;
  s.set_map("/some/where/office.yaml");
  s.mutable_explore()->set_mode(swarm::scenario::BASELINE);
  s.set_seed(7);
  const std::string d = default_run_dir(s, 0);
  EXPECT_TRUE(std::regex_match(d, std::regex(R"(runs/\d{8}-\d{6}-office-baseline-s7)"))) << d;
}

// Two runs prepared at once never share a DDS domain (their participant ids, so their ports, would
// be the same), and an explicit domain another run holds is refused by name.
TEST(RunProcesses, ConcurrentRunsHoldDifferentDomains) {
  swarm::test::TempDir dir;
  RunOptions o;
  o.overrides.map = "small";
  o.discovery = RunOptions::Discovery::Simple;
  o.preferred_domain = 7;
  o.out_dir = dir.file("a");
  const PreparedRun a = prepare_run(o);
  o.out_dir = dir.file("b");
  const PreparedRun b = prepare_run(o);
  // Other tests may hold domains meanwhile: the search goes on to the next free one.
  EXPECT_GE(a.launch.domain_id, 7);
  EXPECT_GT(b.launch.domain_id, a.launch.domain_id);
  EXPECT_LE(b.launch.domain_id, kAutoDomains);
  o.out_dir = dir.file("c");
  o.domain_id = a.launch.domain_id;
  const std::string held = "DDS domain " + std::to_string(a.launch.domain_id) + " is in use by another swarm run";
  try {
    (void)prepare_run(o);
    ADD_FAILURE() << "domain " << a.launch.domain_id << " was given twice";
  } catch (const cfg::ConfigError& e) {
    EXPECT_TRUE(swarm::test::contains(e.what(), held)) << e.what();
  }
  EXPECT_EQ(discovery_server_port(7), 7400 + 3500 + 495);
}

TEST(RunCommandHelpers, LastLinesKeepWhatATerminalShows) {
  TempDir dir;
  spit(dir.file("log"), "1\n2\n3\n4\r\n10%\r50%\r100%\n");
  EXPECT_EQ(last_lines(dir.file("log"), 3), (std::vector<std::string>{"3", "4", "100%"}));
  EXPECT_EQ(last_lines(dir.file("log"), 10).size(), 5u);
  EXPECT_TRUE(last_lines(dir.file("missing"), 10).empty());
}

TEST(RunCommandHelpers, MetricsSummary) {
  TempDir dir;
  swarm::record::write_metrics(dir.file("m.json"), summary_fixture());
  const std::string s = summarize_metrics(dir.file("m.json"));
  EXPECT_TRUE(contains(s, "steps            368 (99 % explored at step 351)")) << s;
  EXPECT_TRUE(contains(s, "planning rounds  17")) << s;
  EXPECT_TRUE(contains(s, "explored         99.5 %")) << s;
  EXPECT_TRUE(contains(s, "wall time        12.5 s (29.4 ticks/s)")) << s;
  EXPECT_TRUE(contains(s, "traffic          1.23 MB in 4321 messages")) << s;
  EXPECT_TRUE(contains(s, "complete")) << s;
  // steps_to_99 is null when 99 % was never reached; the line then has no "(99 % ...)".
  auto incomplete = summary_fixture();
  incomplete.steps = 10;
  incomplete.steps_to_99.reset();
  incomplete.complete = false;
  swarm::record::write_metrics(dir.file("n.json"), incomplete);
  const std::string n = summarize_metrics(dir.file("n.json"));
  EXPECT_TRUE(contains(n, "steps            10\n")) << n;
  EXPECT_TRUE(contains(n, "INCOMPLETE")) << n;
  spit(dir.file("bad.json"), "{not json");
  EXPECT_THROW((void)summarize_metrics(dir.file("bad.json")), std::runtime_error);
  // The robot held up longest; a mapf phase the GCS called complete while the simulator saw a
  // robot off its goal.
  auto mapf = summary_fixture();
  mapf.motion.per_robot["member-0-1"].longest_blocked_ticks = 4;
  mapf.motion.per_robot["member-1-2"].longest_blocked_ticks = 31;
  swarm::record::PhaseMetrics ph;
  ph.name = "mapf";
  ph.complete = false;
  ph.ground_truth_done = false;
  ph.disagreement = "the GCS judged the phase complete; by the simulator's ground truth its work is not done";
  ph.task = {{"ground_truth_at_goal", 8}, {"ground_truth_living", 9}};
  mapf.phases.push_back(ph);
  mapf.complete = false;
  swarm::record::write_metrics(dir.file("mapf.json"), mapf);
  const std::string g = summarize_metrics(dir.file("mapf.json"));
  EXPECT_TRUE(contains(g, "longest block    31 ticks in a row (member-1-2)")) << g;
  EXPECT_TRUE(contains(g, "8/9 robots at goal (ground truth)")) << g;
  EXPECT_TRUE(contains(g, "INCOMPLETE: phase mapf: the GCS judged the phase complete; by the simulator's ground truth")) << g;
  EXPECT_TRUE(contains(g, "    they disagree: the GCS judged the phase complete")) << g;
  EXPECT_THROW((void)summarize_metrics(dir.file("none.json")), std::runtime_error);
  // A required key missing, or another schema version, is an error naming it.
  auto j = swarm::record::to_json(summary_fixture());
  j.erase("explored_fraction");
  spit(dir.file("missing.json"), j.dump());
  try {
    (void)summarize_metrics(dir.file("missing.json"));
    ADD_FAILURE() << "no error for a missing key";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), "missing key 'explored_fraction'")) << e.what();
  }
  j = swarm::record::to_json(summary_fixture());
  j["schema_version"] = 1;
  spit(dir.file("old.json"), j.dump());
  try {
    (void)summarize_metrics(dir.file("old.json"));
    ADD_FAILURE() << "no error for an unknown schema version";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), "schema_version 1")) << e.what();
  }
}

TEST(RunCommand, SuccessWritesTheRunDirectoryPictureAndSummary) {
  TempDir dir;
  const RunOptions o = small_run(dir, fake_bin(dir));
  std::ostringstream out, err;
  ASSERT_EQ(run_command(o, out, err), 0) << err.str();
  const std::string run = o.out_dir;
  EXPECT_TRUE(contains(out.str(), "steps            368")) << out.str();
  EXPECT_TRUE(contains(out.str(), "run dir: " + run)) << out.str();
  EXPECT_TRUE(fs::exists(run + "/map.png"));
  // Traffic over time in 1 s bins of 5 ticks of 200 ms: up to tick 4, then ticks 5..9; the
  // simulator's sensing of the robots last, labelled as on the robot.
  EXPECT_TRUE(fs::exists(run + "/traffic.png"));
  EXPECT_EQ(slurp(run + "/traffic.csv"),
            "second,member_leader_bytes_per_s,leader_gcs_bytes_per_s,telemetry_bytes_per_s,control_bytes_per_s,"
            "sim_robot_on_robot_bytes_per_s\n1,400,40,0,0,4000\n2,500,50,0,0,5000\n");
  // The roles got one scenario file, written from the flags.
  const auto scenario = cfg::load_scenario(run + "/scenario.pbtxt");
  EXPECT_EQ(scenario.map(), "small");
  EXPECT_EQ(scenario.groups(), 1u);
  EXPECT_TRUE(scenario.has_start());  // resolved, so every role uses the same one
  const std::string leader_log = slurp(run + "/logs/leader-0.log");
  const std::regex leader_args("args: --group 0 --scenario " + run + "/scenario.pbtxt --run-dir " +
                               run + " --domain \\d+ --partition swarm-\\d+-\\d+");
  EXPECT_TRUE(std::regex_search(leader_log, leader_args)) << leader_log;
  EXPECT_TRUE(contains(slurp(run + "/logs/member-0-1.log"), "--index 1"));
  EXPECT_TRUE(contains(slurp(run + "/logs/gcs.log"), "--progress "));
  EXPECT_TRUE(contains(slurp(run + "/logs/gcs.log"), "progress 100%"));

  // `swarm render` on the same directory.
  std::ostringstream rout, rerr;
  RenderOptions r;
  r.run_dir = run;
  r.tick = 5;
  EXPECT_EQ(render_command(r, rout, rerr), 0) << rerr.str();
  EXPECT_TRUE(fs::exists(run + "/frontiers-5.png"));
}

TEST(RunCommand, AFailingRoleIsNamedWithItsLogTail) {
  TempDir dir;
  const RunOptions o =
      small_run(dir, fake_bin(dir, "echo 'no route to planner' >&2; exit 3", "exec sleep 30"));
  std::ostringstream out, err;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run_command(o, out, err), 1);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  const std::string log = o.out_dir + "/logs/leader-0.log";
  EXPECT_TRUE(
      contains(err.str(), "swarm run: process leader-0 failed (exit code 3); its log: " + log))
      << err.str();
  EXPECT_TRUE(contains(err.str(), "  | no route to planner")) << err.str();
}

TEST(RunCommand, BadFlagsAndScenariosExit2) {
  TempDir dir;
  const std::string bin = fake_bin(dir);
  auto run_with = [&](auto tweak) {
    RunOptions o = small_run(dir, bin);
    tweak(o);
    std::ostringstream out, err;
    const int rc = run_command(o, out, err);
    EXPECT_TRUE(err.str().rfind("swarm run: ", 0) == 0) << err.str();
    return rc;
  };
  EXPECT_EQ(run_with([](RunOptions& o) { o.overrides.mode = "fastest"; }), 2);
  EXPECT_EQ(run_with([](RunOptions& o) { o.overrides.start = "x"; }), 2);
  EXPECT_EQ(run_with([](RunOptions& o) { o.overrides.groups = 0; }), 2);
  EXPECT_EQ(run_with([](RunOptions& o) { o.overrides.map = "no-such-map"; }), 2);
  EXPECT_EQ(run_with([&](RunOptions& o) { o.scenario_path = dir.file("missing.pbtxt"); }), 2);
  spit(dir.file("file"), "");
  EXPECT_EQ(run_with([&](RunOptions& o) { o.out_dir = dir.file("file") + "/run"; }), 2);
  // A kill of a robot that shares its process (it would take the others along).
  EXPECT_EQ(run_with([](RunOptions& o) {
              o.overrides.groups = 1;
              o.overrides.robots_per_group = 3;
              o.agents_per_process = 2;
              o.overrides.kills = {"member-0-1@10"};
            }),
            2);
}

TEST(RunCommand, MissingRoleBinaryExits1BeforeCreatingAnything) {
  TempDir dir;
  RunOptions o = small_run(dir, dir.file("empty-bin"));
  std::ostringstream out, err;
  EXPECT_EQ(run_command(o, out, err), 1);
  EXPECT_TRUE(contains(err.str(), "swarm-sim")) << err.str();
  EXPECT_FALSE(fs::exists(o.out_dir));
}

TEST(RunCommand, AFailedRunStillEndsWithMetricsSayingWhy) {
  // The GCS wrote its metrics (the run ended itself), then a leader failed: incomplete, and why.
  TempDir dir;
  const RunOptions o = small_run(dir, fake_bin(dir, "sleep 1; exit 3"));
  std::ostringstream out, err;
  EXPECT_EQ(run_command(o, out, err), 1);
  EXPECT_TRUE(contains(err.str(), "what the run did up to the stop, and why it stopped: " + o.out_dir + "/metrics.json"))
      << err.str();
  const auto m = swarm::record::read_metrics(o.out_dir + "/metrics.json");
  EXPECT_FALSE(m.complete);
  EXPECT_EQ(m.ended, "process leader-0 failed (exit code 3) (the GCS: complete)");
}

TEST(RunCommand, WithoutTheGcsMetricsTheRecordSaysWhatIsKnown) {
  // The GCS died with its metrics: the launcher writes what the record holds up to its last
  // whole frame, marked partial, which read_metrics refuses by name.
  TempDir dir;
  const std::string fixtures = dir.file("fixtures");
  const std::string bin = fake_bin(dir, "exit 0", "exit 0",
                                   "head -c 40 " + fixtures + "/run.pb > \"$RUN/run.pb\"; kill -9 $$");
  const RunOptions o = small_run(dir, bin);
  std::ostringstream out, err;
  EXPECT_EQ(run_command(o, out, err), 1);
  const auto j = nlohmann::json::parse(slurp(o.out_dir + "/metrics.json"));
  EXPECT_EQ(j.at("partial"), true);
  EXPECT_EQ(j.at("complete"), false);
  EXPECT_EQ(j.at("ended"), "process gcs was killed by signal 9 (Killed)");
  EXPECT_TRUE(j.at("ticks_run").is_number()) << j.dump();
  EXPECT_TRUE(contains(j.at("record").get<std::string>(), "truncated")) << j.dump();
  try {
    (void)swarm::record::read_metrics(o.out_dir + "/metrics.json");
    ADD_FAILURE() << "a partial metrics.json was read as whole";
  } catch (const swarm::record::MetricsError& e) {
    EXPECT_TRUE(contains(e.what(), "the run ended early (process gcs was killed")) << e.what();
  }
}

TEST(RunCommand, CheckResolvesTheRunAndStartsNothing) {
  TempDir dir;
  RunOptions o = small_run(dir, fake_bin(dir));
  std::ostringstream out, err;
  EXPECT_EQ(check_run_command(o, out, err), 0) << err.str();
  EXPECT_TRUE(contains(out.str(), "would run small")) << out.str();
  EXPECT_TRUE(contains(out.str(), "1 x 2 robots, mission explore")) << out.str();
  EXPECT_FALSE(fs::exists(o.out_dir));
  o.overrides.groups = 0;
  std::ostringstream out2, err2;
  EXPECT_EQ(check_run_command(o, out2, err2), 2);
  EXPECT_TRUE(contains(err2.str(), "field groups: must be >= 1")) << err2.str();
}

TEST(RunProcesses, AnEarlierRunsResultsAreNotTakenForThisOnes) {
  TempDir dir;
  const RunOptions o = local_run(dir);
  fs::create_directories(o.out_dir);
  for (const char* f : {"metrics.json", "run.pb", "map.png"}) spit(o.out_dir + "/" + f, "an earlier run's");
  const PreparedRun run = prepare_run(o);
  for (const char* f : {"metrics.json", "run.pb", "map.png"}) EXPECT_FALSE(fs::exists(o.out_dir + "/" + f)) << f;
}

TEST(RunProcesses, ARunDirectoryTakesOneRunAtATime) {
  TempDir dir;
  const RunOptions o = local_run(dir);
  const PreparedRun a = prepare_run(o);
  try {
    (void)prepare_run(o);
    ADD_FAILURE() << "two runs were let into one directory";
  } catch (const cfg::ConfigError& e) {
    EXPECT_TRUE(contains(e.what(), "--out " + o.out_dir + ": another swarm run is writing to this directory"))
        << e.what();
  }
}

TEST(RenderCommand, ATickPastTheRunIsRefused) {
  TempDir dir;
  const RunOptions o = small_run(dir, fake_bin(dir));
  std::ostringstream out, err;
  ASSERT_EQ(run_command(o, out, err), 0) << err.str();
  RenderOptions r;
  r.run_dir = o.out_dir;
  r.tick = 99999;
  std::ostringstream rout, rerr;
  EXPECT_EQ(render_command(r, rout, rerr), 2);
  EXPECT_TRUE(contains(rerr.str(), "--tick 99999: " + o.out_dir + "/run.pb holds ticks 0..9")) << rerr.str();
  EXPECT_FALSE(fs::exists(o.out_dir + "/frontiers-99999.png"));
}

TEST(RenderCommand, ATruncatedRecordIsDrawnUpToItsLastWholeFrame) {
  TempDir dir;
  const RunOptions o = small_run(dir, fake_bin(dir));
  std::ostringstream out, err;
  ASSERT_EQ(run_command(o, out, err), 0) << err.str();
  std::ofstream(o.out_dir + "/run.pb", std::ios::app | std::ios::binary) << "\x40half a frame";
  RenderOptions r;
  r.run_dir = o.out_dir;
  std::ostringstream rout, rerr;
  EXPECT_EQ(render_command(r, rout, rerr), 0) << rerr.str();
  EXPECT_TRUE(contains(rerr.str(), "truncated")) << rerr.str();
  EXPECT_TRUE(contains(rerr.str(), "(up to tick 9)")) << rerr.str();
}

TEST(RenderCommand, MissingOrDamagedRunDirExits2) {
  TempDir dir;
  std::ostringstream out, err;
  RenderOptions r;
  r.run_dir = dir.file("nope");
  EXPECT_EQ(render_command(r, out, err), 2);
  EXPECT_TRUE(contains(err.str(), "not a directory")) << err.str();
  r.run_dir = dir.str();
  EXPECT_EQ(render_command(r, out, err), 2);  // no run.pb
  spit(dir.file("run.pb"), "\x10garbage");
  std::ostringstream err2;
  EXPECT_EQ(render_command(r, out, err2), 2);
  EXPECT_TRUE(contains(err2.str(), "truncated") || contains(err2.str(), "corrupt")) << err2.str();
}
