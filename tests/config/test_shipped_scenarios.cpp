// Every scenario shipped in scenarios/ loads, validates and resolves to a world.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"

namespace {

namespace cfg = swarm::config;
namespace fs = std::filesystem;

std::vector<std::string> shipped() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(cfg::data_dir()) / "scenarios")) {
    if (e.path().extension() == ".pbtxt") names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

fs::path path_of(const std::string& name) {
  return fs::path(cfg::data_dir()) / "scenarios" / (name + ".pbtxt");
}

TEST(ShippedScenarios, AreThereAll) {
  EXPECT_EQ(shipped(),
            (std::vector<std::string>{"cover-given", "cover-small", "default", "deploy_faults", "mapf-small", "maze1",
                                      "maze2", "open", "small"}));
}

class Shipped : public ::testing::TestWithParam<std::string> {};

TEST_P(Shipped, LoadsAndResolves) {
  const fs::path p = path_of(GetParam());
  const swarm::scenario::Scenario s = cfg::load_scenario(p.string());
  EXPECT_EQ(s.name(), GetParam());
  const cfg::World w = cfg::resolve_world(s, p.parent_path().string(), p.string());
  EXPECT_EQ(w.robot_cells.size(), static_cast<size_t>(s.groups() * s.robots_per_group()));
  EXPECT_TRUE(w.scenario.has_start());
  // The recorded scenario (resolved start included) reads back and resolves the same way.
  const swarm::scenario::Scenario again = cfg::parse_scenario_text(cfg::to_text(w.scenario), "x");
  EXPECT_EQ(cfg::resolve_world(again, p.parent_path().string()).robot_cells, w.robot_cells);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, Shipped, ::testing::ValuesIn(shipped()),
                         [](const auto& info) {
                           std::string name = info.param;  // test names: letters, digits, '_'
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(ShippedScenarios, DefaultIsThePapersTable1OnMaze1) {
  const swarm::scenario::Scenario s = cfg::load_scenario(path_of("default").string());
  EXPECT_EQ(s.groups(), 3u);
  EXPECT_EQ(s.robots_per_group(), 3u);
  EXPECT_DOUBLE_EQ(s.sensing_range_m(), 3.0);
  EXPECT_EQ(s.explore().replan_threshold_steps(), 20u);
  EXPECT_EQ(s.explore().mode(), swarm::scenario::GROUP_FRONTIER);
  EXPECT_EQ(s.map(), "maze1");
  const cfg::World w = cfg::resolve_world(s, "");
  EXPECT_DOUBLE_EQ(w.truth.resolution(), 0.2);  // the grid size of Table 1 is the map's
}

TEST(ShippedScenarios, PaperMapsUseTable1) {
  for (const char* name : {"open", "maze1", "maze2"}) {
    const swarm::scenario::Scenario s = cfg::load_scenario(path_of(name).string());
    EXPECT_EQ(s.map(), name);
    EXPECT_EQ(s.groups() * s.robots_per_group(), 9u) << name;
    EXPECT_DOUBLE_EQ(s.sensing_range_m(), 3.0) << name;
    EXPECT_EQ(s.explore().replan_threshold_steps(), 20u) << name;
  }
}

TEST(ShippedScenarios, SmallIsAQuickTwoByTwoRun) {
  const swarm::scenario::Scenario s = cfg::load_scenario(path_of("small").string());
  EXPECT_EQ(s.map(), "small");
  EXPECT_EQ(s.groups(), 2u);
  EXPECT_EQ(s.robots_per_group(), 2u);
  EXPECT_LE(s.max_ticks(), 1000u);
}

}  // namespace
