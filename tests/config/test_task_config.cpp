// What the run's settings allow every task (config/task_config.hpp): whether a phase is given the
// map; and the phases a mission runs, with their defaults (config::mission_phases).
#include "swarm/config/task_config.hpp"

#include <gtest/gtest.h>

#include "swarm/config/scenario.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace swarm::config {
namespace {

TEST(MapGiven, OnlyPhasesThatNoExplorationPrecedesAreGivenTheMap) {
  const auto mission = [](const std::string& phases) { return parse_scenario_text("mission { " + phases + " }", "t"); };
  const auto explore_first = mission("phase { explore {} } phase { cover {} } phase { mapf {} }");
  EXPECT_FALSE(map_given(explore_first, 0));  // exploration never is
  EXPECT_FALSE(map_given(explore_first, 1));
  EXPECT_FALSE(map_given(explore_first, 2));
  EXPECT_FALSE(any_map_given(explore_first));
  const auto cover_first = mission("phase { cover {} } phase { collect {} } phase { explore {} } phase { mapf {} }");
  EXPECT_TRUE(map_given(cover_first, 0));
  EXPECT_TRUE(map_given(cover_first, 1));
  EXPECT_FALSE(map_given(cover_first, 2));
  EXPECT_FALSE(map_given(cover_first, 3));
  EXPECT_FALSE(map_given(cover_first, 4));  // past the mission
  EXPECT_TRUE(any_map_given(cover_first));
}

TEST(MissionPhases, ATopLevelFieldOfATasksTypeGivesThatTasksDefaults) {
  const auto s = parse_scenario_text(
      "explore { mode: BASELINE dbscan_eps_cells: 3 } "
      "mission { phase { explore { dbscan_eps_cells: 5 } } phase { cover {} } phase { explore {} } }",
      "t");
  const auto phases = mission_phases(s);
  ASSERT_EQ(phases.size(), 3u);
  EXPECT_EQ(phases[0].explore().mode(), swarm::scenario::BASELINE);  // from the top level
  EXPECT_EQ(phases[0].explore().dbscan_eps_cells(), 5);              // its own wins
  EXPECT_TRUE(phases[1].has_cover());
  EXPECT_EQ(phases[2].explore().mode(), swarm::scenario::BASELINE);
  EXPECT_EQ(phases[2].explore().dbscan_eps_cells(), 3);
  // No mission: the first task of the schema alone, with the top-level settings.
  const auto alone = mission_phases(parse_scenario_text("explore { mode: IDEAL }", "t"));
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(task_name(alone[0]), "explore");
  EXPECT_EQ(alone[0].explore().mode(), swarm::scenario::IDEAL);
}

}  // namespace
}  // namespace swarm::config
