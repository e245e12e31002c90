// `swarm experiment darp` on a tiny grid (one map, one condition, one seed, a 2-point sweep): the
// files it promises, a row per run, and bad input exiting 2.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiment_darp.hpp"
#include "swarm_test/files.hpp"

namespace {

using swarm::test::slurp;
using swarm::test::TempDir;
using swarm::tools::DarpExperimentOptions;

// A tiny grid: the rectangle, spread starts, 3 robots, one seed, one job, into `dir`.
DarpExperimentOptions tiny(const TempDir& dir, std::vector<std::string> methods) {
  DarpExperimentOptions o;
  o.maps = {"rectangle"};
  o.conditions = {"far"};
  o.methods = std::move(methods);
  o.robots = {3};
  o.seeds = 1;
  o.jobs = 1;
  o.out_dir = dir.str();
  return o;
}

TEST(ExperimentDarp, WritesTableCsvJsonAndPlots) {
  TempDir dir;
  DarpExperimentOptions o = tiny(dir, {"standalone", "kmeans"});
  o.max_iterations = 300;  // close-together starts may not converge: bound the test's time
  o.sweep_max = 2;
  o.sweep_seeds = 1;
  std::ostringstream out, err;
  ASSERT_EQ(swarm::tools::experiment_darp_command(o, out, err), 0) << err.str();
  for (const char* f : {"table.txt", "results.csv", "results.json", "darp_boxplot.png", "darp_sweep.png",
                        "pictures/rectangle-far-kmeans.png"}) {
    EXPECT_FALSE(slurp(dir.file(f)).empty()) << f;
  }
  const nlohmann::json j = nlohmann::json::parse(slurp(dir.file("results.json")));
  EXPECT_EQ(j["runs"].size(), 2u + 2 * 2);  // 2 methods + sweep n = 1, 2 for far and close
  EXPECT_EQ(j["runs"][0]["iterations"].get<int>() >= 0, true);
  EXPECT_NE(out.str().find("[1/"), std::string::npos) << "progress lines";
  EXPECT_NE(out.str().find("rectangle sweep"), std::string::npos);
  // The CSV: a header and one line per run.
  std::istringstream csv(slurp(dir.file("results.csv")));
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 1 + 6);
  // The default division converges every run and says how many the repair finished.
  EXPECT_NE(out.str().find("division auto: 0 of 6 runs did not converge"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("finished by the repair"), std::string::npos) << out.str();
  for (const auto& run : j["runs"]) EXPECT_EQ(run["status"], "converged") << run.dump();
}

// --division darp: DARP alone, its iterations against the paper's; no repair.
TEST(ExperimentDarp, DarpAloneForThePapersFigures) {
  TempDir dir;
  DarpExperimentOptions o = tiny(dir, {"standalone", "bfs-kmeans"});
  o.sweep_max = 0;
  o.division = "darp";
  std::ostringstream out, err;
  ASSERT_EQ(swarm::tools::experiment_darp_command(o, out, err), 0) << err.str();
  EXPECT_NE(out.str().find("check: BFS + K-Means (always)"), std::string::npos) << out.str();
  const nlohmann::json j = nlohmann::json::parse(slurp(dir.file("results.json")));
  for (const auto& run : j["runs"]) EXPECT_EQ(run["finished_by"], "darp") << run.dump();
}

TEST(ExperimentDarp, BadInputExitsTwo) {
  TempDir dir;
  auto expect_bad = [&](DarpExperimentOptions o, const std::string& message) {
    o.out_dir = dir.str();
    std::ostringstream out, err;
    EXPECT_EQ(swarm::tools::experiment_darp_command(o, out, err), 2);
    EXPECT_NE(err.str().find(message), std::string::npos) << err.str();
  };
  DarpExperimentOptions o;
  o.methods = {"genetic"};
  expect_bad(o, "--methods: unknown \"genetic\"; accepted: standalone, random, kmeans, bfs-kmeans, selective");
  o.methods = {};
  o.seeds = 0;
  expect_bad(o, "--seeds must be >= 1");
  o.seeds = 1;
  o.maps = {"maze1"};
  expect_bad(o, "the bottleneck condition needs a map with a known narrowest passage");
  o.maps = {"nowhere"};
  expect_bad(o, "--map: unknown map 'nowhere'");
  o.maps = {};
  o.division = "best";
  expect_bad(o, "--division \"best\": expected auto or darp");
}

}  // namespace
