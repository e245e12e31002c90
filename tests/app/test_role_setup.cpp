// What a role's set-up holds of the map (app::load_role): only the simulator holds the ground
// truth; the other roles know the map's frame, and its cells only when the scenario gives the
// robots the map (config::map_given).
#include "swarm/app/role.hpp"

#include <gtest/gtest.h>

#include <string>

#include "swarm_test/data.hpp"

namespace swarm::app {
namespace {

RoleSetup load(const std::string& scenario, RoleKind kind) {
  RoleOptions o;
  o.scenario_path = test::source_dir() + "/scenarios/" + scenario;
  o.group = 0;
  o.indices = {1};
  return load_role(o, kind);
}

TEST(RoleSetup, NoRoleButTheSimulatorHoldsTheTruthWhenTheRobotsExplore) {
  const RoleSetup sim = load("small.pbtxt", RoleKind::Sim);
  ASSERT_GT(sim.world.truth.size(), 0u);
  for (const RoleKind kind : {RoleKind::Gcs, RoleKind::Leader, RoleKind::Member}) {
    const RoleSetup role = load("small.pbtxt", kind);
    EXPECT_EQ(role.world.truth.size(), 0u) << static_cast<int>(kind);
    EXPECT_EQ(role.given_map.size(), 0u) << static_cast<int>(kind);
    // The frame is the map's extent, which every role needs for its own maps.
    EXPECT_EQ(role.world.frame.width, sim.world.truth.width());
    EXPECT_EQ(role.world.frame.height, sim.world.truth.height());
    EXPECT_EQ(role.world.frame.cells(), sim.world.truth.size());
    EXPECT_DOUBLE_EQ(role.world.frame.resolution, sim.world.truth.resolution());
  }
}

TEST(RoleSetup, ARoleIsGivenTheMapWhenNoExplorationComesFirst) {
  const RoleSetup sim = load("cover-given.pbtxt", RoleKind::Sim);
  for (const RoleKind kind : {RoleKind::Gcs, RoleKind::Leader, RoleKind::Member}) {
    const RoleSetup role = load("cover-given.pbtxt", kind);
    EXPECT_EQ(role.world.truth.size(), 0u) << static_cast<int>(kind);
    ASSERT_EQ(role.given_map.size(), sim.world.truth.size()) << static_cast<int>(kind);
    for (int i = 0; i < static_cast<int>(role.given_map.size()); ++i) {
      ASSERT_EQ(role.given_map.at(i), sim.world.truth.at(i)) << i;
    }
  }
}

}  // namespace
}  // namespace swarm::app
