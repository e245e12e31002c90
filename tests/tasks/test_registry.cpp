// The task registry (tasks/registry.hpp) against the scenario schema: every task a phase can name
// has exactly one row, named as its field, with all of its parts; --mission takes every name.
#include "swarm/tasks/registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"
#include "swarm_test/fake_swarm.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace swarm::tasks {
namespace {

TEST(TaskRegistry, OneRowPerTaskOfTheSchemaNamedAsItsField) {
  const std::vector<std::string> names = config::task_names();
  EXPECT_EQ(names, (std::vector<std::string>{"explore", "cover", "mapf", "collect", "rendezvous"}));
  ASSERT_EQ(task_rows().size(), names.size());
  std::set<int> cases;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const TaskRow& row = task_rows()[i];
    EXPECT_EQ(row.name, names[i]);
    const auto* field = Phase::descriptor()->FindFieldByName(row.name);
    ASSERT_NE(field, nullptr) << row.name;
    EXPECT_EQ(static_cast<int>(row.phase_case), field->number()) << row.name;
    EXPECT_TRUE(cases.insert(row.phase_case).second) << row.name;
    EXPECT_TRUE(row.gcs && row.leader && row.judge) << row.name;
  }
}

TEST(TaskRegistry, EachPhaseOfAMissionFindsItsRowAndItsName) {
  auto s = config::parse_scenario_text("", "t");
  config::set_mission(s, config::task_names());
  const auto phases = config::mission_phases(s);
  ASSERT_EQ(phases.size(), task_rows().size());
  for (std::size_t i = 0; i < phases.size(); ++i) {
    EXPECT_EQ(config::task_name(phases[i]), task_rows()[i].name);
    EXPECT_EQ(&task_row(phases[i]), &task_rows()[i]);
  }
  EXPECT_THROW(config::set_mission(s, {"explore", "dance"}), config::ConfigError);
  try {
    config::set_mission(s, {"dance"});
  } catch (const config::ConfigError& e) {
    EXPECT_STREQ(e.what(), "unknown task 'dance': expected explore, cover, mapf, collect or rendezvous");
  }
}

// Every row makes its three parts for a phase of a real set-up, and its motion model is the one
// its planner assumes (coverage, MAPF and the rendezvous, which MAPF drives, on the 4-connected grid).
TEST(TaskRegistry, EveryRowMakesItsPartsAndMovesAsItsPlannerAssumes) {
  auto s = config::parse_scenario_text("groups: 1 robots_per_group: 2", "t");
  config::set_mission(s, config::task_names());
  const auto truth = swarm::test::grid_from(
      {"############", "#..........#", "#..........#", "#..........#", "#..........#", "############"});
  const app::RoleSetup setup = swarm::test::setup_for(truth, {5, 2}, s);
  const auto phases = config::mission_phases(setup.world.scenario);
  for (std::uint32_t i = 0; i < phases.size(); ++i) {
    EXPECT_NE(gcs_task(phases[i], setup, i), nullptr) << i;
    EXPECT_NE(group_task(phases[i], setup, 0, i), nullptr) << i;
    const sim::PhaseSim part = sim_part(phases[i], setup, i);
    EXPECT_NE(part.judge, nullptr) << i;
    const bool four = phases[i].has_cover() || phases[i].has_mapf() || phases[i].has_rendezvous();
    EXPECT_EQ(part.motion.neighbour_count(), four ? 4 : 8) << config::task_name(phases[i]);
  }
}

}  // namespace
}  // namespace swarm::tasks
