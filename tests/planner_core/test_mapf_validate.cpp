// The MAPF validator and cost measures (planner/mapf/validate.hpp, instance.hpp) on hand-made
// plans: every count below is worked out by hand from the drawing.
#include <gtest/gtest.h>

#include "swarm/planner/mapf/instance.hpp"
#include "swarm/planner/mapf/validate.hpp"
#include "swarm/planner/mapf/warehouse.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace {

using swarm::planner::Cell;
using namespace swarm::planner::mapf;

Instance corridor(std::vector<Cell> starts, std::vector<Cell> goals) {
  Instance in;
  in.map = swarm::test::grid_from({
      "#####",
      ".....",  // y = 1: the corridor
      "#.###",  // y = 0: one alcove at x = 1
  });
  in.starts = std::move(starts);
  in.goals = std::move(goals);
  return in;
}

TEST(MapfValidate, AcceptsAConflictFreePlan) {
  // Agent 0 goes right along the corridor; agent 1 steps into the alcove and out of its way.
  const Instance in = corridor({{0, 1}, {1, 1}}, {{2, 1}, {1, 0}});
  const std::vector<Path> plan = {{{0, 1}, {1, 1}, {2, 1}}, {{1, 1}, {1, 0}}};
  const ValidationReport r = validate(in, plan);
  EXPECT_TRUE(r.ok()) << r.summary();
  EXPECT_EQ(sum_of_costs(in, plan), 2 + 1);
  EXPECT_EQ(makespan(in, plan), 2);
  EXPECT_EQ(lower_bound(in), 2 + 1);
}

TEST(MapfValidate, CountsOneVertexConflictPerPairAndStep) {
  // Three agents meet on the centre (1, 1) at t = 1: three pairs, three conflicts.
  Instance in;
  in.map = swarm::test::grid_from({"...", "...", "..."});
  in.starts = {{0, 1}, {2, 1}, {1, 0}};
  in.goals = {{1, 2}, {2, 1}, {1, 0}};
  const std::vector<Path> plan = {{{0, 1}, {1, 1}, {1, 2}}, {{2, 1}, {1, 1}, {2, 1}}, {{1, 0}, {1, 1}, {1, 0}}};
  const ValidationReport r = validate(in, plan);
  ASSERT_EQ(r.conflicts.size(), 3u) << r.summary();
  for (const Conflict& c : r.conflicts) {
    EXPECT_EQ(c.kind, ConflictKind::Vertex);
    EXPECT_EQ(c.time, 1);
    EXPECT_EQ(c.cell, (Cell{1, 1}));
  }
  EXPECT_TRUE(r.problems.empty());
}

TEST(MapfValidate, FindsASwapInTheCorridor) {
  const Instance in = corridor({{1, 1}, {2, 1}}, {{2, 1}, {1, 1}});
  const std::vector<Path> plan = {{{1, 1}, {2, 1}}, {{2, 1}, {1, 1}}};
  const ValidationReport r = validate(in, plan);
  ASSERT_EQ(r.conflicts.size(), 1u) << r.summary();
  EXPECT_EQ(r.conflicts[0].kind, ConflictKind::Swap);
  EXPECT_EQ(r.conflicts[0].a, 0);
  EXPECT_EQ(r.conflicts[0].b, 1);
  EXPECT_EQ(r.conflicts[0].time, 1);
  EXPECT_EQ(r.conflicts[0].cell, (Cell{1, 1}));
  EXPECT_EQ(r.conflicts[0].other, (Cell{2, 1}));
}

TEST(MapfValidate, AnAgentOnItsGoalBlocksItUnderStayButNotUnderVanish) {
  // Agent 1 arrives on (2, 1) at t = 1 and stays; agent 0 passes over it at t = 2.
  Instance in = corridor({{0, 1}, {3, 1}}, {{4, 1}, {2, 1}});
  const std::vector<Path> plan = {{{0, 1}, {0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}}, {{3, 1}, {2, 1}}};
  ValidationReport r = validate(in, plan);
  ASSERT_EQ(r.conflicts.size(), 1u) << r.summary();
  EXPECT_EQ(r.conflicts[0].time, 3);
  EXPECT_EQ(r.conflicts[0].cell, (Cell{2, 1}));
  in.rules.at_goal = GoalRule::Vanish;
  r = validate(in, plan);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(MapfValidate, ReportsIllegalSteps) {
  const Instance in = corridor({{0, 1}, {4, 1}}, {{2, 1}, {3, 1}});
  const std::vector<Path> plan = {{{0, 1}, {2, 1}},              // a jump of two cells
                                  {{4, 1}, {4, 0}, {3, 1}}};     // into the wall below
  const ValidationReport r = validate(in, plan);
  ASSERT_EQ(r.problems.size(), 3u) << r.summary();
  EXPECT_EQ(r.problems[0].agent, 0);
  EXPECT_NE(r.problems[0].what.find("not adjacent"), std::string::npos);
  EXPECT_NE(r.problems[1].what.find("blocked"), std::string::npos);
  EXPECT_NE(r.problems[2].what.find("not adjacent"), std::string::npos);  // (4,0) -> (3,1) is diagonal
}

TEST(MapfValidate, ReportsWrongEndsAndMissingPaths) {
  const Instance in = corridor({{0, 1}, {4, 1}}, {{2, 1}, {3, 1}});
  ValidationReport r = validate(in, {{{1, 1}, {2, 1}}, {{4, 1}}});
  ASSERT_EQ(r.problems.size(), 2u) << r.summary();
  EXPECT_NE(r.problems[0].what.find("not at its start"), std::string::npos);
  EXPECT_NE(r.problems[1].what.find("not at its goal"), std::string::npos);
  r = validate(in, {{{0, 1}, {1, 1}, {2, 1}}});
  EXPECT_FALSE(r.ok());
}

TEST(MapfValidate, ReservedRobotsAreAvoidedAndNamed) {
  Instance in = corridor({{0, 1}}, {{4, 1}});
  in.reserved = {{{4, 1}, {3, 1}, {2, 1}, {1, 1}, {1, 0}}};  // comes the other way, then into the alcove
  const std::vector<Path> through = {{{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}}};
  ValidationReport r = validate(in, through);
  ASSERT_FALSE(r.conflicts.empty());
  EXPECT_EQ(r.conflicts[0].b, -1);  // reserved path 0
  // Waiting at the start until the reserved robot has gone into the alcove: no conflict.
  const std::vector<Path> waits = {{{0, 1}, {0, 1}, {0, 1}, {0, 1}, {0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}}};
  r = validate(in, waits);
  EXPECT_TRUE(r.ok()) << r.summary();
  // The reserved robot stays in the alcove for ever; a goal there is infeasible.
  Instance blocked = corridor({{0, 1}}, {{1, 0}});
  blocked.reserved = in.reserved;
  EXPECT_NE(feasibility_problem(blocked), "");
}

TEST(MapfValidate, PathCostIgnoresTrailingWaitsOnTheGoal) {
  const Instance in = corridor({{0, 1}}, {{2, 1}});
  EXPECT_EQ(path_cost(in, 0, {{0, 1}, {1, 1}, {2, 1}, {2, 1}, {2, 1}}), 2);
  EXPECT_EQ(path_cost(in, 0, {{0, 1}, {1, 1}, {2, 1}, {3, 1}, {2, 1}}), 4);  // left and came back
  EXPECT_EQ(path_cost(in, 0, {{0, 1}, {1, 1}}), kNoCost);
  EXPECT_EQ(idle_steps(in, 0, {{0, 1}, {0, 1}, {1, 1}, {1, 1}, {2, 1}, {2, 1}}), 2);
}

TEST(MapfValidate, ChecksInstancesAsInput) {
  Instance in = corridor({{0, 1}, {0, 1}}, {{2, 1}, {0, 0}});
  const auto problems = check_instance(in);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("blocked"), std::string::npos);  // agent 1's goal (0, 0)
  EXPECT_NE(problems[1].find("share the start"), std::string::npos);
  in = corridor({{0, 1}}, {{9, 9}});
  EXPECT_NE(check_instance(in).at(0).find("outside"), std::string::npos);
  in = corridor({{2, 1}}, {{2, 1}});  // start == goal is fine
  EXPECT_TRUE(check_instance(in).empty());
  EXPECT_TRUE(validate(in, {{{2, 1}}}).ok());
}

// The paper's rules on the warehouse lattice: stops only in passage middles (or at the start
// before moving), 2 steps each, never turning back in a passage.
TEST(MapfValidate, PaperRulesOnTheWarehouse) {
  Instance in;
  in.map = warehouse_map(2, 3);  // 7 x 5 cells, intersections at odd (x, y)
  in.rules = Rules::paper_warehouse();
  in.starts = {{1, 1}};
  in.goals = {{5, 1}};
  ASSERT_TRUE(check_instance(in).empty());
  EXPECT_TRUE(validate(in, {{{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}}}).ok());
  // A 2-step stop in the middle (2, 1) and a 2-step stop at the start: fine.
  EXPECT_TRUE(validate(in, {{{1, 1}, {1, 1}, {1, 1}, {2, 1}, {2, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}}}).ok());
  // A 1-step stop, a stop at the intersection (3, 1) after moving, a U-turn in a passage.
  const auto one = validate(in, {{{1, 1}, {2, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}}});
  ASSERT_EQ(one.problems.size(), 1u);
  EXPECT_NE(one.problems[0].what.find("2 steps"), std::string::npos);
  const auto at_crossing = validate(in, {{{1, 1}, {2, 1}, {3, 1}, {3, 1}, {3, 1}, {4, 1}, {5, 1}}});
  ASSERT_EQ(at_crossing.problems.size(), 1u);
  EXPECT_NE(at_crossing.problems[0].what.find("intersection"), std::string::npos);
  const auto u_turn = validate(in, {{{1, 1}, {2, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}}});
  ASSERT_FALSE(u_turn.problems.empty());
  EXPECT_NE(u_turn.problems[0].what.find("turns back"), std::string::npos);
  // Starts must be intersections.
  in.starts = {{2, 1}};
  EXPECT_FALSE(check_instance(in).empty());
}

}  // namespace
