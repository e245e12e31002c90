// The traffic layer end to end on the FakeBus (the real GCS, leaders, members and simulator, in one
// thread): each test hands the layer's engine (tasks/mapf/mapf_gcs.hpp, lifelong, as explore, cover
// and collect use it) a goal per robot, and the simulator judges from ground truth: every robot on
// its goal, no vertex or edge conflict, no move refused because of another robot. The meetings the
// layer exists for, each on a map drawn for it: head-on in a corridor, a robot that must be let by,
// a rotation on a ring, two groups through one door, a dead robot in a corridor, and late or lost
// messages.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"
#include "swarm_test/phase_checks.hpp"

namespace swarm::gcs {
namespace {

using planner::Cell;

// The GCS's task for the phase: the layer driving every robot id r to goals[r], in windows of 8.
GcsTaskFactory layer_to(std::vector<Cell> goals) {
  return [goals](const swarm::scenario::Phase&, const app::RoleSetup& setup, std::uint32_t index) -> std::unique_ptr<GcsTask> {
    MapfGcsTask::Lifelong layer;
    layer.routes = [goals](const GcsContext&, const planner::OccupancyGrid&, const std::vector<int>& robots, const char*) {
      std::vector<std::vector<Cell>> routes(goals.size());
      for (const int r : robots) routes[static_cast<std::size_t>(r)] = {goals[static_cast<std::size_t>(r)]};
      return MapfGcsTask::passing(routes);
    };
    layer.window = 8;
    return std::make_unique<MapfGcsTask>(tasks::traffic_driving(), index, config::map_given(setup.world.scenario, index),
                                         std::move(layer));
  };
}

struct Meeting {
  std::vector<std::string> art;  // the map; robot r starts on the cell marked '0' + r
  std::vector<Cell> goals;       // robot r's goal
  std::string scenario;          // groups, robots_per_group, links, ...
};

// Runs the meeting to its end (`at` each tick, as FakeSwarm::run_to_end); the metrics.json.
nlohmann::json drive(const Meeting& m, const std::function<void(swarm::test::FakeSwarm&, std::uint32_t)>& at = {}) {
  const auto art = swarm::test::ascii_map(m.art);
  auto sc = config::parse_scenario_text(
      m.scenario + " max_ticks: 400 mission { phase { mapf { execution: MAPF_EXECUTE_ADG } } }", "layer test");
  auto setup = swarm::test::setup_for(art.grid, art.at.at('0'), sc);
  for (std::size_t r = 0; r < setup.world.robot_cells.size(); ++r) {
    setup.world.robot_cells[r] = art.at.at(static_cast<char>('0' + r));
  }
  // The simulator's judge: every robot on its goal.
  auto* mapf = setup.world.scenario.mutable_mission()->mutable_phase(0)->mutable_mapf();
  for (const Cell c : m.goals) {
    auto* g = mapf->add_goals();
    g->set_x((c.x + 0.5) * art.grid.resolution());
    g->set_y((c.y + 0.5) * art.grid.resolution());
  }
  tasks::resolve_mission(setup.world, "layer test");
  swarm::test::FakeSwarm s(setup, {}, layer_to(m.goals));
  return s.run_to_end([&](std::uint32_t tick) {
    if (at) at(s, tick);
  });
}

// Every robot on its goal by ground truth, the GCS agreeing, and nothing in the way of anyone.
void expect_all_home(const nlohmann::json& m) {
  ASSERT_TRUE(m["complete"].get<bool>()) << m["ended"] << swarm::test::phase_named(m, "mapf").dump(1);
  const auto& p = swarm::test::phase_named(m, "mapf");
  EXPECT_TRUE(p["ground_truth_done"].get<bool>());
  swarm::test::expect_no_conflict(p);
  EXPECT_EQ(p["motion"]["wall_stops"], 0);
  EXPECT_EQ(p["motion"]["routes_rejected"], 0);
}

// Two robots of one group (the leader's own and a member) meet head-on in a one-cell corridor with
// one pocket: one steps into the pocket and lets the other pass (PIBT's swap).
TEST(TrafficLayer, HeadOnInAOneCellCorridorOneStepsIntoThePocket) {
  const Meeting m{{
                      "#########",
                      "#0.....1#",
                      "####.####",
                      "#########",
                  },
                  {{7, 2}, {1, 2}},
                  "groups: 1 robots_per_group: 2"};
  const auto metrics = drive(m);
  expect_all_home(metrics);
  EXPECT_EQ(swarm::test::phase_named(metrics, "mapf")["task"]["rescues"], 0);
}

// In the same corridor robots 0 and 1 are bound for its far end, robot 0 beyond robot 1's goal, and
// robot 2 at that end for where they come from: they must take turns in the pocket. PIBT alone
// stands or shuffles them there; the planner rescues them with a complete plan
// (planner/traffic/traffic.hpp), which the leaders drive like any other window.
TEST(TrafficLayer, ThreeRobotsTakeTurnsInThePocketByARescue) {
  for (const std::string links : {"", " links { member_leader { delay_ticks: 1 jitter_ticks: 4 } }"}) {
    SCOPED_TRACE(links.empty() ? "exact links" : "member<->leader 1-5 ticks");
    const Meeting m{{
                        "#########",
                        "#2....10#",
                        "####.####",
                        "#########",
                    },
                    {{1, 2}, {2, 2}, {7, 2}},
                    "groups: 1 robots_per_group: 3" + links};
    const auto metrics = drive(m);
    expect_all_home(metrics);
    const auto& layer = swarm::test::phase_named(metrics, "mapf")["task"];
    EXPECT_GE(layer["rescues"].get<int>(), 1) << layer.dump(1);
    EXPECT_EQ(layer["rescues_failed"], 0);
  }
}

// Four robots of two groups fill a ring of four cells, each to go to the next: no cell is free, so
// they can only all move at once, in one tick: a rotation, which the GCS orders.
TEST(TrafficLayer, ARotationOnAFullRingMovesEveryRobotInOneTick) {
  const Meeting m{{
                      "####",
                      "#01#",
                      "#32#",
                      "####",
                  },
                  {{2, 2}, {2, 1}, {1, 1}, {1, 2}},
                  "groups: 2 robots_per_group: 2"};
  const auto metrics = drive(m);
  expect_all_home(metrics);
  const auto& p = swarm::test::phase_named(metrics, "mapf");
  EXPECT_EQ(p["motion"]["moves"], 4);
  EXPECT_GE(p["task"]["rotations_ordered"].get<int>(), 1);
}

// Two groups of three swap rooms through a one-cell door.
constexpr const char* kDoorArt[] = {
    "#########",
    "#0..#..3#",
    "#1.....4#",
    "#2..#..5#",
    "#########",
};
const std::vector<Cell> kDoorGoals = {{7, 3}, {7, 2}, {7, 1}, {1, 3}, {1, 2}, {1, 1}};

TEST(TrafficLayer, TwoGroupsSwapRoomsThroughOneDoor) {
  const Meeting m{{std::begin(kDoorArt), std::end(kDoorArt)}, kDoorGoals, "groups: 2 robots_per_group: 3"};
  expect_all_home(drive(m));
}

// The same under late and lost messages: member<->leader delay 2 to 5 ticks, 5 % loss on every
// link. A late release only makes a robot wait.
TEST(TrafficLayer, TwoGroupsSwapRoomsThroughOneDoorWithLateAndLostMessages) {
  const Meeting m{{std::begin(kDoorArt), std::end(kDoorArt)},
                  kDoorGoals,
                  "groups: 2 robots_per_group: 3 links { member_leader { delay_ticks: 2 jitter_ticks: 3 loss: 0.05 } "
                  "leader_gcs { loss: 0.05 } sim_robot { loss: 0.05 } }"};
  expect_all_home(drive(m));
}

// Robot 1 dies at the start in the middle of the top corridor of a ring of corridors, on its own
// goal. Robot 0's way to the far end of that corridor runs through it: the layer holds the plan
// when the robot is lost, and plans again with it as an obstacle, so robot 0 goes round the ring,
// where robot 2 first gets out of its way into a pocket.
TEST(TrafficLayer, ADeadRobotInACorridorIsGoneRound) {
  const Meeting m{{
                      "#########",
                      "#0..1...#",
                      "#.#####.#",
                      "#2......#",
                      "####.####",
                      "#########",
                  },
                  {{7, 4}, {4, 4}, {4, 1}},
                  "groups: 1 robots_per_group: 3"};
  const auto metrics = drive(m, [](swarm::test::FakeSwarm& s, std::uint32_t tick) {
    if (tick == 1) s.disconnect(s.topology().robot(0, 1));
  });
  expect_all_home(metrics);
  const auto& p = swarm::test::phase_named(metrics, "mapf");
  EXPECT_EQ(p["motion"]["per_robot"]["member-0-1"]["moves"], 0);
  EXPECT_EQ(p["task"]["plans"].back()["why"], "robot lost");
  // Round the ring: down 2, along the bottom 6, up 2; and a step towards the dead robot and back
  // before its loss was known.
  EXPECT_EQ(p["motion"]["per_robot"]["leader-0"]["moves"], 10 + 2);
}

}  // namespace
}  // namespace swarm::gcs
