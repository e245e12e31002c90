// The coverage task end to end on the FakeBus (the real GCS, leaders, members and simulator, in
// one thread): every reachable free cell is covered, as the simulator judges from ground truth,
// with the map given, after exploration, in the flat variant, and when a member is lost midway;
// and through the traffic layer with no conflict.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "swarm_test/fake_swarm.hpp"
#include "swarm_test/phase_checks.hpp"

namespace swarm::leader {
namespace {

using swarm::test::expect_no_conflict;
using swarm::test::phase_named;

TEST(CoverTask, AfterExplorationTheExploredMapIsCovered) {
  const auto m = swarm::test::run_text(
      "map: 'small' groups: 1 robots_per_group: 3 max_ticks: 3000 "
      "mission { phase { explore {} } phase { cover {} } }");
  ASSERT_TRUE(m["complete"].get<bool>());
  ASSERT_EQ(m["phases"].size(), 2u);
  const auto& cover = phase_named(m, "cover");
  // It starts once the robots stand still: a stop's round trip after exploration ended.
  EXPECT_GT(cover["start_tick"].get<int>(), m["phases"][0]["end_tick"].get<int>());
  EXPECT_LE(cover["start_tick"].get<int>(), m["phases"][0]["end_tick"].get<int>() + 10);
  EXPECT_FALSE(cover["task"]["map_given"].get<bool>());
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
}

TEST(CoverTask, TheFlatVariantCoversToo) {
  const auto m = swarm::test::run_text(
      "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 2000 "
      "mission { phase { cover { hierarchical: false } } }");
  ASSERT_TRUE(m["complete"].get<bool>()) << m["phases"].dump(1) << m["agents"].dump(1);
  EXPECT_DOUBLE_EQ(phase_named(m, "cover")["task"]["covered_fraction"].get<double>(), 1.0);
}

// The cleaning order inside each robot's region (cover.order): plowing and Group-k reach every
// reachable cell as spanning-tree coverage does; their curves differ (the run's coverage_curve).
TEST(CoverTask, PlowAndGroupKOrdersCoverEveryReachableCell) {
  for (const std::string order : {"ORDER_PLOW", "ORDER_GROUP_K"}) {
    const auto m = swarm::test::run_text(
        "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 3000 mission { phase { cover { order: " + order +
        " } } }");
    ASSERT_TRUE(m["complete"].get<bool>()) << order;
    const auto& cover = phase_named(m, "cover");
    EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0) << order;
    EXPECT_EQ(cover["task"]["order"], order);
  }
}

// ---- Through the traffic layer (docs/traffic.md), in detail -------------------------------------

// The mission complete, every cell covered as the simulator judges, no conflict in the cover phase,
// which it returns.
const nlohmann::json& expect_covered_without_a_conflict(const nlohmann::json& m) {
  EXPECT_TRUE(m["complete"].get<bool>()) << m["phases"].dump(1);
  const auto& cover = phase_named(m, "cover");
  EXPECT_DOUBLE_EQ(cover["task"]["covered_fraction"].get<double>(), 1.0);
  expect_no_conflict(cover);
  return cover;
}

TEST(CoverTask, ThroughTheTrafficLayerEveryCellIsCoveredWithoutAConflict) {
  const auto m = swarm::test::run_text(
      "map: 'small' groups: 3 robots_per_group: 3 max_ticks: 3000 "
      "mission { phase { cover { traffic: true flat_candidate: false } } }");
  const auto& cover = expect_covered_without_a_conflict(m);
  EXPECT_GT(cover["task"]["traffic"]["windows"].get<int>(), 1);
  // The second bound: some robot must reach the cell farthest from every robot.
  EXPECT_GT(cover["task"]["reach_bound_moves"].get<int>(), 0);
  EXPECT_LE(cover["task"]["reach_bound_moves"].get<int>(), cover["task"]["makespan_ticks"].get<int>());
  // Each window is planned from the plan's end while the one before is driven, and continues the
  // plan: no window waits for the slowest robot of the last.
  EXPECT_GT(cover["task"]["traffic"]["windows_continued"].get<int>(), cover["task"]["traffic"]["windows"].get<int>() / 2);
  // As the hierarchical cover divides: among the groups, then each share among its robots; both
  // levels are recorded, each balanced within one cell of every share.
  const auto& division = cover["task"]["divisions"][0];
  EXPECT_EQ(division["agents"], "leaders");
  ASSERT_EQ(division["within_groups"].size(), 3u) << division.dump(1);
  std::vector<nlohmann::json> levels{division};
  for (const auto& g : division["within_groups"]) levels.push_back(g);
  for (const auto& d : levels) {
    EXPECT_EQ(d["darp_status"], "converged") << d.dump(1);
    EXPECT_TRUE(d["finished_by"] == "darp" || d["finished_by"] == "repair") << d.dump(1);
    for (std::size_t k = 0; k < d["cells"].size(); ++k) {
      EXPECT_LE(std::abs(d["cells"][k].get<double>() - d["shares"][k].get<double>()), 1.0) << d.dump(1);
    }
  }
}

// The explore, cover chain on warehouse-5x8, seed 2 (about 100 cells left for 9 robots), with
// these cover settings: the metrics, once the cover phase covered everything without a conflict.
nlohmann::json warehouse_after_exploration(const std::string& cover_settings) {
  auto m = swarm::test::run_text(
      "map: 'warehouse-5x8' groups: 3 robots_per_group: 3 max_ticks: 3000 seed: 2 "
      "mission { phase { explore {} } phase { cover { " + cover_settings + " } } }");
  expect_covered_without_a_conflict(m);
  return m;
}

// After exploration a group's robots stand scattered, and a share grown from the leader's cell
// sends its members across the map; the cells left are few and scattered. The division among all
// robots and the tours are made too, each rehearsed through the traffic layer, and the one
// cheapest to drive is driven: the fewest estimated ticks, then cells that no route passes, then
// planned steps, then moves onto other groups' parts, then moves in all. Seed 2: the cells left
// lie in two pieces. The groups' division of them as they lie weaves (28 planned steps, estimated
// at 33 ticks), the robots' less (21 steps, 25 ticks). The divisions of the pieces joined by one
// cell (region_graph.hpp, join_pieces) pass every cell too, the robots' in 20 planned steps
// estimated at 21 ticks. The tours pass every cell: the four solved plan 15-17 steps, estimated
// at 15-19 ticks, and the fourth (15 steps, estimated at 15 ticks: its longest route is a leader's
// own) is driven; the drive takes that from the routes' arrival at the leaders.
TEST(CoverTask, AfterExplorationTheDivisionCheaperToDriveIsDriven) {
  const auto m = warehouse_after_exploration("");
  const auto& cover = phase_named(m, "cover");
  const auto& division = cover["task"]["divisions"][0];
  const auto& compared = division["compared"];
  for (const char* candidate : {"leaders", "robots", "leaders-joined", "robots-joined", "tours-4"}) {
    ASSERT_TRUE(compared.contains(candidate)) << candidate << ": " << division.dump(1);
  }
  const auto key = [&](const char* candidate) {
    const auto& c = compared[candidate];
    return std::make_tuple(c["estimated_ticks"].get<int>(), c["cells_missed"].get<int>(), c["planned_steps"].get<int>(),
                           c["moves_in_other_groups_parts"].get<int>(), c["route_moves"].get<int>());
  };
  const auto longest = [&](const char* candidate) { return compared[candidate]["longest_route_moves"].get<int>(); };
  // The DARP divisions' longest routes, balanced by work (cover.route_balance_rounds).
  EXPECT_EQ(longest("leaders"), 24);
  EXPECT_EQ(longest("robots"), 19);
  EXPECT_EQ(longest("leaders-joined"), 23);
  EXPECT_EQ(longest("robots-joined"), 20);
  EXPECT_EQ(longest("tours-4"), 15);
  EXPECT_EQ(std::get<2>(key("leaders")), 28);
  EXPECT_EQ(std::get<2>(key("robots")), 21);
  EXPECT_EQ(std::get<2>(key("leaders-joined")), 23);
  EXPECT_EQ(std::get<2>(key("robots-joined")), 20);
  EXPECT_EQ(std::get<2>(key("tours-4")), 15);
  // Driven by the dependency graph, each member setting off a tick after the leaders' robots (its
  // route's way from the leader) and each robot that follows another into a cell a tick after it
  // left: the joined robots' division's 20 planned steps take 21 ticks; the tours' 15 take 15,
  // their longest route being a leader's own.
  EXPECT_EQ(std::get<0>(key("leaders")), 33);
  EXPECT_EQ(std::get<0>(key("robots")), 25);
  EXPECT_EQ(std::get<0>(key("leaders-joined")), 23);
  EXPECT_EQ(std::get<0>(key("robots-joined")), 21);
  EXPECT_EQ(std::get<0>(key("tours-4")), 15);
  // With exact links the routes' arrivals are known: one draw, so no range.
  EXPECT_EQ(compared["tours-4"]["estimated_ticks_range"], nlohmann::json::array({15, 15}));
  EXPECT_EQ(std::get<1>(key("leaders")), 0);
  EXPECT_EQ(std::get<1>(key("robots")), 0);
  EXPECT_EQ(std::get<1>(key("leaders-joined")), 0);
  EXPECT_EQ(std::get<1>(key("robots-joined")), 0);
  EXPECT_EQ(division["pieces"], 2) << division.dump(1);
  EXPECT_EQ(division["joining_cells"], 1) << division.dump(1);
  // The fourth tours are cheaper than the other three (on estimated ticks, 15 against 17-19).
  for (const char* tours : {"tours", "tours-2", "tours-3"}) {
    EXPECT_EQ(std::get<1>(key(tours)), 0) << tours;
    EXPECT_LT(key("tours-4"), key(tours)) << tours;
  }
  EXPECT_EQ(std::get<3>(key("tours-4")), 6);
  EXPECT_EQ(std::get<3>(key("tours-3")), 11);
  for (const char* division_kind : {"leaders", "robots", "leaders-joined", "robots-joined"}) {
    EXPECT_LT(key("tours-4"), key(division_kind)) << division_kind;
  }
  EXPECT_EQ(division["driven"], "tours-4") << division.dump(1);
  EXPECT_EQ(division["method"], "tours");
  // One plan covered everything: no second division for cells left.
  EXPECT_EQ(cover["task"]["divisions"].size(), 1u) << cover["task"]["divisions"].dump(1);
  // Driven without a push aside: the busiest robot made its route's 15 moves; and the phase took
  // the estimate and the order's way to the leaders.
  int busiest = 0;
  for (const auto& [name, r] : cover["motion"]["per_robot"].items()) busiest = std::max(busiest, r["moves"].get<int>());
  EXPECT_EQ(busiest, 15);
  EXPECT_EQ(cover["end_tick"].get<int>() - cover["start_tick"].get<int>(), 15 + 1);
}

// Under member<->leader jitter (1 to 5 ticks) a member's route arrives when its draw says: each
// candidate's estimate is the mean of its drive over draws of the routes' arrivals, within the
// range of those draws, and the candidate with the lowest mean is driven.
TEST(CoverTask, UnderLinkJitterEachCandidateIsEstimatedOverDrawsOfTheRoutesArrivals) {
  auto m = swarm::test::run_text(
      "map: 'warehouse-5x8' groups: 3 robots_per_group: 3 max_ticks: 3000 seed: 2 "
      "links { member_leader { delay_ticks: 1 jitter_ticks: 4 } } "
      "mission { phase { explore {} } phase { cover {} } }");
  expect_covered_without_a_conflict(m);
  const auto& division = phase_named(m, "cover")["task"]["divisions"][0];
  const auto& compared = division["compared"];
  ASSERT_GE(compared.size(), 3u) << division.dump(1);
  double lowest_mean = 1e9;
  int spread = 0;
  for (const auto& [name, c] : compared.items()) {
    const double mean = c["estimated_ticks"].get<double>();
    const int fastest = c["estimated_ticks_range"][0].get<int>(), slowest = c["estimated_ticks_range"][1].get<int>();
    EXPECT_LE(fastest, mean) << name;
    EXPECT_LE(mean, slowest) << name;
    // The draws differ, except for a candidate whose members' routes come, in every draw, before
    // any of their cells is the last to be covered (the tours planned for the latest arrival).
    spread += fastest < slowest ? 1 : 0;
    // Never faster than with every route there at once: the plan's steps at the least (a tick more
    // when the longest route is a member's, sent on by its leader; here it may be a leader's own).
    EXPECT_GE(fastest, c["planned_steps"].get<int>()) << name;
    lowest_mean = std::min(lowest_mean, mean);
  }
  EXPECT_GE(spread, static_cast<int>(compared.size()) - 1) << division.dump(1);
  // The driven one has the lowest mean (candidates tied on it are ranked by the costs after it).
  const std::string driven = division["driven"].get<std::string>();
  ASSERT_TRUE(compared.contains(driven)) << division.dump(1);
  EXPECT_EQ(compared[driven]["estimated_ticks"].get<double>(), lowest_mean) << division.dump(1);
}

// Few cells left but the tours switched off (tour_candidate_cells: 0): only the DARP divisions are
// compared.
TEST(CoverTask, WithoutTheTourCandidateOnlyTheDivisionsAreCompared) {
  const auto m = warehouse_after_exploration("tour_candidate_cells: 0");
  const auto& division = phase_named(m, "cover")["task"]["divisions"][0];
  EXPECT_FALSE(division["compared"].contains("tours")) << division.dump(1);
  // The cheapest of the four (the same as with the tours): the robots' division of the pieces
  // joined, 21 estimated ticks, against 23 for the groups' and 33 and 25 for the cells as they
  // lie.
  EXPECT_EQ(division["driven"], "robots-joined") << division.dump(1);
}

// A time limit past the clock's range is no limit: the divisions run as without one (it used to
// wrap to a deadline already past, and DARP stopped after 0 iterations: cells [38, 1356]).
TEST(CoverTask, AHugeDarpTimeLimitIsNoLimit) {
  for (const char* limit : {"1e12", "inf"}) {
    const auto m = swarm::test::run_text(
        std::string("map: 'small' groups: 2 robots_per_group: 2 max_ticks: 3000 mission { phase { cover { "
                    "darp_time_limit_s: ") +
        limit + " } } }");
    ASSERT_TRUE(m["complete"].get<bool>()) << limit;
    const auto& division = phase_named(m, "cover")["task"]["divisions"][0];
    EXPECT_EQ(division["darp_status"], "converged") << limit << ": " << division.dump(1);
    EXPECT_GT(division["darp_iterations"].get<int>(), 0) << limit << ": " << division.dump(1);
    for (std::size_t k = 0; k < division["cells"].size(); ++k) {
      EXPECT_LE(std::abs(division["cells"][k].get<double>() - division["shares"][k].get<double>()), 1.0) << limit;
    }
  }
}

// Jitter on the GCS's link reorders its orders: a window can reach a leader before the one it
// continues, and a relay of progress before its window. They wait for it; nothing is lost.
TEST(CoverTask, ThroughTheTrafficLayerWindowsThatArriveOutOfOrderWaitForTheirPlan) {
  for (const int seed : {1, 2}) {
    SCOPED_TRACE(seed);
    const auto m = swarm::test::run_text(
        "map: 'small' groups: 3 robots_per_group: 3 max_ticks: 4000 seed: " + std::to_string(seed) +
        " links { leader_gcs { delay_ticks: 2 jitter_ticks: 2 loss: 0.05 } member_leader { jitter_ticks: 1 } } "
        "mission { phase { cover { } } }");
    const auto& cover = expect_covered_without_a_conflict(m);
    EXPECT_GT(cover["task"]["traffic"]["windows_continued"].get<int>(), 0);
  }
}

TEST(CoverTask, ThroughTheTrafficLayerTheFlatDivisionCoversToo) {
  const auto m = swarm::test::run_text(
      "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 3000 "
      "mission { phase { cover { traffic: true hierarchical: false } } }");
  const auto& cover = expect_covered_without_a_conflict(m);
  EXPECT_EQ(cover["task"]["divisions"][0]["agents"], "robots");
}

TEST(CoverTask, ThroughTheTrafficLayerAfterExplorationTooWithoutAConflict) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 3 robots_per_group: 3 max_ticks: 4000 "
      "mission { phase { explore {} } phase { cover { traffic: true } } }"));
  expect_covered_without_a_conflict(s.run_to_end());
}

TEST(CoverTask, ThroughTheTrafficLayerALostMembersCellsGoToTheOthers) {
  auto setup = swarm::test::setup_from_text(
      "map: 'small' groups: 2 robots_per_group: 3 max_ticks: 4000 mission { phase { cover { traffic: true } } }");
  swarm::test::FakeSwarm s(setup);
  const auto m = s.run_to_end([&](std::uint32_t tick) {
    if (tick == 60) s.disconnect(setup.topology.robot(0, 2));
  });
  const auto& cover = expect_covered_without_a_conflict(m);
  bool redivided = false;
  for (const auto& d : cover["task"]["divisions"]) redivided = redivided || d["why"] == "robot lost";
  EXPECT_TRUE(redivided) << cover["task"]["divisions"].dump();
}

}  // namespace
}  // namespace swarm::leader
