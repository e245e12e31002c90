// `swarm experiment` and `swarm report` through the real `swarm` command: a small explore
// experiment (map small, 2 seeds, every method) runs for real, every run completes, the CSV has
// one row per run, and `swarm report` rebuilds the same table and CSV byte for byte. Bad input
// exits 2 saying what is accepted.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run_swarm.hpp"
#include "swarm_test/text.hpp"

namespace swarm::test {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(text);
  while (std::getline(in, cell, sep)) out.push_back(cell);
  return out;
}

using swarm::test::contains;

// One experiment (1 map x 3 methods x 2 seeds = 6 runs of 2 x 2 robots), then its report: one
// test, since ctest runs every test in a process of its own.
TEST(ExperimentExplore, EveryRunCompletesAndReportRebuildsTheSameTableAndCsv) {
  const std::string dir = fresh_dir("experiment_explore") + "/exp";
  const CommandResult result =
      run_swarm("experiment explore --maps small --seeds 2 --jobs 2 --scenario " +
                source_path("scenarios/small.pbtxt") + " --out " + dir);

  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* f :
       {"experiment.json", "results.csv", "results.json", "table.txt", "table2.png"}) {
    EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
  }
  // A progress line per run, then the table.
  std::size_t progress_lines = 0;
  for (std::size_t at = result.output.find("/6] "); at != std::string::npos; at = result.output.find("/6] ", at + 1)) ++progress_lines;
  EXPECT_EQ(progress_lines, 6U) << result.output;
  EXPECT_TRUE(contains(result.output, "6 runs: 6 ok (6 complete), 0 failed")) << result.output;

  const auto lines = split(slurp(dir + "/results.csv"), '\n');
  ASSERT_EQ(lines.size(), 1u + 6u) << slurp(dir + "/results.csv");
  const auto header = split(lines[0], ',');
  const std::vector<std::string> expected = {
      "run", "map", "method", "seed", "status", "complete", "steps", "steps_to_99",
      "planning_rounds", "explored_percent", "ticks_run", "wall_seconds", "traffic_bytes",
      "map_bytes", "map_bytes_per_robot_second", "radio_bytes", "sim_robot_on_robot_bytes", "leader_gcs_bytes", "leader_gcs_peak_bytes_per_s",
      "leader_gcs_queue_median_ticks", "leader_gcs_queue_p95_ticks", "member_leader_bytes",
      "member_leader_peak_bytes_per_s", "member_leader_queue_median_ticks", "member_leader_queue_p95_ticks", "log",
      "failure"};
  EXPECT_EQ(header, expected);
  auto col = [&](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  std::vector<std::string> methods;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    auto cells = split(lines[i], ',');
    cells.resize(header.size());  // trailing empty cells
    EXPECT_EQ(cells[col("map")], "small") << lines[i];
    EXPECT_EQ(cells[col("status")], "ok") << lines[i];
    EXPECT_EQ(cells[col("complete")], "true") << lines[i];
    EXPECT_GT(std::stoi(cells[col("steps")]), 10) << lines[i];
    EXPECT_GE(std::stoi(cells[col("planning_rounds")]), 1) << lines[i];
    EXPECT_GE(std::stod(cells[col("explored_percent")]), 99.0) << lines[i];
    EXPECT_TRUE(fs::exists(dir + "/" + cells[col("run")] + "/metrics.json")) << lines[i];
    methods.push_back(cells[col("method")]);
  }
  for (const char* m : {"group-frontier", "baseline", "ideal"}) {
    EXPECT_EQ(std::count(methods.begin(), methods.end(), m), 2) << m;
  }
  // Seed 1 of every method keeps its map and a mid-run frontier snapshot.
  int pictures = 0;
  for (const auto& e : fs::directory_iterator(dir + "/pictures")) {
    pictures += e.path().extension() == ".png";
  }
  EXPECT_EQ(pictures, 6);

  // `swarm report` on the experiment directory: the same bytes.
  const std::string table = slurp(dir + "/table.txt");
  const std::string csv = slurp(dir + "/results.csv");
  const std::string json = slurp(dir + "/results.json");
  ASSERT_FALSE(table.empty());
  EXPECT_TRUE(contains(result.output, table)) << "the experiment printed its table";

  const std::string out = dir + "/../report";
  const CommandResult r = run_swarm("report " + dir + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.substr(0, table.size()), table);
  EXPECT_EQ(slurp(out + "/table.txt"), table);
  EXPECT_EQ(slurp(out + "/results.csv"), csv);
  EXPECT_EQ(slurp(out + "/results.json"), json);
  EXPECT_TRUE(fs::exists(out + "/table2.png"));

  // Plain run directories give the same explore table, grouped by mode and map.
  const CommandResult plain = run_swarm("report " + dir + "/runs --out " + dir + "/../plain");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_TRUE(contains(plain.output, "6 runs: 6 ok (6 complete), 0 failed")) << plain.output;
}

// A bandwidth experiment in small settings (map small, 2 seeds, the member<->leader link capped at
// 1 and 1/8 of its mean demand): the uncapped runs run first and measure the demand, each capped
// run gets its share of it, its messages queue, and the table names the knee. Every run writes its
// traffic over time. `swarm report` rebuilds the same outputs.
TEST(ExperimentBandwidth, CapsAreSetFromTheMeasuredDemandAndTheKneeIsNamed) {
  const std::string dir = fresh_dir("experiment_bandwidth") + "/exp";
  const CommandResult result =
      run_swarm("experiment bandwidth --maps small --seeds 2 --jobs 2 --encodings ZSTD_RUN_LENGTH "
                "--cap-links member_leader --cap-bases mean --cap-fractions 1,0.125 --scenario " +
                source_path("scenarios/small.pbtxt") + " --out " + dir);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "demand per sender, measured uncapped on small: member_leader mean ")) << result.output;
  EXPECT_TRUE(contains(result.output, "knee, member_leader, small, group-frontier, ZSTD_RUN_LENGTH: ")) << result.output;
  EXPECT_TRUE(contains(result.output, "6 runs: 6 ok")) << result.output;

  const auto lines = split(slurp(dir + "/results.csv"), '\n');
  ASSERT_EQ(lines.size(), 1u + 6u);
  const auto header = split(lines[0], ',');
  auto col = [&](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  int capped = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    auto cells = split(lines[i], ',');
    cells.resize(header.size());
    EXPECT_EQ(cells[col("status")], "ok") << lines[i];
    EXPECT_TRUE(fs::exists(dir + "/" + cells[col("run")] + "/traffic.csv")) << lines[i];
    EXPECT_TRUE(fs::exists(dir + "/" + cells[col("run")] + "/traffic.png")) << lines[i];
    EXPECT_FALSE(cells[col("member_leader_peak_bytes_per_s")].empty()) << lines[i];
    if (cells[col("cap_link")].empty()) {
      EXPECT_TRUE(cells[col("member_leader_queue_median_ticks")].empty()) << "uncapped runs queue nothing: " << lines[i];
      continue;
    }
    ++capped;
    EXPECT_EQ(cells[col("cap_link")], "member_leader");
    EXPECT_GT(std::stod(cells[col("member_leader_bandwidth_bytes_per_s")]), 0) << lines[i];
    EXPECT_FALSE(cells[col("member_leader_queue_p95_ticks")].empty()) << lines[i];
  }
  EXPECT_EQ(capped, 4);

  const std::string out = dir + "/../report";
  const CommandResult r = run_swarm("report " + dir + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(slurp(out + "/table.txt"), slurp(dir + "/table.txt"));
  EXPECT_EQ(slurp(out + "/results.csv"), slurp(dir + "/results.csv"));
}

TEST(ExperimentBadInput, ExitsTwoSayingWhatIsAccepted) {
  const std::string dir = fresh_dir("experiment_bad_input");
  struct Case {
    std::string args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"experiment explore --maps atlantis --out " + dir + "/a", "unknown map 'atlantis'; accepted"},
      {"experiment latency --methods greedy --out " + dir + "/b",
       "unknown method 'greedy'; accepted: group-frontier, baseline, ideal"},
      {"experiment explore --seeds 0 --out " + dir + "/c", "--seeds 0"},
      {"experiment loss --seeds 0 --out " + dir + "/c", "--seeds 0"},
      {"experiment bandwidth --out /proc/swarm-cannot-write-here", "--out DIR"},
      {"experiment bandwidth --cap-links radio --out " + dir + "/d", "--cap-links: unknown 'radio'; accepted: leader_gcs, member_leader"},
      {"experiment bandwidth --cap-fractions 0 --out " + dir + "/d", "--cap-fractions 0.000: a share of the demand must be above 0"},
      {"experiment bandwidth --encodings GZIP --out " + dir + "/d", "--encodings: unknown map encoding 'GZIP'"},
      {"report " + dir, "holds no runs"},
      {"report " + dir + "/missing", "is not a directory"},
      {"experiment", "A subcommand is required"},
  };
  for (const Case& c : cases) {
    const CommandResult r = run_swarm(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, c.says)) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(dir + "/a/experiment.json"));
}

// The live task experiments in their smallest setting: every run completes, the CSV has a row per
// run, the table and the plot are written; mapf-live's runs have no conflict.
TEST(ExperimentTasks, CoverAndMapfLiveQuickRunsComplete) {
  for (const std::string task : {"cover", "mapf-live"}) {
    const std::string dir = fresh_dir("experiment_" + task);
    const CommandResult r = run_swarm("experiment " + task + " --quick --seeds 1 --out " + dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto results = read_json(dir + "/results.json");
    const std::size_t variants = task == "cover" ? 2 : 3;
    ASSERT_EQ(results["runs"].size(), 2 * variants) << task;
    for (const auto& run : results["runs"]) {
      EXPECT_EQ(run["status"], "ok") << task << " " << run["dir"];
      EXPECT_TRUE(run["complete"].get<bool>()) << task << " " << run["dir"];
      if (task == "mapf-live") EXPECT_EQ(run["conflicts"], 0) << run["dir"];
      if (task == "cover") EXPECT_DOUBLE_EQ(run["covered_percent"].get<double>(), 100.0) << run["dir"];
    }
    EXPECT_TRUE(fs::exists(dir + "/" + task + ".png"));
    EXPECT_TRUE(fs::exists(dir + "/table.txt"));
    std::ifstream csv(dir + "/results.csv");
    std::string line;
    std::size_t lines = 0;
    while (std::getline(csv, line)) ++lines;
    EXPECT_EQ(lines, 1 + 2 * variants) << task;
  }
}

// The chained mission in its smallest setting: the run completes, every phase has its row in
// the CSV and its table, with the cover phase's ratio to its bound, and no phase counts a conflict.
TEST(ExperimentMission, QuickRunsTheChainAndTablesEveryPhase) {
  const std::string dir = fresh_dir("experiment_mission");
  const CommandResult r = run_swarm("experiment mission --quick --mission explore,cover,collect --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto results = read_json(dir + "/results.json");
  ASSERT_EQ(results["runs"].size(), 1u);
  const auto& run = results["runs"][0];
  EXPECT_TRUE(run["complete"].get<bool>()) << run.dump();
  ASSERT_EQ(run["phases"].size(), 3u);
  for (const auto& p : run["phases"]) {
    EXPECT_TRUE(p["complete"].get<bool>()) << p.dump();
    EXPECT_EQ(p["vertex_conflicts"], 0) << p.dump();
    EXPECT_EQ(p["edge_conflicts"], 0) << p.dump();
    EXPECT_GT(p["ticks"].get<double>(), 0) << p.dump();
  }
  // cover's bound: ⌈cells / robots⌉ of 9 robots; a makespan can never beat it.
  EXPECT_GE(run["phases"][1]["ratio"].get<double>(), 1.0);
  EXPECT_TRUE(run["phases"][0]["ratio"].is_null());
  std::ifstream table(dir + "/table.txt");
  const std::string text((std::istreambuf_iterator<char>(table)), std::istreambuf_iterator<char>());
  for (const char* phase : {"phase 1: explore", "phase 2: cover", "phase 3: collect"}) {
    EXPECT_NE(text.find(phase), std::string::npos) << text;
  }
  EXPECT_NE(text.find("1 of 1 runs completed the whole mission"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(dir + "/mission.png"));
  std::ifstream csv(dir + "/results.csv");
  std::string line;
  std::size_t lines = 0;
  while (std::getline(csv, line)) ++lines;
  EXPECT_EQ(lines, 1u + 3u);
  // Bad input is refused before any run, naming the flag.
  const CommandResult bad = run_swarm("experiment mission --robots 3by3 --out " + dir + "-bad");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--robots '3by3'"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace swarm::test
