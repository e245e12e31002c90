// The MAPF solvers behind solve() (planner/mapf/solver.hpp): CBS's sum of costs equals a brute
// force's optimum, ECBS stays within w of it, every plan passes the independent validator, an
// unsolvable instance (grid or graph) ends with a status inside its limit, reservations are
// respected, results are deterministic, and every solver's plans are valid on MovingAI maps.
#include <gtest/gtest.h>

#include "mapf_brute_force.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm/planner/mapf/validate.hpp"
#include "swarm/planner/mapf/warehouse.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/data.hpp"

namespace {

using swarm::planner::Cell;
using swarm::planner::OccupancyGrid;
using namespace swarm::planner::mapf;
using swarm::test::brute_force_soc;

SolverConfig config(SolverKind kind, double w = 1.5) {
  SolverConfig c;
  c.kind = kind;
  c.ecbs.w = w;
  return c;
}

Instance small_random(std::uint64_t seed) {
  // 4 x 4 with two walls; 3 agents.
  const OccupancyGrid map = swarm::test::grid_from({"....", ".#..", "..#.", "...."});
  return *random_instance(map, 3, seed);
}

TEST(MapfSolvers, CbsMatchesTheBruteForceOptimum) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const Instance in = small_random(seed);
    const long long optimum = brute_force_soc(in);
    const Result r = solve(in, config(SolverKind::Cbs), StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved) << "seed " << seed << ": " << r.message;
    EXPECT_TRUE(validate(in, r.paths).ok()) << "seed " << seed << ": " << validate(in, r.paths).summary();
    EXPECT_EQ(r.soc, optimum) << "seed " << seed;
  }
}

TEST(MapfSolvers, CbsWithoutImprovementsIsStillOptimal) {
  SolverConfig plain = config(SolverKind::Cbs);
  plain.cbs.prioritize_conflicts = false;
  plain.cbs.bypass = false;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Instance in = small_random(seed);
    const Result r = solve(in, plain, StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved);
    EXPECT_EQ(r.soc, brute_force_soc(in)) << "seed " << seed;
  }
}

// The corridor with one alcove (2, 0): agent 1 stands in agent 0's way and must step aside. By
// hand: agent 1 enters the alcove at t = 1, agent 0 passes (2, 1) at t = 2, agent 1 comes back at
// t = 3 and reaches (3, 1) at t = 4 while agent 0 reaches (4, 1): 4 + 4 = 8 (lower bound 4 + 1).
TEST(MapfSolvers, CorridorWithAnAlcove) {
  Instance in;
  in.map = swarm::test::grid_from({"#####", ".....", "##.##"});
  in.starts = {{0, 1}, {2, 1}};
  in.goals = {{4, 1}, {3, 1}};
  const long long optimum = brute_force_soc(in);
  EXPECT_EQ(optimum, 8);
  EXPECT_EQ(lower_bound(in), 5);
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
    const Result r = solve(in, config(k), StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved) << to_string(k);
    EXPECT_TRUE(validate(in, r.paths).ok());
    if (k == SolverKind::Cbs) EXPECT_EQ(r.soc, optimum);
    if (k == SolverKind::Ecbs) EXPECT_LE(static_cast<double>(r.soc), 1.5 * static_cast<double>(optimum));
  }
}

TEST(MapfSolvers, EcbsStaysWithinItsBound) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const Instance in = small_random(seed);
    const long long optimum = brute_force_soc(in);
    const Result r = solve(in, config(SolverKind::Ecbs, 1.2), StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved);
    EXPECT_TRUE(validate(in, r.paths).ok());
    EXPECT_LE(static_cast<double>(r.soc), 1.2 * static_cast<double>(optimum) + 1e-9) << "seed " << seed;
    EXPECT_GE(r.soc, optimum);
  }
}

// Two agents that must swap ends of a dead-end corridor: no plan exists.
Instance swap_in_a_dead_end() {
  Instance in;
  in.map = swarm::test::grid_from({"....", "####"});
  in.starts = {{0, 1}, {1, 1}};
  in.goals = {{1, 1}, {0, 1}};
  return in;
}

// The same on a graph: two agents swapping the ends of the path 0 - 1 - 2 - 3 (nobody can pass).
Instance swap_on_a_path_graph() {
  Instance in;
  in.graph = Graph(4, {{0, 1}, {1, 2}, {2, 3}});
  in.starts = {vertex_cell(0), vertex_cell(3)};
  in.goals = {vertex_cell(3), vertex_cell(0)};
  return in;
}

TEST(MapfSolvers, AnUnsolvableInstanceEndsWithinItsLimit) {
  for (const Instance& in : {swap_in_a_dead_end(), swap_on_a_path_graph()}) {
    const std::string what = in.graph ? "graph" : "grid";
    EXPECT_EQ(feasibility_problem(in), "") << what;  // connected: the cheap test cannot tell
    for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs}) {
      const Result r = solve(in, config(k), StopCondition::after(0.2));
      EXPECT_TRUE(r.status == Status::Timeout || r.status == Status::Infeasible) << what << " " << to_string(r.status);
      EXPECT_LT(r.seconds, 0.2 + 0.15) << what << " " << to_string(k);
    }
    // LaCAM explores every configuration of this small instance and proves it.
    const Result r = solve(in, config(SolverKind::Lacam), StopCondition::after(5));
    EXPECT_EQ(r.status, Status::Infeasible) << what << ": " << r.message;
    EXPECT_LT(r.seconds, 1.0) << what;
  }
}

TEST(MapfSolvers, AnUnreachableGoalIsInfeasibleAtOnce) {
  Instance in;
  in.map = swarm::test::grid_from({"..#..", "..#.."});
  in.starts = {{0, 0}};
  in.goals = {{4, 0}};
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
    const Result r = solve(in, config(k), StopCondition::after(5));
    EXPECT_EQ(r.status, Status::Infeasible);
    EXPECT_NE(r.message.find("cannot be reached"), std::string::npos);
  }
}

TEST(MapfSolvers, BadInputIsInvalidInstance) {
  Instance in;
  in.map = swarm::test::grid_from({"....", "...."});
  in.starts = {{0, 0}, {0, 0}};
  in.goals = {{3, 0}, {3, 1}};
  const Result r = solve(in, config(SolverKind::Cbs), StopCondition::after(1));
  EXPECT_EQ(r.status, Status::InvalidInstance);
  EXPECT_NE(r.message.find("share the start"), std::string::npos);
}

TEST(MapfSolvers, ReservedPathsAreRespected) {
  // A reserved robot walks down the middle column while the agent crosses it left to right.
  Instance in;
  in.map = swarm::test::grid_from({".....", ".....", "....."});
  in.starts = {{0, 1}};
  in.goals = {{4, 1}};
  in.reserved = {{{2, 2}, {2, 1}, {2, 0}}, {{3, 0}, {3, 1}, {3, 1}, {3, 1}, {3, 2}}};
  const Instance on_graph = graph_instance(in);
  const InstanceGraph g(in);
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs}) {
    const Result r = solve(in, config(k), StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved) << to_string(k) << ": " << r.message;
    const ValidationReport v = validate(in, r.paths);
    EXPECT_TRUE(v.ok()) << v.summary();
    EXPECT_GE(r.soc, 4);
    // The graph form carries the reserved paths over: the same plan, vertex for cell.
    const Result rg = solve(on_graph, config(k), StopCondition::after(5));
    ASSERT_EQ(rg.status, Status::Solved) << to_string(k) << ": " << rg.message;
    ASSERT_EQ(rg.paths.size(), 1u);
    Path cells;
    for (const Cell c : rg.paths[0]) cells.push_back(g.cell(c.x));
    EXPECT_EQ(cells, r.paths[0]) << to_string(k);
  }
  // Without reservations the straight line (cost 4) would cross both robots.
  EXPECT_FALSE(validate(in, {{{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}}}).ok());
  const Result lacam = solve(in, config(SolverKind::Lacam), StopCondition::after(1));
  EXPECT_EQ(lacam.status, Status::Unsupported);
  EXPECT_NE(lacam.message.find("reserved"), std::string::npos);
}

TEST(MapfSolvers, AnAgentAlreadyOnItsGoalCostsNothing) {
  Instance in;
  in.map = swarm::test::grid_from({"....", "...."});
  in.starts = {{1, 0}, {0, 1}};
  in.goals = {{1, 0}, {3, 1}};
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
    const Result r = solve(in, config(k), StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved) << to_string(k);
    EXPECT_EQ(r.soc, 3) << to_string(k);
  }
}

TEST(MapfSolvers, AreDeterministic) {
  const OccupancyGrid map = swarm::test::grid_from({"........", "..##....", "......#.", ".#......", "........"});
  const Instance in = *random_instance(map, 8, 7);
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
    SolverConfig c = config(k);
    c.lacam.seed = 3;
    const Result a = solve(in, c, StopCondition::after(5));
    const Result b = solve(in, c, StopCondition::after(5));
    ASSERT_EQ(a.status, Status::Solved) << to_string(k);
    EXPECT_EQ(a.paths, b.paths) << to_string(k);
  }
}

// Every solver on the MovingAI maps (the first agents of scenario 1): valid plans, and CBS and
// ECBS never cost less than the lower bound.
class MovingAi : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(MovingAi, EverySolversPlanIsValid) {
  const std::string dir = swarm::test::benchmarks_dir() + "/movingai/";
  const std::string name = GetParam().first;
  const OccupancyGrid map = swarm::planner::load_movingai_map(dir + name + ".map");
  const Instance in = instance_from_scen(map, load_movingai_scen(dir + name + "-random-1.scen"), GetParam().second, name + ".map");
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
    const Result r = solve(in, config(k, 1.2), StopCondition::after(2));
    ASSERT_EQ(r.status, Status::Solved) << name << " " << to_string(k);
    const ValidationReport v = validate(in, r.paths);
    EXPECT_TRUE(v.ok()) << name << " " << to_string(k) << ": " << v.summary();
    EXPECT_GE(r.soc, r.lower_bound);
    if (k == SolverKind::Ecbs) EXPECT_LE(static_cast<double>(r.soc), 1.2 * static_cast<double>(r.lower_bound) * 1.2);
  }
}

INSTANTIATE_TEST_SUITE_P(Maps, MovingAi,
                         ::testing::Values(std::pair{"random-32-32-20", 15}, std::pair{"room-32-32-4", 10},
                                           std::pair{"maze-32-32-2", 6}, std::pair{"warehouse-10-20-10-2-1", 10},
                                           std::pair{"den520d", 10}),
                         [](const auto& info) {
                           std::string n = info.param.first;
                           for (char& ch : n) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return n;
                         });

// Our solvers on the paper's world (its rules: stops only in passage middles, agents leave at
// their goals): valid plans.
TEST(MapfSolvers, RunOnThePapersWorld) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Instance in = random_warehouse_instance(5, 8, 10, seed);
    for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
      const Result r = solve(in, config(k), StopCondition::after(5));
      ASSERT_EQ(r.status, Status::Solved) << to_string(k) << " seed " << seed << ": " << r.message;
      EXPECT_TRUE(validate(in, r.paths).ok()) << validate(in, r.paths).summary();
      EXPECT_GE(r.soc, r.lower_bound);
    }
  }
}

// The paper's rule for a timed-out CBS: the last CT node explored, with its collisions.
TEST(MapfSolvers, TimedOutCbsReturnsAPlanWithItsCollisions) {
  const Instance in = random_warehouse_instance(5, 8, 30, 4);
  SolverConfig c = config(SolverKind::Cbs);
  c.cbs.timeout_plan = TimeoutPlan::LastExpanded;
  const Result r = solve(in, c, StopCondition::after(0.05));
  if (r.status == Status::Timeout) {
    ASSERT_EQ(r.paths.size(), 30u);
    EXPECT_EQ(r.conflicts, static_cast<int>(validate(in, r.paths).conflicts.size()));
    EXPECT_GT(r.conflicts, 0);
    EXPECT_TRUE(validate(in, r.paths).problems.empty());
  } else {
    EXPECT_EQ(r.status, Status::Solved);
  }
  EXPECT_LT(r.seconds, 0.05 + 0.15);
}

// A timed-out LaCAM returns its best plan too: the way to the configuration nearest the goals,
// then every agent straight on to its goal; legal moves, every goal reached, conflicts counted.
TEST(MapfSolvers, TimedOutLacamReturnsItsBestPlanWithItsConflicts) {
  const Instance in = random_warehouse_instance(10, 10, 100, 3);
  const Result r = solve(in, config(SolverKind::Lacam), StopCondition::after(0.0));
  ASSERT_EQ(r.status, Status::Timeout) << r.message;
  ASSERT_EQ(r.paths.size(), 100u);
  const ValidationReport v = validate(in, r.paths);
  EXPECT_TRUE(v.problems.empty()) << v.summary();
  EXPECT_EQ(r.conflicts, static_cast<int>(v.conflicts.size()));
  for (int a = 0; a < in.agents(); ++a) {
    ASSERT_FALSE(r.paths[static_cast<std::size_t>(a)].empty());
    EXPECT_EQ(r.paths[static_cast<std::size_t>(a)].back(), in.goals[static_cast<std::size_t>(a)]) << "agent " << a;
  }
  EXPECT_NE(r.message.find("of 100 agents on their goals"), std::string::npos) << r.message;
}

}  // namespace
