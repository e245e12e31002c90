// The GCS node on the FakeBus with scripted leaders: it starts round 1 once every group's map has
// arrived, sends the delayed global map with it, and declares the mission complete when the fused
// map has no frontier left, which stops the run.
#include "swarm/gcs/gcs_node.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"

namespace swarm::gcs {
namespace {

using comm::LinkClass;
using planner::Cell;
using planner::CellChange;
using planner::CellState;
namespace topic = comm::topic;

std::vector<CellChange> cells_of(const planner::OccupancyGrid& g, int x_from, int x_to) {
  std::vector<CellChange> out;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = x_from; x < x_to; ++x) out.push_back({g.index({x, y}), g.at(Cell{x, y})});
  }
  return out;
}

TEST(GcsNode, StartsRoundsFromTheGroupsMapsAndDeclaresCompletionWhenNoFrontierIsLeft) {
  const auto art = swarm::test::ascii_map({
      "########",
      "#S.....#",
      "########",
  });
  swarm::scenario::Scenario sc;
  sc.set_groups(2);
  sc.set_robots_per_group(1);
  sc.set_max_ticks(50);
  auto setup = swarm::test::setup_for(art.grid, art.at.at('S'), sc);
  const comm::Topology& t = setup.topology;
  swarm::test::FakeSwarm s(setup, {t.leader(0), t.leader(1)});

  // Leader g sends the west half of the truth at tick 0 (group 0) or 1 (group 1), and group 0 the
  // east half at tick 6; both keep their heartbeats going.
  std::vector<msgs::RoundStart> rounds;
  for (int g = 0; g < 2; ++g) {
    auto& a = s.agent(t.leader(g));
    a.subscribe<msgs::Sense>(topic::sense(t.leader(g)), LinkClass::SimRobot, [](const msgs::Sense&) {},
                             comm::Delivery::BestEffort, 1);
    a.subscribe<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs,
                                  [&rounds, g](const msgs::RoundStart& r) { if (g == 0) rounds.push_back(r); },
                                  comm::Delivery::Reliable, 1);
    a.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {t.sim()});
    auto& patch = a.advertise<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, {t.gcs()});
    auto& beat = a.advertise<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, {t.gcs()});
    a.advertise<msgs::PlanReport>(topic::kPlanReport, LinkClass::Telemetry, {t.gcs()});
    s.script(t.leader(g), [&, g, &patch = patch, &beat = beat](const msgs::Clock& c) {
      msgs::Heartbeat h;
      h.group(static_cast<std::uint16_t>(g));
      beat.send(h);
      std::vector<CellChange> changes;
      if (c.tick() == static_cast<std::uint32_t>(g)) changes = cells_of(art.grid, 0, 4);
      if (g == 0 && c.tick() == 6) changes = cells_of(art.grid, 4, 8);
      if (changes.empty()) return;
      msgs::MapPatch p;
      p.group(static_cast<std::uint16_t>(g));
      p.data(app::encode_patch(changes, planner::PatchEncoding::RunLength));
      patch.send(p);
    });
  }
  s.start();
  while (s.step()) {
  }
  // Group 1's map arrives at tick 2: round 1 starts then; its map is the west half.
  ASSERT_FALSE(rounds.empty());
  EXPECT_EQ(rounds[0].round(), 1u);
  EXPECT_EQ(rounds[0].fused_tick(), 2u);
  planner::OccupancyGrid sent(art.grid.width(), art.grid.height());
  app::decode_map(rounds[0].map_rle(), static_cast<planner::PatchEncoding>(rounds[0].encoding()), sent);
  EXPECT_EQ(sent.at(Cell{3, 1}), CellState::Free);
  EXPECT_EQ(sent.at(Cell{4, 1}), CellState::Unknown);
  // The east half is fused at tick 7: no frontier, complete; the simulator stops the run.
  EXPECT_TRUE(s.complete());
  EXPECT_EQ(s.tick(), 8u);

  s.finish();
  std::ifstream in(s.run_dir() + "/metrics.json");
  const auto m = nlohmann::json::parse(in);
  EXPECT_EQ(m["steps"], 7);
  EXPECT_EQ(m["complete"], true);
  EXPECT_EQ(m["planning_rounds"], 1);
}

// Regression: without the simulator's report explored_fraction silently read 0.
TEST(GcsNode, ARunWithoutTheSimulatorsReportIsAnErrorNamingIt) {
  auto setup = swarm::test::setup_from_text("map: 'small' groups: 1 robots_per_group: 1 max_ticks: 3");
  swarm::test::FakeSwarm s(setup);
  s.start();
  while (s.step()) {
  }
  try {
    s.finish(/*sim_reports=*/false);
    ADD_FAILURE() << "finish() accepted a run without the simulator's report";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no end-of-run report from the simulator (sim)"), std::string::npos)
        << e.what();
  }
}

// The simulator's report arrived but cannot be read: an error naming the process (and, for a
// missing key, the key), never a metrics.json with zeros in it.
TEST(GcsNode, AnUnreadableSimulatorReportIsAnErrorNamingIt) {
  auto setup = swarm::test::setup_from_text("map: 'small' groups: 1 robots_per_group: 1 max_ticks: 3");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{not json", "the simulator's (sim) report is not valid JSON"},
      {"{}", "last_tick"},  // the first required key, named
  };
  for (const auto& [json, expected] : cases) {
    swarm::test::FakeSwarm s(setup);
    s.start();
    while (s.step()) {
    }
    try {
      s.finish(/*sim_reports=*/true, json);
      ADD_FAILURE() << "finish() accepted the simulator report " << json;
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(s.run_dir() + "/metrics.json")) << json;
  }
}

// A phase whose progress stops is given up, named stalled, long before max_ticks: a member cut off
// from tick 30 to the end holds cells of its share that no one else is given (it is not lost: its
// robot answers the simulator), so coverage stops short of them.
TEST(GcsNode, APhaseWhoseProgressStopsIsGivenUpAsStalled) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' groups: 2 robots_per_group: 2 max_ticks: 3000 stall_ticks: 200 faults { agent: 'member-0-1' "
      "cut_from_tick: 30 cut_to_tick: 2999 } mission { phase { cover {} } }"));
  const auto m = s.run_to_end();
  EXPECT_FALSE(m["complete"].get<bool>());
  const auto& cover = swarm::test::phase_named(m, "cover");
  ASSERT_TRUE(cover.contains("gave_up")) << cover.dump(1);
  EXPECT_EQ(cover["gave_up"].get<std::string>().rfind("stalled: covered at ", 0), 0u) << cover["gave_up"];
  // Ended stall_ticks after the last progress, not at max_ticks.
  EXPECT_LT(m["ticks_run"].get<int>(), 1500);
}

// Between two phases the robots must all be known to stand still before the next starts. A member
// whose links are cut as exploration ends cannot confirm its stop until they heal: after
// stall_ticks of waiting the next phase is given up as stalled, not waited for up to max_ticks.
TEST(GcsNode, RobotsThatDoNotAllStandStillInTimeStallTheNextPhase) {
  const std::string mission = "mission { phase { explore {} } phase { cover {} } }";
  // Lockstep runs are deterministic: the same run without the cut says when exploration ends.
  swarm::test::FakeSwarm plain(swarm::test::setup_from_text("map: 'small' max_ticks: 3000 " + mission));
  const int end = plain.run_to_end()["phases"][0]["end_tick"].get<int>();
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      "map: 'small' max_ticks: 3000 stall_ticks: 40 faults { agent: 'member-0-1' cut_from_tick: " + std::to_string(end) +
      " cut_to_tick: " + std::to_string(end + 800) + " } " + mission));
  const auto m = s.run_to_end();
  EXPECT_FALSE(m["complete"].get<bool>());
  ASSERT_EQ(m["phases"].size(), 2u) << m["phases"].dump(1);
  EXPECT_TRUE(m["phases"][0]["complete"].get<bool>());
  EXPECT_EQ(m["phases"][0]["end_tick"], end);
  const auto& cover = m["phases"][1];
  ASSERT_TRUE(cover["gave_up"].is_string()) << cover.dump(1);
  EXPECT_EQ(cover["gave_up"].get<std::string>().rfind("stalled: not every group reported its robots standing", 0), 0u);
  EXPECT_EQ(cover["start_tick"], cover["end_tick"]);
  EXPECT_EQ(cover["start_tick"].get<int>(), end + 40);
  EXPECT_LT(m["ticks_run"].get<int>(), end + 800);
}

}  // namespace
}  // namespace swarm::gcs
