// A task phase's settings turned into planner inputs (config/task_config.hpp): whether a phase is
// given the map.
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

}  // namespace
}  // namespace swarm::config
