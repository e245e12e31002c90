// The rendezvous task: where it gathers the robots (gather.hpp, checked against an independent
// brute force), and its GCS and leader parts with the simulator's judge on the FakeBus (the real
// nodes in one thread).
#include "swarm/tasks/rendezvous/gather.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"

namespace swarm::tasks::rendezvous {
namespace {

using planner::Cell;

// The sum of the k smallest 8-connected step counts from `centre` over every reachable free cell:
// no k distinct cells stand tighter (an independent check of the cells gather() picks).
long long tightest(const planner::OccupancyGrid& map, Cell centre, std::size_t k) {
  std::vector<int> steps;
  for (const int s : steps_from(map, centre, planner::MotionModel::eight())) {
    if (s >= 0) steps.push_back(s);
  }
  std::sort(steps.begin(), steps.end());
  return std::accumulate(steps.begin(), steps.begin() + static_cast<long>(std::min(k, steps.size())), 0LL);
}

// The least sum of 4-connected path lengths over every assignment of robots to cells (brute force).
double best_assignment(const planner::OccupancyGrid& map, const std::vector<Cell>& robots, std::vector<Cell> cells) {
  std::sort(cells.begin(), cells.end(), [](Cell a, Cell b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
  double best = 1e18;
  do {
    double sum = 0;
    for (std::size_t i = 0; i < robots.size(); ++i) {
      sum += steps_from(map, cells[i], planner::MotionModel::four())[static_cast<std::size_t>(map.index(robots[i]))];
    }
    best = std::min(best, sum);
  } while (std::next_permutation(cells.begin(), cells.end(),
                                 [](Cell a, Cell b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); }));
  return best;
}

const planner::OccupancyGrid kRooms = swarm::test::grid_from({
    "############",
    "#.....#....#",
    "#.....#....#",
    "#..........#",
    "#.....#....#",
    "############",
});

TEST(Gather, PacksAroundThePointAndAssignsTheShortestPaths) {
  const std::vector<Cell> robots{{1, 1}, {5, 4}, {10, 1}, {8, 4}};
  const Gathering g = gather(kRooms, {3, 2}, robots);
  EXPECT_EQ(g.centre, (Cell{3, 2}));
  ASSERT_EQ(g.cells.size(), 4u);
  EXPECT_EQ(g.cells[0], (Cell{3, 2}));
  // The tightest cluster there is: the centre and three of its 8 neighbours (1 step each).
  EXPECT_EQ(packing(kRooms, g.centre, g.cells).step_sum, 3);
  EXPECT_EQ(packing(kRooms, g.centre, g.cells).step_sum, tightest(kRooms, g.centre, 4));
  // Every robot on a cell of its own, and no assignment is shorter.
  std::set<std::pair<int, int>> distinct;
  for (const Cell c : g.goals) distinct.insert({c.x, c.y});
  EXPECT_EQ(distinct.size(), 4u);
  for (const Cell c : g.goals) EXPECT_NE(std::find(g.cells.begin(), g.cells.end(), c), g.cells.end());
  EXPECT_DOUBLE_EQ(g.path_sum, best_assignment(kRooms, robots, g.cells));
  // (1, 1) -> (2, 2): 2; (5, 4) -> (3, 3): 3; (10, 1) -> (4, 2) and (8, 4) -> (3, 2) through the
  // doorway (6, 2): 7 each.
  EXPECT_DOUBLE_EQ(g.path_sum, 19.0);
}

TEST(Gather, APointInAWallGathersAtTheNearestFreeCell) {
  const Gathering g = gather(kRooms, {6, 1}, {{1, 1}, {2, 1}});
  EXPECT_EQ(g.centre, (Cell{5, 1}));  // (7, 1) is as near; the lower index wins
  EXPECT_EQ(packing(kRooms, g.centre, g.cells).step_sum, tightest(kRooms, g.centre, 2));
}

TEST(Gather, ARobotThatCannotReachIsLeftOutAndTheOthersStillGather) {
  planner::OccupancyGrid walled = kRooms;
  walled.set({6, 2}, planner::CellState::Occupied);  // the doorway: two rooms apart
  const Gathering g = gather(walled, {2, 2}, {{1, 1}, {9, 2}, {4, 4}});
  EXPECT_EQ(g.goals[1], (Cell{-1, -1}));
  EXPECT_EQ(g.cells.size(), 2u);
  EXPECT_GE(g.goals[0].x, 0);
  EXPECT_GE(g.goals[2].x, 0);
  EXPECT_EQ(packing(walled, g.centre, {g.goals[0], g.goals[2]}).step_sum, tightest(walled, g.centre, 2));
}

// Gathering at the run's start picks exactly the start cells, so every robot already home stays.
TEST(Gather, HomeIsTheStartCells) {
  const std::vector<Cell> starts = planner::start_cells(kRooms, {3, 2}, 6);
  const Gathering g = gather(kRooms, {3, 2}, starts);
  EXPECT_EQ(g.cells, starts);
  EXPECT_EQ(g.goals, starts);
  EXPECT_DOUBLE_EQ(g.path_sum, 0.0);
}

// ---- The task on the FakeBus ----------------------------------------------------------------------

constexpr const char* kTwoGroups = "map: 'small' groups: 2 robots_per_group: 3 max_ticks: 800 ";

// Robots first driven apart (mapf to random goals), then home: every one back on a start cell,
// judged from the ground truth, with no conflict.
TEST(RendezvousTask, HomeBringsEveryRobotBackToTheStartCells) {
  swarm::test::FakeSwarm s(
      swarm::test::setup_from_text(std::string(kTwoGroups) + "mission { phase { mapf {} } phase { rendezvous {} } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  const auto& p = swarm::test::phase_named(m, "rendezvous");
  EXPECT_EQ(p["task"]["target"], "home");
  EXPECT_EQ(p["task"]["robots_alive"], 6);
  EXPECT_EQ(p["task"]["on_gathering_cells"], 6);
  EXPECT_TRUE(p["task"]["packed"].get<bool>());
  EXPECT_EQ(p["task"]["step_sum"], p["task"]["ideal_step_sum"]);
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["motion"]["blocked_moves"], 0);
  EXPECT_GT(p["task"]["makespan_ticks"].get<int>(), 0);
  std::set<std::pair<int, int>> starts;
  for (const Cell c : s.setup().world.robot_cells) starts.insert({c.x, c.y});
  for (const Cell c : s.sim().world().robots()) EXPECT_EQ(starts.count({c.x, c.y}), 1u) << c.x << "," << c.y;
}

TEST(RendezvousTask, EveryRobotGathersAroundAPointPackedAsTightlyAsTheCellsAllow) {
  swarm::test::FakeSwarm s(swarm::test::setup_from_text(
      std::string(kTwoGroups) + "mission { phase { rendezvous { point { x: 6.1 y: 1.1 } } } }"));
  const auto m = s.run_to_end();
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  const auto& p = swarm::test::phase_named(m, "rendezvous");
  EXPECT_EQ(p["task"]["target"], "point");
  EXPECT_EQ(p["task"]["centre"], nlohmann::json::array({30, 5}));
  EXPECT_EQ(p["task"]["on_gathering_cells"], 6);
  EXPECT_TRUE(p["task"]["packed"].get<bool>());
  EXPECT_EQ(p["task"]["ideal_step_sum"], 5);  // the centre and five of its 8 neighbours (1 step each)
  EXPECT_EQ(p["task"]["conflicts"], 0);
  EXPECT_EQ(p["task"]["paths"]["robots_at_goal"], 6);
}

// A member lost on the way: the GCS holds the plan, gathers the five others (the lost one standing
// where it stopped) and reports it lost; the simulator agrees.
TEST(RendezvousTask, ARobotLostOnTheWayTheOthersStillGatherAndItIsReported) {
  auto setup = swarm::test::setup_from_text(
      std::string(kTwoGroups) +
      "mission { phase { rendezvous { point { x: 6.1 y: 1.1 } execution: MAPF_EXECUTE_ADG } } }");
  swarm::test::FakeSwarm s(setup);
  const comm::AgentId lost = setup.topology.robot(1, 2);
  const auto m = s.run_to_end([&](std::uint32_t tick) {
    if (tick == 12) s.disconnect(lost);
  });
  ASSERT_TRUE(m["complete"].get<bool>()) << m.dump();
  const auto& p = swarm::test::phase_named(m, "rendezvous");
  EXPECT_EQ(p["task"]["robots_lost"], nlohmann::json::array({lost}));
  EXPECT_EQ(p["task"]["robots_alive"], 5);
  EXPECT_EQ(p["task"]["on_gathering_cells"], 5);
  EXPECT_TRUE(p["task"]["packed"].get<bool>());
  EXPECT_EQ(p["task"]["conflicts"], 0);
  const auto& plans = p["task"]["paths"]["plans"];
  ASSERT_EQ(plans.size(), 2u) << plans;
  EXPECT_EQ(plans[1]["why"], "robot lost");
  EXPECT_EQ(plans[1]["robots"], 5);
}

}  // namespace
}  // namespace swarm::tasks::rendezvous
