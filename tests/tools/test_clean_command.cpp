// `swarm clean` and `swarm experiment clean`: outputs on the built-in rooms, and bad input exiting
// with status 2 and saying what is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "clean_command.hpp"
#include "offline_experiments.hpp"
#include "swarm_test/files.hpp"
#include "swarm_test/text.hpp"

namespace fs = std::filesystem;
using namespace swarm::tools;
using swarm::test::contains;
using swarm::test::slurp;
using swarm::test::TempDir;

namespace {

struct Result {
  int status;
  std::string out, err;
};

Result run_clean(const CleanCommandOptions& o) {
  std::ostringstream out, err;
  const int status = clean_command(o, out, err);
  return {status, out.str(), err.str()};
}

TEST(CleanCommand, ComparesPlowingAndGroupKOnTheClutterRoom) {
  TempDir dir;
  CleanCommandOptions o;
  o.map = "clutter";
  o.out_dir = dir.file("out");
  const Result r = run_clean(o);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "start (1, 48)")) << r.out;
  EXPECT_TRUE(contains(r.out, "Basic_Group:   7 groups, C = 0.24 0.59 0.57 0.45 0.72 0.33 0.47")) << r.out;
  EXPECT_TRUE(contains(r.out, "Merge_Group:   6 groups"));
  EXPECT_TRUE(contains(r.out, "clean when plowing has 45 %"));
  for (const char* f : {"summary.txt", "groups-basic.png", "groups-released.png", "groups.png", "plow.png",
                        "group-k.png", "coverage.png"}) {
    EXPECT_TRUE(fs::exists(dir.file("out/") + f)) << f;
  }
}

TEST(CleanCommand, BadInputSaysWhatIsWrong) {
  TempDir dir;
  const std::vector<std::pair<CleanCommandOptions, std::string>> cases = {
      {{"kitchen", "", 0.5, 1, "columns", 0, dir.file("o")}, "unknown map 'kitchen'"},
      {{"clutter", "3", 0.5, 1, "columns", 0, dir.file("o")}, "--start '3': expected X,Y"},
      {{"clutter", "0,0", 0.5, 1, "columns", 0, dir.file("o")}, "--start 0,0 is on a blocked cell"},
      {{"clutter", "70,3", 0.5, 1, "columns", 0, dir.file("o")}, "--start 70,3 is outside the map (x 0..59, y 0..49)"},
      {{"clutter", "", 0.0, 1, "columns", 0, dir.file("o")}, "--k must be in (0, 1]"},
      {{"clutter", "", 0.5, 1, "diagonal", 0, dir.file("o")}, "--sweep 'diagonal'; accepted: columns, rows"},
      {{"clutter", "", 0.5, 1, "columns", -1, dir.file("o")}, "--margin must be 0 or more"},
      {{"clutter", "", 0.5, 1, "columns", 0, "/proc/no/such/dir"}, "cannot create the output directory"},
  };
  for (const auto& [o, expected] : cases) {
    const Result r = run_clean(o);
    EXPECT_EQ(r.status, 2) << expected;
    EXPECT_TRUE(contains(r.err, "swarm clean: ") && contains(r.err, expected)) << "expected: " << expected << "\ngot: " << r.err;
  }
}

TEST(CleanExperiment, TheEmptyRoomChecksEqualAndTheFilesAreWritten) {
  TempDir dir;
  CleanExperimentOptions o;
  o.maps = {"empty", "clutter"};
  o.seeds = 2;
  o.out_dir = dir.file("exp");
  std::ostringstream out, err;
  ASSERT_EQ(clean_experiment(o, out, err), 0) << err.str();
  EXPECT_TRUE(contains(out.str(), "[4/4] ")) << out.str();
  EXPECT_TRUE(contains(out.str(), "no obstacle groups: Group-k and plowing equal (the paper): yes"));
  EXPECT_TRUE(contains(out.str(), "Group-k clearly ahead when plowing is at 40-50 %"));
  const std::string csv = slurp(dir.file("exp/results.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4 + 1);
  for (const char* f : {"table.txt", "results.json", "coverage.png", "groups-clutter.png", "group-k-empty.png"}) {
    EXPECT_TRUE(fs::exists(dir.file("exp/") + f)) << f;
  }
  EXPECT_EQ(nlohmann::json::parse(slurp(dir.file("exp/results.json")))["maps"].size(), 2u);
  o.maps = {"nowhere.map"};
  EXPECT_EQ(clean_experiment(o, out, err), 2);
  EXPECT_TRUE(contains(err.str(), "no MovingAI map file nowhere.map")) << err.str();
}

}  // namespace
