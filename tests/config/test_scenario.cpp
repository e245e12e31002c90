// Scenario text: parsing with positioned errors, defaults, printing, mode names.
#include "swarm/config/scenario.hpp"
#include "swarm_test/text.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace {

namespace cfg = swarm::config;
namespace fs = std::filesystem;
using swarm::scenario::Scenario;

// A scratch folder per test, removed afterwards.
class ScenarioFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("swarm_config_scenario_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  fs::path dir_;
};

std::string error_of(const std::function<void()>& f) { return swarm::test::error_of<cfg::ConfigError>(f, "(no ConfigError)"); }

TEST(ScenarioDefaults, EqualThePapersTable1) {
  const Scenario s = cfg::parse_scenario_text("", "empty");
  EXPECT_EQ(s.groups(), 3u);
  EXPECT_EQ(s.robots_per_group(), 3u);
  EXPECT_DOUBLE_EQ(s.sensing_range_m(), 3.0);
  EXPECT_EQ(s.explore().replan_threshold_steps(), 20u);
  EXPECT_EQ(s.map(), "maze1");
  EXPECT_EQ(s.explore().mode(), swarm::scenario::GROUP_FRONTIER);
  EXPECT_EQ(s.explore().global_map_delay_rounds(), 1u);  // GCS fusion takes one planning round
  EXPECT_FALSE(s.has_start());                           // = the free cell nearest the centre
  EXPECT_NO_THROW(cfg::validate(s, "empty"));
}

TEST(ScenarioParse, ReadsEveryKindOfField) {
  const Scenario s = cfg::parse_scenario_text(R"(
    # a comment
    name: "t"
    map: "maps/x.yaml"
    start { x: 1.5 y: 2.5 }
    groups: 2
    robots_per_group: 4
    explore { mode: BASELINE replan_threshold_steps: 7 }
    links { leader_gcs { delay_ticks: 3 loss: 0.25 } }
    realtime: true
  )",
                                              "inline");
  EXPECT_EQ(s.name(), "t");
  EXPECT_EQ(s.map(), "maps/x.yaml");
  EXPECT_DOUBLE_EQ(s.start().x(), 1.5);
  EXPECT_DOUBLE_EQ(s.start().y(), 2.5);
  EXPECT_EQ(s.groups(), 2u);
  EXPECT_EQ(s.robots_per_group(), 4u);
  EXPECT_EQ(s.explore().mode(), swarm::scenario::BASELINE);
  EXPECT_EQ(s.explore().replan_threshold_steps(), 7u);
  EXPECT_EQ(s.links().leader_gcs().delay_ticks(), 3u);
  EXPECT_DOUBLE_EQ(s.links().leader_gcs().loss(), 0.25);
  EXPECT_TRUE(s.realtime());
}

TEST_F(ScenarioFile, MalformedValueReportsFileLineAndColumn) {
  const std::string path = write("bad.pbtxt",
                                 "# line 1\n"
                                 "groups: 3\n"
                                 "robots_per_group: abc\n");
  // Line 3; "abc" starts at column 19 (1-based).
  EXPECT_EQ(error_of([&] { (void)cfg::load_scenario(path); }).rfind(path + ":3:19: ", 0), 0u)
      << error_of([&] { (void)cfg::load_scenario(path); });
}

TEST_F(ScenarioFile, MissingBraceReportsWhereTheFileEnds) {
  const std::string path = write("bad.pbtxt", "explore {\n  mode: IDEAL\n");
  const std::string e = error_of([&] { (void)cfg::load_scenario(path); });
  EXPECT_EQ(e, path + ":3:1: unexpected end of file: the '{' at line 1, column 9 is never closed "
                   "(add '}')");
}

TEST_F(ScenarioFile, RepeatedFieldPointsAtTheRepeat) {
  const std::string path = write("bad.pbtxt", "groups: 3\ngroups: 4\n");
  EXPECT_EQ(error_of([&] { (void)cfg::load_scenario(path); }),
            path + ":2:1: Non-repeated field \"groups\" is specified multiple times.");
}

TEST_F(ScenarioFile, ColumnsCountATabAsOneCharacter) {
  const std::string path = write("bad.pbtxt", "\tgroups: x\n");
  const std::string e = error_of([&] { (void)cfg::load_scenario(path); });
  EXPECT_EQ(e.rfind(path + ":1:10: ", 0), 0u) << e;
}

TEST_F(ScenarioFile, BadBooleanPointsAtTheValue) {
  const std::string path = write("bad.pbtxt", "realtime: maybe\n");
  const std::string e = error_of([&] { (void)cfg::load_scenario(path); });
  EXPECT_EQ(e.rfind(path + ":1:11: ", 0), 0u) << e;
}

TEST_F(ScenarioFile, UnknownFieldSuggestsTheNearestName) {
  const std::string path = write("bad.pbtxt", "groups: 2\n  grups: 3\n");
  const std::string e = error_of([&] { (void)cfg::load_scenario(path); });
  EXPECT_EQ(e.rfind(path + ":2:3: ", 0), 0u) << e;
  EXPECT_NE(e.find("\"grups\""), std::string::npos) << e;
  EXPECT_NE(e.find("Did you mean \"groups\"?"), std::string::npos) << e;
}

TEST_F(ScenarioFile, UnknownModeListsTheModes) {
  const std::string path = write("bad.pbtxt", "explore {\n  mode: FAST\n}\n");
  const std::string e = error_of([&] { (void)cfg::load_scenario(path); });
  EXPECT_EQ(e.rfind(path + ":2:9: ", 0), 0u) << e;
  EXPECT_NE(e.find("GROUP_FRONTIER, BASELINE, IDEAL"), std::string::npos) << e;
}

TEST_F(ScenarioFile, EveryUnknownEnumValueListsItsOwnEnumsValues) {
  const std::string encoding = write("encoding.pbtxt", "map_encoding: SUPER_ZIP\n");
  std::string e = error_of([&] { (void)cfg::load_scenario(encoding); });
  EXPECT_EQ(e.rfind(encoding + ":1:15: ", 0), 0u) << e;
  EXPECT_NE(e.find("expected one of RAW_CELLS, RUN_LENGTH, ZSTD_RUN_LENGTH"), std::string::npos) << e;
  EXPECT_EQ(e.find("GROUP_FRONTIER"), std::string::npos) << e;
  const std::string solver = write("solver.pbtxt", "mission {\n  phase { mapf { solver: MAPF_MAGIC } }\n}\n");
  e = error_of([&] { (void)cfg::load_scenario(solver); });
  EXPECT_NE(e.find("expected one of MAPF_ECBS, MAPF_CBS, MAPF_LACAM"), std::string::npos) << e;
}

TEST_F(ScenarioFile, ADirectoryIsNoScenario) {
  // It would read as an empty file: the default scenario.
  const std::string e = error_of([&] { (void)cfg::load_scenario(dir_.string()); });
  EXPECT_EQ(e, dir_.string() + ": is a directory, not a scenario file (see scenarios/ for examples)");
}

TEST_F(ScenarioFile, NegativeCountIsAParseError) {
  const std::string path = write("bad.pbtxt", "groups: -1\n");
  EXPECT_EQ(error_of([&] { (void)cfg::load_scenario(path); }).rfind(path + ":1:9: ", 0), 0u)
      << error_of([&] { (void)cfg::load_scenario(path); });
}

TEST_F(ScenarioFile, LoadValidates) {
  const std::string path = write("bad.pbtxt", "groups: 0\n");
  EXPECT_EQ(error_of([&] { (void)cfg::load_scenario(path); }),
            path + ": field groups: must be >= 1 (got 0)");
}

TEST_F(ScenarioFile, MissingFileNamesIt) {
  const std::string path = (dir_ / "nope.pbtxt").string();
  const std::string e = error_of([&] { (void)cfg::load_scenario(path); });
  EXPECT_EQ(e.rfind(path + ": cannot open", 0), 0u) << e;
}

TEST(ScenarioText, RoundTripsEverySetField) {
  Scenario s;
  s.set_name("round");
  s.set_groups(5);
  s.mutable_start()->set_x(10.1);
  s.mutable_start()->set_y(0.3);
  s.set_tick_seconds(0.1);
  s.mutable_explore()->set_mode(swarm::scenario::IDEAL);
  s.mutable_links()->mutable_member_leader()->set_loss(0.05);
  const std::string text = cfg::to_text(s);
  EXPECT_NE(text.find("groups: 5"), std::string::npos) << text;
  EXPECT_NE(text.find("mode: IDEAL"), std::string::npos) << text;
  EXPECT_EQ(text.find("robots_per_group"), std::string::npos) << "unset fields stay unset\n"
                                                              << text;
  const Scenario back = cfg::parse_scenario_text(text, "printed");
  EXPECT_EQ(back.SerializeAsString(), s.SerializeAsString()) << text;
}

TEST(ScenarioMode, NamesRoundTrip) {
  for (auto m : {swarm::scenario::GROUP_FRONTIER, swarm::scenario::BASELINE,
                 swarm::scenario::IDEAL}) {
    EXPECT_EQ(cfg::parse_mode(cfg::mode_name(m)), m);
  }
  EXPECT_EQ(cfg::mode_name(swarm::scenario::GROUP_FRONTIER), "group-frontier");
  EXPECT_EQ(cfg::parse_mode("Group_Frontier"), swarm::scenario::GROUP_FRONTIER);
  EXPECT_EQ(cfg::parse_mode("BASELINE"), swarm::scenario::BASELINE);
}

TEST(ScenarioMode, UnknownNameListsTheAcceptedOnes) {
  EXPECT_EQ(error_of([] { (void)cfg::parse_mode("greedy"); }),
            "unknown mode 'greedy': expected one of group-frontier, baseline, ideal");
}

}  // namespace
