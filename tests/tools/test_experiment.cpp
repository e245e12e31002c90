// `swarm experiment` / `swarm report` without running a swarm: plans, the manifest, the tables and
// CSV computed from fabricated run directories, failed runs, and bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "swarm_test/files.hpp"
#include "swarm_test/metrics_fixture.hpp"
#include "experiment.hpp"
#include "experiment_analysis.hpp"
#include "experiment_command.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm_test/text.hpp"

using namespace swarm::tools;
namespace fs = std::filesystem;

namespace {

using swarm::test::slurp;
using swarm::test::spit;
using swarm::test::TempDir;

using swarm::test::contains;

// A run directory as the GCS leaves it (only what the experiment reads).
void fake_run(const std::string& dir, const std::string& map, const std::string& mode, int seed,
              int steps, int rounds, bool complete = true, double explored = 0.999) {
  spit(dir + "/metrics.json", swarm::record::to_json(swarm::test::run_metrics(map, mode, static_cast<std::uint64_t>(seed),
                                                        static_cast<std::uint32_t>(steps),
                                                        static_cast<std::uint32_t>(rounds), complete, explored)).dump(2));
  spit(dir + "/scenario.pbtxt", "map: \"" + map + "\"\ntick_seconds: 0.2\n");
}

ExperimentPlan explore_plan(std::uint32_t seeds) {
  swarm::scenario::Scenario base;
  return make_plan(ExperimentKind::kExplore, {"open", "maze1"}, {"group-frontier", "baseline"},
                   seeds, base, "");
}

// Fills DIR with the runs of explore_plan(2): group-frontier 10 % faster; one baseline run failed.
ExperimentPlan fake_explore(const std::string& dir) {
  ExperimentPlan plan = explore_plan(2);
  for (ExperimentRun& r : plan.runs) {
    if (r.method == "baseline" && r.map == "maze1" && r.seed == 2) {
      r.status = RunStatus::kFailed;
      r.failure = "process leader-1 failed (exit code 3)";
      r.log = r.dir + "/logs/leader-1.log";
      continue;
    }
    const int base = r.map == "open" ? 200 : 600;
    const int steps = (r.method == "baseline" ? base : base * 9 / 10) + static_cast<int>(r.seed) * 4;
    fake_run(dir + "/" + r.dir, r.map, r.method, static_cast<int>(r.seed), steps, steps / 20);
    r.status = RunStatus::kOk;
  }
  write_manifest(dir, plan);
  return plan;
}

// `swarm report DIRS --out OUT`: its exit status, what it printed and what it said was wrong.
struct Reported {
  int status;
  std::string out, err;
};
Reported report_of(std::vector<std::string> dirs, const std::string& out_dir) {
  std::ostringstream out, err;
  ReportOptions r;
  r.dirs = std::move(dirs);
  r.out_dir = out_dir;
  const int status = report_command(r, out, err);
  return {status, out.str(), err.str()};
}

}  // namespace

TEST(ExperimentPlan, ExploreRunsEveryMapMethodAndSeedWithPicturesForSeedOne) {
  const ExperimentPlan p = explore_plan(3);
  ASSERT_EQ(p.runs.size(), 2u * 2u * 3u);
  EXPECT_EQ(p.runs[0].dir, "runs/open-group-frontier-s1");
  EXPECT_TRUE(p.runs[0].pictures);
  EXPECT_FALSE(p.runs[1].pictures);
  EXPECT_EQ(p.runs.back().dir, "runs/maze1-baseline-s3");
}

TEST(ExperimentPlan, SweepsShareTheirZeroPoint) {
  swarm::scenario::Scenario base;
  base.mutable_explore()->set_replan_threshold_steps(20);
  const ExperimentPlan lat = make_plan(ExperimentKind::kLatency, {"maze1"}, {"group-frontier"}, 1, base, "");
  EXPECT_EQ(lat.leader_gcs_delays_ticks, (std::vector<std::uint32_t>{0, 10, 20, 40, 80}));
  EXPECT_EQ(lat.member_leader_delays_ticks, (std::vector<std::uint32_t>{0, 1, 5, 10}));
  EXPECT_EQ(lat.runs.size(), 5u + 4u - 1u);  // (0, 0) once
  EXPECT_EQ(lat.runs[1].dir, "runs/maze1-group-frontier-lg10-ml0-s1");
  const ExperimentPlan bw = make_plan(ExperimentKind::kBandwidth, {"maze1"}, {"group-frontier"}, 1, base, "");
  // The encodings uncapped (the default one shared by both parts), then 2 links x 2 bases x 5 shares.
  EXPECT_EQ(bw.runs.size(), 3u + 20u);
  EXPECT_EQ(std::count_if(bw.runs.begin(), bw.runs.end(), [](const ExperimentRun& r) { return r.setting.waits_for_demand(); }), 20);
  EXPECT_EQ(bw.runs[3].dir, "runs/maze1-group-frontier-zstd-run-length-lg-mean200-s1");
  SweepChoices absolute;
  absolute.leader_gcs_caps_bytes_per_s = {4000, 16000};
  const ExperimentPlan abs = make_plan(ExperimentKind::kBandwidth, {"maze1"}, {"group-frontier"}, 1, base, "", absolute);
  EXPECT_EQ(abs.runs.size(), 3u + 2u);  // the unlimited reference is the uncapped default encoding
  const ExperimentPlan loss = make_plan(ExperimentKind::kLoss, {"maze1"}, {"baseline"}, 2, base, "");
  EXPECT_EQ(loss.runs.size(), 3u * 2u);
  EXPECT_EQ(loss.runs[2].dir, "runs/maze1-baseline-loss5-s1");
}

TEST(RunSetting, AppliesToTheScenario) {
  swarm::scenario::Scenario s;
  RunSetting::delays(40, 5).apply(s);
  EXPECT_EQ(s.links().leader_gcs().delay_ticks(), 40u);
  EXPECT_EQ(s.links().member_leader().delay_ticks(), 5u);
  RunSetting::encoding_and_cap(swarm::scenario::ZSTD_RUN_LENGTH, 16000).apply(s);
  EXPECT_EQ(s.map_encoding(), swarm::scenario::ZSTD_RUN_LENGTH);
  EXPECT_DOUBLE_EQ(s.links().leader_gcs().bandwidth_bytes_per_s(), 16000);
  RunSetting::every_link_loss(0.2).apply(s);
  EXPECT_DOUBLE_EQ(s.links().sim_robot().loss(), 0.2);
  EXPECT_DOUBLE_EQ(s.links().member_leader().loss(), 0.2);
  EXPECT_DOUBLE_EQ(s.links().leader_gcs().loss(), 0.2);
}

TEST(ExperimentManifest, RoundTrips) {
  TempDir dir;
  swarm::scenario::Scenario base;
  ExperimentPlan p = make_plan(ExperimentKind::kBandwidth, {"maze1"}, {"group-frontier"}, 2, base, "/x.pbtxt");
  p.runs[1].status = RunStatus::kFailed;
  p.runs[1].failure = "timeout";
  write_manifest(dir.str(), p);
  const ExperimentPlan q = read_manifest(dir.str());
  EXPECT_EQ(q.kind, ExperimentKind::kBandwidth);
  EXPECT_EQ(q.scenario, "/x.pbtxt");
  EXPECT_EQ(q.encodings, p.encodings);
  EXPECT_EQ(q.leader_gcs_caps_bytes_per_s, p.leader_gcs_caps_bytes_per_s);
  ASSERT_EQ(q.runs.size(), p.runs.size());
  for (std::size_t i = 0; i < p.runs.size(); ++i) {
    EXPECT_EQ(q.runs[i].dir, p.runs[i].dir);
    EXPECT_TRUE(q.runs[i].setting == p.runs[i].setting) << i;
    EXPECT_EQ(q.runs[i].status, p.runs[i].status);
  }
  spit(dir.file("experiment.json"), "{ not json");
  EXPECT_THROW((void)read_manifest(dir.str()), swarm::config::ConfigError);
}

TEST(ExperimentAnalysis, ExploreTableCsvAndFailedRuns) {
  TempDir dir;
  const ExperimentPlan plan = fake_explore(dir.str());
  const auto rows = load_rows(dir.str(), plan);
  const ExperimentOutputs o = analyze_experiment(plan, rows);

  // CSV: the header and one row per run, the failed one marked with its log.
  std::istringstream csv(o.csv);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(csv, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 1u + plan.runs.size());
  for (const std::string& l : lines) {
    EXPECT_EQ(std::count(l.begin(), l.end(), ','), 26) << l;  // 27 columns, no quoted commas here
  }
  EXPECT_EQ(lines[0],
            "run,map,method,seed,status,complete,steps,steps_to_99,planning_rounds,explored_percent,"
            "ticks_run,wall_seconds,traffic_bytes,map_bytes,map_bytes_per_robot_second,radio_bytes,"
            "sim_robot_on_robot_bytes,leader_gcs_bytes,leader_gcs_peak_bytes_per_s,leader_gcs_queue_median_ticks,leader_gcs_queue_p95_ticks,"
            "member_leader_bytes,member_leader_peak_bytes_per_s,member_leader_queue_median_ticks,"
            "member_leader_queue_p95_ticks,log,failure");
  // open gf seed 1: 200*0.9 + 4 = 184 steps; map bytes 1500 / (9 robots x 185 ticks x 0.2 s); no
  // traffic per link in these fabricated runs.
  EXPECT_EQ(lines[1], "runs/open-group-frontier-s1,open,group-frontier,1,ok,true,184,174,9,99.90,185,"
                      "2.50,101499,1500,4.5,101499,0,,,,,,,,,,");
  EXPECT_EQ(lines[8], "runs/maze1-baseline-s2,maze1,baseline,2,failed,,,,,,,,,,,,,,,,,,,,,"
                      "runs/maze1-baseline-s2/logs/leader-1.log,process leader-1 failed (exit code 3)");

  // Table: means, the change against the baseline and the failed run marked and listed.
  EXPECT_TRUE(contains(o.table, "8 runs: 7 ok (7 complete), 1 failed")) << o.table;
  EXPECT_TRUE(contains(o.table, "186.0 ± 2.8")) << o.table;  // open gf: 184, 188
  EXPECT_TRUE(contains(o.table, "604.0 ± 0.0*")) << o.table;  // maze1 baseline: seed 1 only
  EXPECT_TRUE(contains(o.table, "1/2 (1 failed)")) << o.table;
  EXPECT_TRUE(contains(o.table, "FAILED runs/maze1-baseline-s2: process leader-1 failed")) << o.table;
  // open: 186 vs 206 = -9.7 %, both seeds 20 fewer, so an interval of width 0; maze1: 546 vs 604 =
  // -9.6 %, but only seed 1 has both runs: no interval.
  EXPECT_TRUE(contains(o.table, "-9.7 % [-9.7, -9.7]")) << o.table;
  EXPECT_TRUE(contains(o.table, "-9.6 %")) << o.table;
  EXPECT_TRUE(contains(o.table, "fewer steps than baseline on every map: yes")) << o.table;
  EXPECT_TRUE(contains(o.table, ">= 25 % fewer steps than baseline on the maze maps (maze1, mean of the per-map changes): NO"))
      << o.table;
  ASSERT_EQ(o.figures.size(), 1u);
  EXPECT_EQ(o.figures[0].first, "table2.png");
  EXPECT_TRUE(contains(o.json, "\"steps_change_vs_baseline_percent\""));
}

// A run the GCS declared complete with a third of the map unseen is left out and marked; a run
// stopped at max_ticks counts, marked as a lower bound.
TEST(ExperimentAnalysis, EndedEarlyAndIncompleteRunsAreMarked) {
  TempDir dir;
  ExperimentPlan plan = explore_plan(2);
  for (ExperimentRun& r : plan.runs) {
    const bool early = r.method == "group-frontier" && r.map == "open" && r.seed == 1;
    const bool stopped = r.method == "baseline" && r.map == "maze1" && r.seed == 2;
    fake_run(dir.str() + "/" + r.dir, r.map, r.method, static_cast<int>(r.seed),
             stopped ? 3000 : 300, 15, !stopped, early ? 0.33 : 0.999);
    r.status = RunStatus::kOk;
  }
  const ExperimentOutputs o = analyze_experiment(plan, load_rows(dir.str(), plan));
  EXPECT_TRUE(contains(o.table, "8 runs: 7 ok (6 complete), 0 failed, 1 ended early")) << o.table;
  EXPECT_TRUE(contains(o.table, "300.0 ± 0.0!")) << o.table;  // open gf: seed 2 only
  EXPECT_TRUE(contains(o.table, "1/2 (1 ended early)")) << o.table;
  EXPECT_TRUE(contains(o.table, "1650.0 ± 1909.2+")) << o.table;  // maze1 baseline: 300, 3000
  EXPECT_TRUE(contains(o.table, "ENDED EARLY runs/open-group-frontier-s1: complete at step 300 "
                                "with 33.0 % explored"))
      << o.table;
  EXPECT_TRUE(contains(o.csv, "runs/open-group-frontier-s1,open,group-frontier,1,ended_early,true,"))
      << o.csv;
  EXPECT_TRUE(contains(o.csv, "runs/maze1-baseline-s2,maze1,baseline,2,ok,false,3000,")) << o.csv;
}

TEST(ReportCommand, ReproducesTheExperimentOutputsByteForByte) {
  TempDir dir;
  const std::string exp = dir.file("exp");
  const ExperimentPlan plan = fake_explore(exp);
  const ExperimentOutputs first = analyze_experiment(plan, load_rows(exp, plan));
  write_outputs(exp, first);
  const std::string csv = slurp(exp + "/results.csv");
  const std::string json = slurp(exp + "/results.json");

  std::ostringstream out, err;
  ReportOptions r;
  r.dirs = {exp};
  EXPECT_EQ(report_command(r, out, err), 0) << err.str();
  EXPECT_EQ(out.str().substr(0, first.table.size()), first.table);
  EXPECT_EQ(slurp(exp + "/results.csv"), csv);
  EXPECT_EQ(slurp(exp + "/results.json"), json);
  EXPECT_EQ(slurp(exp + "/table.txt"), first.table);
  EXPECT_TRUE(fs::exists(exp + "/table2.png"));

  // Plain run directories: grouped by mode and map.
  const Reported plain = report_of({exp + "/runs"}, dir.file("plain"));
  EXPECT_EQ(plain.status, 0) << plain.err;
  EXPECT_TRUE(contains(plain.out, "7 runs: 7 ok (7 complete), 0 failed")) << plain.out;
  EXPECT_TRUE(contains(plain.out, "group-frontier vs baseline")) << plain.out;
  EXPECT_TRUE(fs::exists(dir.file("plain/results.csv")));
}

TEST(ReportCommand, ADirectoryGivenTwiceCountsOnce) {
  TempDir dir;
  const std::string exp = dir.file("exp");
  (void)fake_explore(exp);
  // The folder, one of its runs again, and the folder once more by another spelling.
  const Reported r =
      report_of({exp + "/runs", exp + "/runs/open-group-frontier-s1", exp + "/runs/../runs"}, dir.file("report"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "7 runs: 7 ok (7 complete), 0 failed")) << r.out;
}

TEST(ReportCommand, EachMissionKindGetsItsOwnTable) {
  TempDir dir;
  const std::string exp = dir.file("exp");
  (void)fake_explore(exp);
  // Two chained runs beside the exploration runs: never pooled into the exploration table.
  for (int seed : {1, 2}) {
    swarm::record::RunMetrics m = swarm::test::run_metrics("small", "group-frontier", static_cast<std::uint64_t>(seed), 300, 5);
    m.phases.push_back({"cover", 100, std::optional<std::uint32_t>(250 + seed), true, {}, {}});
    m.phases.back().motion.vertex_conflict_events = static_cast<std::uint64_t>(seed);
    m.phases.back().motion.total.longest_blocked_ticks = 4;
    spit(exp + "/runs/chain-s" + std::to_string(seed) + "/metrics.json", swarm::record::to_json(m).dump(2));
  }
  const Reported r = report_of({exp + "/runs"}, dir.file("report"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "7 runs: 7 ok (7 complete), 0 failed")) << r.out;
  EXPECT_TRUE(contains(r.out, "Mission explore,cover (2 runs)")) << r.out;
  const std::string csv = slurp(dir.file("report/mission-explore-cover.csv"));
  EXPECT_TRUE(contains(csv, ",cover,100,252,152,true,2,0,0,4\n")) << csv;
  EXPECT_TRUE(fs::exists(dir.file("report/mission-explore-cover.txt")));
}

TEST(ReportCommand, ARunThatEndedEarlyIsSkippedSayingSo) {
  TempDir dir;
  const std::string exp = dir.file("exp");
  (void)fake_explore(exp);
  spit(exp + "/runs/stopped/metrics.json",
       R"({"schema_version": 6, "partial": true, "complete": false, "ended": "interrupted: SIGINT", "ticks_run": 18})");
  const Reported r = report_of({exp + "/runs"}, dir.file("report"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "skipped " + exp + "/runs/stopped/metrics.json: the run ended early (interrupted: SIGINT)"))
      << r.err;
  EXPECT_TRUE(contains(r.out, "7 runs: 7 ok (7 complete), 0 failed")) << r.out;
}

TEST(ReportCommand, BadInputExits2SayingWhatIsAccepted) {
  TempDir dir;
  std::ostringstream out, err;
  ReportOptions r;
  r.dirs = {dir.str()};  // empty: no runs
  EXPECT_EQ(report_command(r, out, err), 2);
  EXPECT_TRUE(contains(err.str(), "holds no runs")) << err.str();
  EXPECT_TRUE(contains(err.str(), "experiment.json")) << err.str();
  r.dirs = {dir.file("missing")};
  EXPECT_EQ(report_command(r, out, err), 2);
  EXPECT_TRUE(contains(err.str(), "is not a directory")) << err.str();
  spit(dir.file("exp/experiment.json"), "[]");
  r.dirs = {dir.file("exp")};
  EXPECT_EQ(report_command(r, out, err), 2);
  EXPECT_TRUE(contains(err.str(), "damaged")) << err.str();
}

// A run written by another swarm (another metrics.json schema) is refused by name, not read as
// zeros.
TEST(ReportCommand, RefusesARunOfAnotherMetricsSchemaVersion) {
  TempDir dir;
  const std::string exp = dir.file("exp");
  (void)fake_explore(exp);
  const std::string run = exp + "/runs/open-group-frontier-s1";
  auto m = nlohmann::json::parse(slurp(run + "/metrics.json"));
  m["schema_version"] = 99;
  spit(run + "/metrics.json", m.dump());
  std::ostringstream out, err;
  ReportOptions r;
  r.dirs = {run};
  EXPECT_EQ(report_command(r, out, err), 2);
  EXPECT_TRUE(contains(err.str(), "schema_version 99, but this swarm reads version")) << err.str();
}

TEST(ExperimentCommand, BadInputExits2SayingWhatIsAccepted) {
  TempDir dir;
  auto run = [&](ExperimentOptions o) {
    std::ostringstream out, err;
    o.bin_dir = dir.str();  // never reached
    const int code = experiment_command(o, out, err);
    return std::make_pair(code, err.str());
  };
  ExperimentOptions o;
  o.out_dir = dir.file("out");
  o.maps = {"atlantis"};
  auto [code, msg] = run(o);
  EXPECT_EQ(code, 2);
  EXPECT_TRUE(contains(msg, "unknown map 'atlantis'")) << msg;
  EXPECT_TRUE(contains(msg, "maze1")) << msg;

  o.maps = {};
  o.methods = {"greedy"};
  std::tie(code, msg) = run(o);
  EXPECT_EQ(code, 2);
  EXPECT_TRUE(contains(msg, "unknown method 'greedy'; accepted: group-frontier, baseline, ideal")) << msg;

  o.methods = {};
  o.seeds = 0;
  std::tie(code, msg) = run(o);
  EXPECT_EQ(code, 2);
  EXPECT_TRUE(contains(msg, "--seeds 0")) << msg;

  o.seeds = 1;
  o.jobs = 0;
  std::tie(code, msg) = run(o);
  EXPECT_EQ(code, 2);
  EXPECT_TRUE(contains(msg, "--jobs 0")) << msg;

  o.jobs = std::nullopt;
  spit(dir.file("file"), "x");
  o.out_dir = dir.file("file") + "/out";  // a folder inside a regular file
  std::tie(code, msg) = run(o);
  EXPECT_EQ(code, 2);
  EXPECT_TRUE(contains(msg, "--out DIR")) << msg;
  EXPECT_FALSE(fs::exists(dir.file("out")));
}

// The knee on a synthetic link whose only traffic is a fixed rate of 1,000 B/s: a cap at or above
// it costs nothing; below it the run slows as the rate over the cap (every message waits for the
// bucket). Caps from 4,000 down to 125: the knee is the smallest cap within 5 % of uncapped
// steps, 1,000 (at 500 the run takes twice as long).
TEST(ExperimentAnalysis, TheKneeOfAFixedRateLinkIsItsRate) {
  const double rate = 1000, uncapped = 300;
  std::vector<swarm::tools::analysis::KneePoint> points;
  for (const double cap : {4000.0, 2000.0, 1000.0, 500.0, 250.0, 125.0}) {
    points.push_back({cap, uncapped * std::max(1.0, rate / cap), true});
  }
  using swarm::tools::analysis::knee_of;
  const auto knee_cap = [](const std::optional<swarm::tools::analysis::Knee>& k) { return k ? k->cap : -1.0; };
  EXPECT_EQ(knee_cap(knee_of(points, uncapped, 5.0)), 1000.0);
  // 5 % is the tolerance: a cap 4 % slower still counts; 6 % does not.
  EXPECT_EQ(knee_cap(knee_of({{2000, 300, true}, {1000, 312, true}, {500, 318, true}}, 300, 5.0)), 1000.0);
  // An incomplete run ends the knee's walk down, whatever its steps; so does a largest cap already too slow.
  EXPECT_EQ(knee_cap(knee_of({{2000, 300, true}, {1000, 300, false}, {500, 300, true}}, 300, 5.0)), 2000.0);
  EXPECT_FALSE(knee_of({{2000, 400, true}, {1000, 300, true}}, 300, 5.0).has_value());
}

// Noise: with intervals over seeds, a cap is slower only when its whole 95 % interval lies past the
// tolerance. A cap whose mean is 8 % slower by chance ([-5, +21]) no longer ends the walk at the
// largest cap; the knee is the last cap before one clearly slower (+60 % [+40, +80]), and the caps
// whose interval reaches past 5 % make it uncertain, the largest of them named.
TEST(ExperimentAnalysis, TheKneeIsNotEndedByANoisyCap) {
  using swarm::tools::analysis::knee_of;
  const auto noisy = knee_of({{4000, 324, true, -5, 21}, {2000, 303, true, -3, 5}, {1000, 306, true, -4, 8},
                              {500, 480, true, 40, 80}, {250, 300, true, -1, 1}},
                             300, 5.0);
  ASSERT_TRUE(noisy.has_value());
  EXPECT_EQ(noisy->cap, 1000.0);
  ASSERT_TRUE(noisy->uncertain_at.has_value());
  EXPECT_EQ(*noisy->uncertain_at, 4000.0);
  // The same caps measured tightly: every interval within 5 %, so the knee is certain.
  const auto tight = knee_of({{4000, 300, true, -1, 1}, {2000, 303, true, 0, 2}, {1000, 306, true, 1, 3},
                              {500, 480, true, 40, 80}},
                             300, 5.0);
  ASSERT_TRUE(tight.has_value());
  EXPECT_EQ(tight->cap, 1000.0);
  EXPECT_FALSE(tight->uncertain_at.has_value());
  // A cap whose interval lies wholly past 5 % (+6 % [+5.5, +6.5]) ends the walk although its mean is close.
  EXPECT_EQ(knee_of({{2000, 300, true, -1, 1}, {1000, 318, true, 5.5, 6.5}}, 300, 5.0)->cap, 2000.0);
  // A cap passed over as noisy is no knee itself: 1,000 is +60 % on average ([-10, +130]), so the
  // knee stays at 2,000 until a cap below comes back within 5 % on average (500: +2 %).
  EXPECT_EQ(knee_of({{2000, 300, true, -1, 1}, {1000, 480, true, -10, 130}, {250, 600, true, 50, 150}}, 300, 5.0)->cap,
            2000.0);
  const auto back = knee_of({{2000, 300, true, -1, 1}, {1000, 480, true, -10, 130}, {500, 306, true, -20, 24},
                             {250, 600, true, 50, 150}},
                            300, 5.0);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->cap, 500.0);
  EXPECT_EQ(back->uncertain_at, std::optional<double>(1000.0));
}

// A latency sweep of a chained mission (explore,cover) on fabricated runs: besides the whole
// mission's ticks, each phase's own ticks get rows, each with its change against no delay on the
// same seeds. Seeds 1 and 2 explore in 100 + seed ticks and cover in 50 + seed; with a delay, cover
// takes 10 ticks more: +19.4 % of 51.5, an interval of zero width (the same +10 on both seeds).
TEST(ExperimentAnalysis, AChainedMissionGetsEachPhasesTicks) {
  TempDir dir;
  swarm::scenario::Scenario base;
  ExperimentPlan plan = make_plan(ExperimentKind::kLatency, {"small"}, {"group-frontier"}, 2, base, "");
  plan.mission = {"explore", "cover"};
  for (ExperimentRun& r : plan.runs) {
    const bool delayed = r.setting.member_leader_delay_ticks.value_or(0) + r.setting.leader_gcs_delay_ticks.value_or(0) > 0;
    const auto explore = static_cast<std::uint32_t>(100 + r.seed);
    const auto cover = static_cast<std::uint32_t>(50 + r.seed + (delayed ? 10 : 0));
    auto m = swarm::test::run_metrics("small", "group-frontier", r.seed, explore + cover, 5);
    m.phases.clear();
    m.phases.push_back({"explore", 0, explore, true, {}, {}});
    m.phases.push_back({"cover", explore, explore + cover, true, {}, {}});
    const std::string run = dir.str() + "/" + r.dir;
    spit(run + "/metrics.json", swarm::record::to_json(m).dump(2));
    spit(run + "/scenario.pbtxt", "map: \"small\"\ntick_seconds: 0.2\n");
    r.status = RunStatus::kOk;
  }
  const ExperimentOutputs o = analyze_experiment(plan, load_rows(dir.str(), plan));
  EXPECT_TRUE(contains(o.table, "ticks in phase 1, explore")) << o.table;
  EXPECT_TRUE(contains(o.table, "ticks in phase 2, cover")) << o.table;
  EXPECT_TRUE(contains(o.table, "101.5 ± 0.7")) << o.table;  // explore, every setting
  EXPECT_TRUE(contains(o.table, "51.5 ± 0.7")) << o.table;   // cover without delay
  EXPECT_TRUE(contains(o.table, "61.5 ± 0.7")) << o.table;   // cover with delay
  EXPECT_TRUE(contains(o.table, "+19.4 % [+19.4, +19.4]")) << o.table;
}

// A bandwidth experiment on fabricated runs: the uncapped runs' traffic gives the demand per sender
// (the member<->leader link's bytes over the run and its busiest whole second, shared by its 9
// senders), each capped run its cap, and the table each cap's steps against the uncapped ones of
// the same seeds, the queue and the knee.
TEST(ExperimentAnalysis, BandwidthCapsFollowTheMeasuredDemand) {
  TempDir dir;
  swarm::scenario::Scenario base;
  SweepChoices choices;
  choices.encodings = {swarm::scenario::ZSTD_RUN_LENGTH};
  choices.cap_links = {"member_leader"};
  choices.cap_bases = {"mean", "peak"};
  choices.cap_fractions = {1.0, 0.125};
  ExperimentPlan plan = make_plan(ExperimentKind::kBandwidth, {"maze1"}, {"group-frontier"}, 2, base, "", choices);
  ASSERT_EQ(plan.runs.size(), 2u + 8u);
  // Uncapped: 300 + seed steps (301 ticks of 0.2 s = 60.2 s); member_leader 54,180 bytes, i.e. 900 B/s,
  // 100 B/s per sender; its busiest whole second 2,700 B/s, 300 per sender.
  for (ExperimentRun& r : plan.runs) {
    if (r.setting.waits_for_demand()) continue;
    const std::string run = dir.str() + "/" + r.dir;
    auto m = swarm::test::run_metrics("maze1", "group-frontier", r.seed, 299 + static_cast<std::uint32_t>(r.seed), 15);
    m.traffic.by_link["member_leader"].bytes = static_cast<std::uint64_t>(900 * 0.2 * (300 + r.seed));
    // member-1-1 sent a third of it in both runs, 300 B/s; seed 2's record names no sender.
    if (r.seed == 1) {
      m.traffic.by_link["member_leader"].busiest_sender = "member-1-1";
      m.traffic.by_link["member_leader"].busiest_sender_bytes = m.traffic.by_link["member_leader"].bytes / 3;
    }
    spit(run + "/metrics.json", swarm::record::to_json(m).dump(2));
    spit(run + "/scenario.pbtxt", "map: \"maze1\"\ntick_seconds: 0.2\n");
    spit(run + "/traffic.csv", "second,member_leader_bytes_per_s,leader_gcs_bytes_per_s,sim_robot_on_robot_bytes_per_s\n"
                               "1,900,10,5000\n2,2700,10,5000\n3,900,10,5000\n3.2,9000,10,5000\n");
    r.status = RunStatus::kOk;
  }
  const std::vector<std::string> missing = resolve_demand(plan, load_rows(dir.str(), plan));
  EXPECT_TRUE(missing.empty());
  const ExperimentPlan::Demand& d = plan.demand.at("maze1").at("member_leader");
  EXPECT_EQ(d.runs, 2u);
  // Seed 1: 54,180 B / 60.2 s / 9 = 100 B/s; seed 2 the same rate. The last bin (0.2 s) is not a whole second.
  EXPECT_NEAR(d.mean_bytes_per_s, 100.0, 1e-9);
  EXPECT_NEAR(d.peak_bytes_per_s, 300.0, 1e-9);
  EXPECT_NEAR(d.busiest_mean_bytes_per_s, 300.0, 1e-9);  // seed 1's only: seed 2 named none
  EXPECT_EQ(d.busiest_sender, "member-1-1");
  EXPECT_EQ(d.busiest_sender_runs, 1u);
  for (const ExperimentRun& r : plan.runs) {
    ASSERT_FALSE(r.setting.waits_for_demand()) << r.dir;
    if (!r.setting.demand) continue;
    const double want = r.setting.demand->fraction * (r.setting.demand->basis == "mean" ? 100.0 : 300.0);
    EXPECT_NEAR(*r.setting.member_leader_bandwidth_bytes_per_s, want, 1e-9) << r.dir;
  }
  // Capped: x1 of either basis costs 1 % more steps; x1/8 of the mean 60 %; x1/8 of the peak
  // (37.5 B/s) 40 %. Queues: the median message waited 2 ticks under x1/8, 0 under x1.
  for (ExperimentRun& r : plan.runs) {
    if (!r.setting.demand) continue;
    const bool eighth = r.setting.demand->fraction < 1;
    const double slower = !eighth ? 1.01 : r.setting.demand->basis == "mean" ? 1.6 : 1.4;
    const auto steps = static_cast<std::uint32_t>(std::lround(static_cast<double>(299 + r.seed) * slower));
    auto m = swarm::test::run_metrics("maze1", "group-frontier", r.seed, steps, 15);
    m.traffic.by_link["member_leader"].bytes = 50000;
    m.traffic.by_link["member_leader"].queued_ticks = eighth ? std::vector<std::uint64_t>{10, 10, 30, 50} : std::vector<std::uint64_t>{100};
    const std::string run = dir.str() + "/" + r.dir;
    spit(run + "/metrics.json", swarm::record::to_json(m).dump(2));
    spit(run + "/scenario.pbtxt", "map: \"maze1\"\ntick_seconds: 0.2\n");
    r.status = RunStatus::kOk;
  }
  write_manifest(dir.str(), plan);
  const ExperimentPlan back = read_manifest(dir.str());
  EXPECT_EQ(back.demand.at("maze1").at("member_leader").peak_bytes_per_s, 300.0);
  EXPECT_EQ(back.demand.at("maze1").at("member_leader").busiest_sender, "member-1-1");
  const ExperimentOutputs o = analyze_experiment(back, load_rows(dir.str(), back));
  EXPECT_TRUE(contains(o.table, "member_leader cap, mean x, maze1, group-frontier")) << o.table;
  EXPECT_TRUE(contains(o.table, "12.5 B/s")) << o.table;  // x1/8 of 100 B/s
  EXPECT_TRUE(contains(o.table, "37.5 B/s")) << o.table;  // x1/8 of 300 B/s
  // x1/8 of the mean: seeds 1 and 2, 480 vs 300 and 482 vs 301 steps (+180, +181): +60.1 % of
  // 300.5, and an interval that excludes 0 (t with 1 degree of freedom: 180.5 +- 6.35 steps).
  EXPECT_TRUE(contains(o.table, "+60.1 % [+58.0, +62.2]")) << o.table;
  EXPECT_TRUE(contains(o.table, "2.0 / 3.0")) << o.table;  // median / p95 ticks queued under x1/8
  EXPECT_TRUE(contains(o.table, "knee, member_leader, maze1, group-frontier, ZSTD_RUN_LENGTH: 100 B/s per sender")) << o.table;
  EXPECT_TRUE(contains(o.table, "(1.00 x its mean demand, 0.33 x its peak, 0.33 x the busiest sender's mean)")) << o.table;
  EXPECT_TRUE(contains(o.table, "the busiest sender, member-1-1 in 1 of 2 runs, alone: mean 300 B/s")) << o.table;
  EXPECT_TRUE(contains(o.csv, "member_leader_queue_p95_ticks")) << o.csv;
}
