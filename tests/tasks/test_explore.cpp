// The exploration task on the FakeBus: its planning rounds follow the phase's own settings, and
// rounds are numbered across the run when a mission explores twice.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "swarm_test/fake_swarm.hpp"

namespace swarm::tasks {
namespace {

constexpr const char* kTwoGroups = "map: 'small' groups: 2 robots_per_group: 3 max_ticks: 800 ";

// The start tick of every planning round in metrics.json, checking they are numbered 1, 2, ...
std::vector<int> round_ticks(const nlohmann::json& m) {
  std::vector<int> ticks;
  for (const auto& r : m.at("rounds")) {
    EXPECT_EQ(r.at("round").get<int>(), static_cast<int>(ticks.size()) + 1) << m.at("rounds").dump();
    ticks.push_back(r.at("tick").get<int>());
  }
  return ticks;
}

TEST(ExploreTask, ThePhasesOwnReplanThresholdPacesTheRounds) {
  // The scenario-wide setting says 40 ticks; the phase says 3, and the phase decides.
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      std::string(kTwoGroups) +
      "explore { replan_threshold_steps: 40 } mission { phase { explore { replan_threshold_steps: 3 } } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  const std::vector<int> ticks = round_ticks(m);
  ASSERT_GE(ticks.size(), 5u);
  for (std::size_t i = 1; i < ticks.size(); ++i) EXPECT_LE(ticks[i] - ticks[i - 1], 3) << i;
  EXPECT_EQ(m["planning_rounds"], static_cast<int>(ticks.size()));
}

TEST(ExploreTask, ASecondExplorePhaseGoesOnNumberingTheRunsRounds) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(std::string(kTwoGroups) +
                                                        "mission { phase { explore {} } phase { explore {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  ASSERT_EQ(m["phases"].size(), 2u);
  const int first = m["phases"][0]["task"]["planning_rounds"].get<int>();
  const int second = m["phases"][1]["task"]["planning_rounds"].get<int>();
  EXPECT_GE(first, 2);
  // The map is already explored: the second phase plans once and sees no frontier left.
  EXPECT_EQ(second, 1);
  const std::vector<int> ticks = round_ticks(m);
  EXPECT_EQ(static_cast<int>(ticks.size()), first + second);
  EXPECT_EQ(m["planning_rounds"], first + second);
  // The phase starts at the tick the first one ended; its first step, the tick after, plans.
  EXPECT_EQ(ticks.back(), m["phases"][1]["start_tick"].get<int>() + 1);
}

}  // namespace
}  // namespace swarm::tasks
