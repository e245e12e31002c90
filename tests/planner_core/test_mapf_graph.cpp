// MAPF on general graphs (planner/mapf/graph.hpp, instance.hpp's graph instances): the graph's
// adjacency, the grid's graph, check_instance and the validator on graph input, every solver on
// small graphs whose optimum is worked out by hand (or by brute force), and grid instances that
// give the same plans as their graph form. (An unsolvable graph that ends within its limit is in
// test_mapf_solvers.cpp, beside its grid twin.)
#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <vector>

#include "mapf_brute_force.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm/planner/mapf/validate.hpp"
#include "swarm/planner/mapf/warehouse.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/data.hpp"
#include "swarm_test/text.hpp"

namespace {

using swarm::planner::Cell;
using swarm::planner::OccupancyGrid;
using swarm::test::brute_force_soc;
using swarm::test::contains;
using namespace swarm::planner::mapf;

SolverConfig config(SolverKind kind, double w = 1.5) {
  SolverConfig c;
  c.kind = kind;
  c.ecbs.w = w;
  return c;
}

Instance on_graph(Graph graph, const std::vector<std::pair<int, int>>& agents) {
  Instance in;
  in.graph = std::move(graph);
  for (const auto& [s, g] : agents) {
    in.starts.push_back(vertex_cell(s));
    in.goals.push_back(vertex_cell(g));
  }
  return in;
}

std::vector<int> list(std::span<const int> s) { return {s.begin(), s.end()}; }

// A ring of 6 with the chord 0 -- 3:
//     1 --- 2
//    /       \   (edges 0-1, 1-2, 2-3, 3-4, 4-5, 5-0
//   0 ------- 3    and the chord 0-3)
//    \       /
//     5 --- 4
Graph ring_with_chord() { return Graph(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {0, 3}}); }

// A path 0 - 1 - 2 - 3 with a side branch 1 - 4:
//       4
//       |
//   0 - 1 - 2 - 3
Graph path_with_branch() { return Graph(5, {{0, 1}, {1, 2}, {2, 3}, {1, 4}}); }

TEST(MapfGraph, ListsNeighboursInEdgeOrder) {
  const Graph g = ring_with_chord();
  EXPECT_EQ(g.vertices(), 6);
  EXPECT_EQ(list(g.neighbours(0)), (std::vector<int>{1, 5, 3}));
  EXPECT_EQ(list(g.neighbours(3)), (std::vector<int>{2, 4, 0}));
  EXPECT_EQ(g.degree(1), 2);
  EXPECT_TRUE(g.adjacent(0, 3));
  EXPECT_TRUE(g.adjacent(3, 0));
  EXPECT_FALSE(g.adjacent(1, 4));
  EXPECT_FALSE(g.adjacent(0, 6));
  // Every move u -> v has its own index in 0 .. 2E - 1.
  std::vector<int> arcs;
  for (int u = 0; u < g.vertices(); ++u) {
    for (int v : g.neighbours(u)) arcs.push_back(g.arc(u, v));
  }
  std::sort(arcs.begin(), arcs.end());
  for (int k = 0; k < 14; ++k) EXPECT_EQ(arcs[static_cast<std::size_t>(k)], k);
  EXPECT_EQ(g.arc(1, 4), -1);
  EXPECT_TRUE(check_graph(g).empty());
}

TEST(MapfGraph, KeepsBadEdgesOutOfTheAdjacencyAndReportsThem) {
  const Graph g(3, {{0, 1}, {1, 1}, {2, 5}, {1, 0}, {2, -1}}, {{0, 0}, {1, 0}});
  EXPECT_EQ(list(g.neighbours(1)), (std::vector<int>{0}));
  EXPECT_EQ(g.degree(2), 0);
  const std::vector<std::string> p = check_graph(g);
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0], "edge 1 (1 -- 1) is a self loop");
  EXPECT_EQ(p[1], "edge 2 (2 -- 5): vertex 5 is not in the graph (vertices 0..2)");
  EXPECT_EQ(p[2], "edge 3 (1 -- 0) repeats edge 0");
  EXPECT_EQ(p[3], "edge 4 (2 -- -1): vertex -1 is not in the graph (vertices 0..2)");
  EXPECT_EQ(p[4], "2 positions for 3 vertices (give one per vertex, or none)");
}

// A 3 x 2 grid with one wall: 5 free cells, numbered row by row from y = 0, each listing its
// neighbours in motion.hpp's order (+x, -x, +y, -y).
TEST(MapfGraph, AGridsGraphHasAVertexPerFreeCell) {
  Instance in;
  in.map = swarm::test::grid_from({
      "...",  // y = 1: vertices 2, 3, 4
      ".#.",  // y = 0: vertices 0, 1
  });
  const InstanceGraph g(in);
  ASSERT_EQ(g.vertices(), 5);
  EXPECT_TRUE(g.on_grid());
  EXPECT_EQ(g.vertex({0, 0}), 0);
  EXPECT_EQ(g.vertex({2, 0}), 1);
  EXPECT_EQ(g.vertex({1, 0}), -1);  // the wall
  EXPECT_EQ(g.vertex({3, 0}), -1);  // outside
  EXPECT_EQ(g.vertex({1, 1}), 3);
  EXPECT_EQ(g.cell(3), (Cell{1, 1}));
  EXPECT_EQ(list(g.graph().neighbours(3)), (std::vector<int>{4, 2}));     // +x, -x (-y is the wall)
  EXPECT_EQ(list(g.graph().neighbours(0)), (std::vector<int>{2}));        // +y
  EXPECT_EQ(list(g.graph().neighbours(4)), (std::vector<int>{3, 1}));     // -x, -y
  EXPECT_EQ(g.graph().positions()[4], (Position{2, 1}));
  EXPECT_TRUE(check_graph(g.graph()).empty());

  in.starts = {{0, 0}};
  in.goals = {{2, 0}};
  const Instance as_graph = graph_instance(in);
  ASSERT_TRUE(as_graph.graph.has_value());
  EXPECT_EQ(*as_graph.graph, g.graph());
  EXPECT_EQ(as_graph.starts, (std::vector<Cell>{vertex_cell(0)}));
  EXPECT_EQ(as_graph.goals, (std::vector<Cell>{vertex_cell(1)}));
  EXPECT_EQ(lower_bound(as_graph), 4);  // around the wall
  EXPECT_EQ(lower_bound(in), 4);
}

TEST(MapfGraph, DistancesFollowTheEdges) {
  const Graph g = ring_with_chord();
  const DistanceTable from_0(g, 0);
  const std::vector<int> expected = {0, 1, 2, 1, 2, 1};
  for (int v = 0; v < 6; ++v) EXPECT_EQ(from_0.at(v), expected[static_cast<std::size_t>(v)]) << "vertex " << v;
  const DistanceTable none(g, 9);
  EXPECT_EQ(none.at(0), DistanceTable::kUnreachable);
}

// Ring with the chord; agent 0 goes 0 -> 3, agent 1 goes 3 -> 0: the lower bound is 1 + 1 (both
// along the chord), but they cannot swap on it. By hand: agent 0 takes the chord at t = 1 while
// agent 1 leaves 3 for 4 (following, not swapping) and goes round 4, 5, 0: 1 + 3 = 4. Nothing
// cheaper: if one agent arrives at t = 1 it sits on its goal from then on, and the other, which
// must leave that vertex at once, needs 3 steps round the ring; if neither arrives at t = 1, each
// costs >= 2, and 2 + 2 is impossible (0 and 3 have no common neighbour, so a cost of 2 means
// waiting a step and then taking the chord: the other is still on that end then, or they swap).
TEST(MapfGraph, RingWithAChordHasOptimumFour) {
  const Instance in = on_graph(ring_with_chord(), {{0, 3}, {3, 0}});
  EXPECT_TRUE(check_instance(in).empty());
  EXPECT_EQ(lower_bound(in), 2);
  EXPECT_EQ(brute_force_soc(in), 4);
  const Result cbs = solve(in, config(SolverKind::Cbs), StopCondition::after(5));
  ASSERT_EQ(cbs.status, Status::Solved) << cbs.message;
  EXPECT_EQ(cbs.soc, 4);
  EXPECT_EQ(cbs.makespan, 3);
  EXPECT_EQ(cbs.lower_bound, 2);
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
    const Result r = solve(in, config(k, 1.5), StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved) << to_string(k) << ": " << r.message;
    EXPECT_TRUE(validate(in, r.paths).ok()) << to_string(k) << ": " << validate(in, r.paths).summary();
    if (k == SolverKind::Ecbs) {
      EXPECT_LE(r.soc, 6) << "1.5 x 4";
    }
  }
}

// Path with a branch; agent 0 goes 0 -> 3, agent 1 goes 3 -> 0: on the path they cannot pass each
// other, so one must wait in the branch 4 while the other goes by, which costs it at least 2 more
// steps (1 -> 4 -> 1): optimum >= 3 + 3 + 2 = 8. Agent 0 is nearer the branch: 0, 1, 4 (t = 2)
// while agent 1 goes 3, 2, 1 (t = 2), 0 (t = 3); then agent 0 goes 1, 2, 3 (t = 5): 5 + 3 = 8.
// (Agent 1 stepping aside instead costs 10: agent 0 must wait at 0 until 1 is in the branch.)
TEST(MapfGraph, PathWithABranchHasOptimumEight) {
  const Instance in = on_graph(path_with_branch(), {{0, 3}, {3, 0}});
  EXPECT_EQ(lower_bound(in), 6);
  EXPECT_EQ(brute_force_soc(in), 8);
  const Result cbs = solve(in, config(SolverKind::Cbs), StopCondition::after(5));
  ASSERT_EQ(cbs.status, Status::Solved) << cbs.message;
  EXPECT_EQ(cbs.soc, 8);
  EXPECT_EQ(cbs.paths[0], (Path{vertex_cell(0), vertex_cell(1), vertex_cell(4), vertex_cell(1), vertex_cell(2), vertex_cell(3)}));
  EXPECT_EQ(cbs.paths[1], (Path{vertex_cell(3), vertex_cell(2), vertex_cell(1), vertex_cell(0)}));
  for (SolverKind k : {SolverKind::Ecbs, SolverKind::Lacam}) {
    const Result r = solve(in, config(k, 1.2), StopCondition::after(5));
    ASSERT_EQ(r.status, Status::Solved) << to_string(k) << ": " << r.message;
    EXPECT_TRUE(validate(in, r.paths).ok()) << to_string(k) << ": " << validate(in, r.paths).summary();
    if (k == SolverKind::Ecbs) {
      EXPECT_LE(static_cast<double>(r.soc), 1.2 * 8 + 1e-9);
    }
  }
}

// A connected random graph: a random tree on `vertices` plus `extra` random edges.
Graph random_graph(int vertices, int extra, swarm::planner::Rng& rng) {
  std::vector<Edge> edges;
  const auto has = [&](int u, int v) {
    return std::any_of(edges.begin(), edges.end(), [&](const Edge& e) { return (e.u == u && e.v == v) || (e.u == v && e.v == u); });
  };
  for (int v = 1; v < vertices; ++v) edges.push_back({static_cast<int>(rng.below(static_cast<std::uint64_t>(v))), v});
  while (extra > 0) {
    const int u = rng.uniform_int(0, vertices - 1), v = rng.uniform_int(0, vertices - 1);
    if (u == v || has(u, v)) continue;
    edges.push_back({u, v});
    --extra;
  }
  return Graph(vertices, std::move(edges));
}

// Small random graphs (8 vertices, a tree and 0 to 2 more edges, 4 agents): where a plan exists,
// CBS finds the brute force's optimum (up to 21 against a lower bound of 10), ECBS stays within w
// of it and LaCAM solves it; where none exists (2 of the 16, both on trees), LaCAM proves it.
TEST(MapfGraph, SolversMatchTheBruteForceOnRandomGraphs) {
  int solvable = 0, unsolvable = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    swarm::planner::Rng rng(seed);
    const Graph g = random_graph(8, static_cast<int>(seed % 3), rng);
    std::vector<int> order = {0, 1, 2, 3, 4, 5, 6, 7};
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
    std::vector<int> goals = order;
    for (std::size_t i = goals.size(); i > 1; --i) std::swap(goals[i - 1], goals[rng.below(i)]);
    const Instance in =
        on_graph(g, {{order[0], goals[0]}, {order[1], goals[1]}, {order[2], goals[2]}, {order[3], goals[3]}});
    const long long optimum = brute_force_soc(in);
    if (optimum < 0) {
      ++unsolvable;
      const Result r = solve(in, config(SolverKind::Lacam), StopCondition::after(5));
      EXPECT_EQ(r.status, Status::Infeasible) << "seed " << seed << ": " << r.message;
      continue;
    }
    ++solvable;
    const Result cbs = solve(in, config(SolverKind::Cbs), StopCondition::after(5));
    ASSERT_EQ(cbs.status, Status::Solved) << "seed " << seed << ": " << cbs.message;
    EXPECT_EQ(cbs.soc, optimum) << "seed " << seed;
    const Result ecbs = solve(in, config(SolverKind::Ecbs, 1.3), StopCondition::after(5));
    ASSERT_EQ(ecbs.status, Status::Solved) << "seed " << seed;
    EXPECT_LE(static_cast<double>(ecbs.soc), 1.3 * static_cast<double>(optimum) + 1e-9) << "seed " << seed;
    const Result lacam = solve(in, config(SolverKind::Lacam), StopCondition::after(5));
    ASSERT_EQ(lacam.status, Status::Solved) << "seed " << seed;
    EXPECT_GE(lacam.soc, optimum) << "seed " << seed;
    for (const Result* r : {&cbs, &ecbs, &lacam}) EXPECT_TRUE(validate(in, r->paths).ok()) << "seed " << seed;
  }
  EXPECT_EQ(solvable, 14);
  EXPECT_EQ(unsolvable, 2);
}

TEST(MapfGraph, AGoalInAnotherComponentIsInfeasibleAtOnce) {
  const Instance in = on_graph(Graph(4, {{0, 1}, {2, 3}}), {{0, 3}});
  EXPECT_EQ(feasibility_problem(in), "agent 0: goal vertex 3 cannot be reached from start vertex 0");
  EXPECT_EQ(lower_bound(in), kNoCost);
  for (SolverKind k : {SolverKind::Cbs, SolverKind::Ecbs, SolverKind::Lacam}) {
    const Result r = solve(in, config(k), StopCondition::after(5));
    EXPECT_EQ(r.status, Status::Infeasible) << to_string(k);
  }
}

TEST(MapfGraph, CheckInstanceNamesBadGraphInput) {
  Instance in = on_graph(Graph(4, {{0, 1}, {1, 1}, {1, 7}}), {{0, 3}, {0, 2}, {9, 1}});
  in.starts.push_back({1, 1});
  in.goals.push_back(vertex_cell(1));
  in.rules = Rules::paper_warehouse();
  const std::vector<std::string> p = check_instance(in);
  const auto has = [&](const std::string& text) {
    return std::any_of(p.begin(), p.end(), [&](const std::string& s) { return contains(s, text); });
  };
  EXPECT_TRUE(has("graph: edge 1 (1 -- 1) is a self loop"));
  EXPECT_TRUE(has("graph: edge 2 (1 -- 7): vertex 7 is not in the graph (vertices 0..3)"));
  EXPECT_TRUE(has("agents 0 and 1 share the start vertex 0"));
  EXPECT_TRUE(has("agent 2: start vertex 9 is not in the 4-vertex graph"));
  EXPECT_TRUE(has("agents 2 and 3 share the goal vertex 1"));
  EXPECT_TRUE(has("agent 3: start (1, 1) names no vertex"));
  EXPECT_TRUE(has("the paper's rules (stops only in passage middles) need a warehouse grid"));
  const Result r = solve(in, config(SolverKind::Lacam), StopCondition::after(1));
  EXPECT_EQ(r.status, Status::InvalidInstance);
}

TEST(MapfGraph, TheValidatorUsesTheGraphsEdges) {
  const Instance in = on_graph(ring_with_chord(), {{0, 3}, {3, 0}});
  const auto path = [](std::vector<int> vs) {
    Path p;
    for (int v : vs) p.push_back(vertex_cell(v));
    return p;
  };
  // The optimum by hand (RingWithAChordHasOptimumFour).
  const ValidationReport good = validate(in, {path({0, 3}), path({3, 4, 5, 0})});
  EXPECT_TRUE(good.ok()) << good.summary();
  EXPECT_EQ(sum_of_costs(in, {path({0, 3}), path({3, 4, 5, 0})}), 4);
  // Both along the chord in the same step: one swap conflict.
  const ValidationReport swap = validate(in, {path({0, 3}), path({3, 0})});
  ASSERT_EQ(swap.conflicts.size(), 1u) << swap.summary();
  EXPECT_EQ(swap.conflicts[0].kind, ConflictKind::Swap);
  EXPECT_EQ(swap.conflicts[0].cell, vertex_cell(0));
  EXPECT_EQ(swap.conflicts[0].other, vertex_cell(3));
  EXPECT_EQ(swap.conflicts[0].time, 1);
  EXPECT_TRUE(swap.problems.empty());
  // Agent 1 waits on 4 at t = 2 when agent 0 comes round the other way: one vertex conflict.
  const ValidationReport meet = validate(in, {path({0, 5, 4, 3}), path({3, 4, 4, 5, 0})});
  ASSERT_EQ(meet.conflicts.size(), 1u) << meet.summary();
  EXPECT_EQ(meet.conflicts[0].kind, ConflictKind::Vertex);
  EXPECT_EQ(meet.conflicts[0].cell, vertex_cell(4));
  EXPECT_EQ(meet.conflicts[0].time, 2);
  // 1 -> 4 is no edge of the ring; (2, 1) names no vertex.
  const ValidationReport jump = validate(in, {path({0, 1, 4, 3}), Path{vertex_cell(3), {2, 1}, vertex_cell(0)}});
  ASSERT_EQ(jump.problems.size(), 3u) << jump.summary();
  EXPECT_EQ(jump.problems[0].agent, 0);
  EXPECT_EQ(jump.problems[0].time, 2);
  EXPECT_EQ(jump.problems[0].what, "step vertex 1 -> vertex 4: not adjacent");
  EXPECT_EQ(jump.problems[1].agent, 1);
  EXPECT_EQ(jump.problems[1].what, "step vertex 3 -> (2, 1): (2, 1) names no vertex");
  EXPECT_EQ(jump.problems[2].what, "step (2, 1) -> vertex 0: (2, 1) names no vertex");
}

TEST(MapfGraph, TheGaDoesNotTakeAGraph) {
  const Instance in = on_graph(ring_with_chord(), {{0, 2}});
  for (SolverKind k : {SolverKind::Ga, SolverKind::Ga1}) {
    const Result r = solve(in, config(k), StopCondition::after(1));
    EXPECT_EQ(r.status, Status::Unsupported) << to_string(k);
    EXPECT_TRUE(contains(r.message, "graph instance")) << r.message;
  }
  // The paper's world as a graph loses its rules' meaning: check_instance refuses them.
  const Instance paper = graph_instance(random_warehouse_instance(3, 3, 4, 1));
  EXPECT_EQ(solve(paper, config(SolverKind::Ga), StopCondition::after(1)).status, Status::InvalidInstance);
}

// A grid instance and its graph form (graph_instance) give the same result, vertex for cell: the
// grid's graph lists neighbours in the grid's order, so every tie is broken the same way.
std::vector<Path> as_cells(const Instance& grid, const std::vector<Path>& graph_paths) {
  const InstanceGraph g(grid);
  std::vector<Path> out;
  for (const Path& p : graph_paths) {
    Path& q = out.emplace_back();
    for (const Cell c : p) q.push_back(g.cell(c.x));
  }
  return out;
}

void expect_same_result(const Instance& grid, const SolverConfig& cfg, const std::string& what) {
  const Instance graph = graph_instance(grid);
  const Result a = solve(grid, cfg, StopCondition::after(10));
  const Result b = solve(graph, cfg, StopCondition::after(10));
  ASSERT_EQ(a.status, Status::Solved) << what << ": " << a.message;
  EXPECT_EQ(b.status, a.status) << what << ": " << b.message;
  EXPECT_EQ(b.soc, a.soc) << what;
  EXPECT_EQ(b.makespan, a.makespan) << what;
  EXPECT_EQ(b.lower_bound, a.lower_bound) << what;
  EXPECT_EQ(b.stats.low_level_expanded, a.stats.low_level_expanded) << what;
  EXPECT_EQ(as_cells(grid, b.paths), a.paths) << what;
  EXPECT_TRUE(validate(graph, b.paths).ok()) << what;
}

struct GridCase {
  const char* map;
  SolverKind kind;
  int agents;
};

class GridAsGraph : public ::testing::TestWithParam<GridCase> {};

TEST_P(GridAsGraph, GivesTheSamePlans) {
  const std::string dir = swarm::test::benchmarks_dir() + "/movingai/";
  const GridCase c = GetParam();
  const OccupancyGrid map = swarm::planner::load_movingai_map(dir + c.map + ".map");
  for (int s = 1; s <= 2; ++s) {
    const Instance in = instance_from_scen(map, load_movingai_scen(dir + c.map + "-random-" + std::to_string(s) + ".scen"),
                                           c.agents, std::string(c.map) + ".map");
    expect_same_result(in, config(c.kind, 1.2), std::string(c.map) + " scenario " + std::to_string(s));
  }
}

INSTANTIATE_TEST_SUITE_P(MovingAi, GridAsGraph,
                         ::testing::Values(GridCase{"random-32-32-20", SolverKind::Cbs, 25},
                                           GridCase{"random-32-32-20", SolverKind::Ecbs, 80},
                                           GridCase{"random-32-32-20", SolverKind::Lacam, 300},
                                           GridCase{"room-32-32-4", SolverKind::Cbs, 12},
                                           GridCase{"maze-32-32-2", SolverKind::Lacam, 60},
                                           GridCase{"warehouse-10-20-10-2-1", SolverKind::Ecbs, 60}),
                         [](const auto& info) {
                           std::string n = std::string(info.param.map) + "_" + to_string(info.param.kind);
                           for (char& ch : n) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return n;
                         });

}  // namespace
