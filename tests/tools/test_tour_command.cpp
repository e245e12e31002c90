// `swarm tour` and its tour files: the shipped scenarios, a good run's outputs, and every kind of
// bad input exiting with status 2 and naming the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "offline_experiments.hpp"
#include "swarm_test/data.hpp"
#include "swarm_test/files.hpp"
#include "swarm_test/text.hpp"
#include "tour_command.hpp"
#include "tour_file.hpp"

namespace fs = std::filesystem;
using namespace swarm::tools;
using swarm::test::contains;
using swarm::test::slurp;
using swarm::test::spit;
using swarm::test::TempDir;

namespace {

// A 6 x 5 room: a wall with a gap at x = 3, two types.
const char* kGood = R"(# two types in a small room
size 6 5
start 0 0 up
destination a 5 4
destination b 4 4
obstacle 3 1 3 4   # a wall, open at y = 0
object a 1 3
object a 5 0
object b 2 1 fixed
object b 4 0
)";

struct Result {
  int status;
  std::string out, err;
};

Result run_tour(TourCommandOptions o) {
  std::ostringstream out, err;
  const int status = tour_command(o, out, err);
  return {status, out.str(), err.str()};
}

// The file with one line appended (or a line replaced when `replace` is found).
std::string good_with(const std::string& extra, const std::string& replace = "") {
  std::string text = kGood;
  if (!replace.empty()) text.replace(text.find(replace), replace.size(), extra);
  else text += extra + "\n";
  return text;
}

TEST(TourFile, ShippedScenariosAreThePapersRooms) {
  const TourFile s1 = load_tour_file(swarm::test::source_dir() + "/scenarios/tour/scenario1.tour");
  EXPECT_EQ(s1.map.width(), 12);
  EXPECT_EQ(s1.problem.objects.size(), 24u);
  EXPECT_EQ(s1.type_names, (std::vector<std::string>{"paper", "can", "pet"}));
  EXPECT_EQ(s1.where(s1.problem.start), "(0, -5)");
  EXPECT_TRUE(s1.unreachable.empty());
  const TourFile s2 = load_tour_file(swarm::test::source_dir() + "/scenarios/tour/scenario2.tour");
  EXPECT_EQ(s2.map.width(), 20);
  EXPECT_EQ(s2.problem.objects.size(), 50u);
  EXPECT_EQ(s2.where(s2.problem.start), "(0, -9)");
  // The paper's type orders come out of the nearest-object rule (checked on plans).
  for (const auto& [file, order] : std::vector<std::pair<const TourFile*, std::vector<std::string>>>{
           {&s1, {"paper", "pet", "can"}}, {&s2, {"paper", "pet", "metal", "glass", "can"}}}) {
    swarm::planner::TourOptions o;
    o.search = swarm::planner::TourOptions::Search::kExact;
    const auto plan = swarm::planner::plan_tour(file->map, file->problem, o);
    std::vector<std::string> types;
    for (const auto& run : plan.runs) types.push_back(file->type_names[static_cast<std::size_t>(run.type)]);
    EXPECT_EQ(types, order);
    EXPECT_EQ(swarm::planner::check_tour(file->map, file->problem, plan), "");
  }
}

TEST(TourCommand, WritesTheTablePicturesAndLegs) {
  TempDir dir;
  spit(dir.file("room.tour"), kGood);
  TourCommandOptions o;
  o.file = dir.file("room.tour");
  o.out_dir = dir.file("out");
  const Result r = run_tour(o);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "Start -> ")) << r.out;
  EXPECT_TRUE(contains(r.out, "Sum"));
  EXPECT_TRUE(contains(r.out, "best order"));
  for (const char* f : {"table.txt", "tour.json", "tour-nna.png", "tour-distance.png", "tour-distance-angle.png"}) {
    EXPECT_TRUE(fs::exists(dir.file("out/") + f)) << f;
  }
  const auto json = nlohmann::json::parse(slurp(dir.file("out/tour.json")));
  ASSERT_EQ(json["variants"].size(), 3u);
  const auto& legs = json["variants"][0]["legs"];
  EXPECT_EQ(legs.size(), 6u);  // 4 pick-ups, 2 drops
  EXPECT_EQ(legs[0]["cells"][0], nlohmann::json::array({0, 0}));
}

TEST(TourCommand, UnreachableObjectsStopItUnlessSkipped) {
  TempDir dir;
  // (2, 4) is walled in by the wall at x = 3 and two more blocked cells.
  spit(dir.file("room.tour"), good_with("obstacle 1 4 1 4\nobstacle 2 3 2 3\nobject a 2 4"));
  TourCommandOptions o;
  o.file = dir.file("room.tour");
  o.out_dir = dir.file("out");
  Result r = run_tour(o);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, dir.file("room.tour") + ":13: object a (2, 4) cannot be reached from the start")) << r.err;
  EXPECT_TRUE(contains(r.err, "--skip-unreachable"));
  o.skip_unreachable = true;
  r = run_tour(o);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "skipped: ")) << r.out;
  const auto json = nlohmann::json::parse(slurp(dir.file("out/tour.json")));
  EXPECT_EQ(json["variants"][0]["skipped_object_lines"], nlohmann::json::array({13}));
}

TEST(TourCommand, BadInputNamesTheFileLineAndWhatWasExpected) {
  TempDir dir;
  const std::string path = dir.file("room.tour");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {good_with("object a 3 2"), ":11: object a (3, 2) is on a blocked cell"},
      {good_with("object b 9 9"), ":11: object b (9, 9) is outside the map (x 0..5, y 0..4)"},
      {good_with("object glass 1 1"), ":11: type 'glass' has no destination (add a line 'destination glass X Y')"},
      {good_with("destination c 3 3"), ":11: the destination of 'c' (3, 3) is on a blocked cell"},
      {good_with("destination a 0 4"), ":11: a second destination for type 'a'"},
      {good_with("start 1 1"), ":11: a second 'start' line (the first is line 3)"},
      {good_with("start 0 0 north", "start 0 0 up"), ":3: unknown heading 'north'; expected up, down, left or right"},
      {good_with("object a x 1"), ":11: 'object' takes TYPE X Y; 'x' is not an integer"},
      {good_with("object a 1"), ":11: 'object' takes TYPE X Y [fixed] (got 2 words)"},
      {good_with("pickup a 1 1"), ":11: unknown statement 'pickup'"},
      {good_with("map clutter"), ":11: both 'size' (line 2) and 'map'; give one"},
      {good_with("obstacle 0 0 7 0"), ":11: obstacle corner (7, 0) is outside the map"},
      {good_with("", "start 0 0 up"), ": no 'start X Y' line"},
      {good_with("start 3 1 up", "start 0 0 up"), ":3: the start (3, 1) is on a blocked cell"},
  };
  for (const auto& [text, expected] : cases) {
    spit(path, text);
    TourCommandOptions o;
    o.file = path;
    o.out_dir = dir.file("out");
    const Result r = run_tour(o);
    EXPECT_EQ(r.status, 2) << expected;
    EXPECT_TRUE(contains(r.err, path + expected)) << "expected: " << expected << "\ngot: " << r.err;
  }
  TourCommandOptions missing;
  missing.file = dir.file("nowhere.tour");
  Result r = run_tour(missing);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "nowhere.tour: cannot read the file")) << r.err;
  spit(path, kGood);
  TourCommandOptions o;
  o.file = path;
  o.variants = {"fastest"};
  r = run_tour(o);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "unknown variant 'fastest'; accepted: nna, distance, distance-angle")) << r.err;
  o.variants = {};
  o.generations = 0;
  EXPECT_EQ(run_tour(o).status, 2);
  o.generations = 10;
  o.search = "annealing";
  EXPECT_EQ(run_tour(o).status, 2);
}

TEST(TourExperiment, TablesChecksAndFilesOnASmallRun) {
  TempDir dir;
  spit(dir.file("room.tour"), kGood);
  TourExperimentOptions o;
  o.scenarios = {dir.file("room.tour")};
  o.seeds = 2;
  o.layouts = 2;
  o.jobs = 2;
  o.out_dir = dir.file("exp");
  std::ostringstream out, err;
  ASSERT_EQ(tour_experiment(o, out, err), 0) << err.str();
  EXPECT_TRUE(contains(out.str(), "[4/4] ")) << out.str();
  EXPECT_TRUE(contains(out.str(), "distance + angle never longer than NNA, best orders: yes"));
  const std::string csv = slurp(dir.file("exp/results.csv"));
  // 2 layouts x 2 seeds x 3 variants with the GA, 2 layouts x 3 with the best orders, + header.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 12 + 6 + 1);
  for (const char* f : {"table.txt", "results.json", "tour.png", "tour-gap.png", "tour-room-nna.png"}) {
    EXPECT_TRUE(fs::exists(dir.file("exp/") + f)) << f;
  }
  EXPECT_EQ(nlohmann::json::parse(slurp(dir.file("exp/results.json")))["scenarios"].size(), 1u);
  o.seeds = 0;
  EXPECT_EQ(tour_experiment(o, out, err), 2);
}

}  // namespace
