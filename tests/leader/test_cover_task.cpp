// The coverage task end to end on the FakeBus (the real GCS, leaders, members and simulator, in
// one thread): every reachable free cell is covered, as the simulator judges from ground truth,
// with the map given, after exploration, in the flat variant, and when a member is lost midway.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "swarm_test/fake_swarm.hpp"

namespace swarm::leader {
namespace {

nlohmann::json run_to_end(swarm::test::FakeSwarm& s, const std::function<void()>& at_tick_60 = {}) {
  s.start();
  while (s.step()) {
    if (s.tick() == 60 && at_tick_60) at_tick_60();
  }
  s.finish();
  std::ifstream in(s.run_dir() + "/metrics.json");
  return nlohmann::json::parse(in);
}

const nlohmann::json& phase_named(const nlohmann::json& m, const std::string& name) {
  for (const auto& p : m["phases"]) {
    if (p["name"] == name) return p;
  }
  throw std::runtime_error("no phase " + name);
}

TEST(CoverTask, GivenTheMapTwoGroupsCoverEveryReachableCell) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 2000 mission { phase { cover {} } }"));
  const auto m = run_to_end(s);
  ASSERT_TRUE(m["complete"].get<bool>());
  const auto& cover = phase_named(m, "cover");
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
  EXPECT_EQ(cover["task"]["target_cells"], 1398);  // every free cell of `small` (README of maps/)
  EXPECT_TRUE(cover["task"]["map_given"].get<bool>());
  EXPECT_EQ(cover["task"]["makespan_ticks"].get<int>() + cover["start_tick"].get<int>(), m["steps"].get<int>());
  EXPECT_EQ(cover["motion"]["wall_stops"], 0);
  // Each leader divided its share once among its two robots.
  EXPECT_EQ(m["agents"]["leader-0"]["phases"][0]["numbers"]["divisions"].size(), 1u);
}

TEST(CoverTask, AfterExplorationTheExploredMapIsCovered) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 1 robots_per_group: 3 max_ticks: 3000 "
      "mission { phase { explore {} } phase { cover {} } }"));
  const auto m = run_to_end(s);
  ASSERT_TRUE(m["complete"].get<bool>());
  ASSERT_EQ(m["phases"].size(), 2u);
  const auto& cover = phase_named(m, "cover");
  EXPECT_EQ(cover["start_tick"], m["phases"][0]["end_tick"]);
  EXPECT_FALSE(cover["task"]["map_given"].get<bool>());
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
}

TEST(CoverTask, TheFlatVariantCoversToo) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 2000 "
      "mission { phase { cover { hierarchical: false } } }"));
  const auto m = run_to_end(s);
  ASSERT_TRUE(m["complete"].get<bool>()) << m["phases"].dump(1) << m["agents"].dump(1);
  EXPECT_DOUBLE_EQ(phase_named(m, "cover")["task"]["covered_fraction"].get<double>(), 1.0);
}

TEST(CoverTask, AMemberLostMidwayIsCoveredForByTheOthers) {
  auto setup = swarm::test::setup_from_text(
      "map: 'small' groups: 1 robots_per_group: 3 max_ticks: 3000 mission { phase { cover {} } }");
  swarm::test::FakeSwarm s(setup);
  const auto m = run_to_end(s, [&] { s.disconnect(setup.topology.robot(0, 2)); });
  ASSERT_TRUE(m["complete"].get<bool>());
  EXPECT_DOUBLE_EQ(phase_named(m, "cover")["task"]["covered_fraction"].get<double>(), 1.0);
  const auto& divisions = m["agents"]["leader-0"]["phases"][0]["numbers"]["divisions"];
  ASSERT_EQ(divisions.size(), 2u);
  EXPECT_EQ(divisions[1]["why"], "member lost");
  EXPECT_EQ(divisions[1]["robots"], 2);
}

}  // namespace
}  // namespace swarm::leader
