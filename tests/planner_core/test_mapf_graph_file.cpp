// MAPF graph instance files (planner/mapf/graph_file.hpp): a file read back as the graph and agents
// it says, written and read again unchanged, and every malformed file refused with its file, line
// and what was expected.
#include <gtest/gtest.h>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/graph_file.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm_test/data.hpp"
#include "swarm_test/files.hpp"
#include "swarm_test/text.hpp"

namespace {

using swarm::planner::Cell;
using swarm::planner::MapFileError;
using namespace swarm::planner::mapf;

// The path 0 - 1 - 2 - 3 with the side branch 1 - 4 (test_mapf_graph.cpp: optimum 8).
constexpr const char* kBranch = R"(# a path with a side branch
vertices 5

position 0 0 0
position 1 1 0
position 2 2 0
position 3 3 0
position 4 1 1.5   # the branch, drawn above vertex 1
edge 0 1
edge	1 2
edge 2 3
edge 1 4
agent 0 3
agent 3 0
)";

TEST(MapfGraphFile, ReadsTheGraphAndTheAgents) {
  swarm::test::TempDir tmp;
  const std::string path = tmp.file("branch.graph");
  swarm::test::spit(path, kBranch);
  const Instance in = load_graph_instance(path);
  ASSERT_TRUE(in.graph.has_value());
  const Graph& g = *in.graph;
  EXPECT_EQ(g.vertices(), 5);
  EXPECT_EQ(g.edges(), (std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}, {1, 4}}));
  ASSERT_EQ(g.positions().size(), 5u);
  EXPECT_EQ(g.positions()[4], (Position{1, 1.5}));
  EXPECT_EQ(in.starts, (std::vector<Cell>{vertex_cell(0), vertex_cell(3)}));
  EXPECT_EQ(in.goals, (std::vector<Cell>{vertex_cell(3), vertex_cell(0)}));
  EXPECT_EQ(in.rules, Rules::standard());
  EXPECT_TRUE(check_instance(in).empty());
  const Result r = solve(in, SolverConfig{}, StopCondition::after(5));
  ASSERT_EQ(r.status, Status::Solved) << r.message;
  EXPECT_EQ(r.soc, 8);
}

TEST(MapfGraphFile, WritesWhatItReads) {
  swarm::test::TempDir tmp;
  swarm::test::spit(tmp.file("a.graph"), kBranch);
  const Instance a = load_graph_instance(tmp.file("a.graph"));
  save_graph_instance(tmp.file("b.graph"), a);
  const Instance b = load_graph_instance(tmp.file("b.graph"));
  EXPECT_EQ(*b.graph, *a.graph);
  EXPECT_EQ(b.graph->edges(), a.graph->edges());
  EXPECT_EQ(b.starts, a.starts);
  EXPECT_EQ(b.goals, a.goals);
  // Without positions, none are written.
  swarm::test::spit(tmp.file("c.graph"), "vertices 2\nedge 0 1\nagent 0 1\n");
  save_graph_instance(tmp.file("d.graph"), load_graph_instance(tmp.file("c.graph")));
  EXPECT_FALSE(swarm::test::contains(swarm::test::slurp(tmp.file("d.graph")), "position"));
  EXPECT_TRUE(load_graph_instance(tmp.file("d.graph")).graph->positions().empty());
}

// A MovingAI instance written as a graph: a vertex per free cell (random-32-32-20 has 819), the
// cells as positions, the same optimum (CBS: the sum of costs does not depend on tie-breaking).
TEST(MapfGraphFile, WritesAGridInstanceAsItsGraph) {
  const std::string dir = swarm::test::benchmarks_dir() + "/movingai/";
  const auto map = swarm::planner::load_movingai_map(dir + "random-32-32-20.map");
  const Instance grid = instance_from_scen(map, load_movingai_scen(dir + "random-32-32-20-random-1.scen"), 20);
  swarm::test::TempDir tmp;
  save_graph_instance(tmp.file("r.graph"), grid);
  const Instance graph = load_graph_instance(tmp.file("r.graph"));
  EXPECT_EQ(graph.graph->vertices(), 819);
  const InstanceGraph g(grid);
  EXPECT_EQ(graph.graph->edges(), g.graph().edges());
  EXPECT_EQ(graph.graph->positions()[static_cast<std::size_t>(g.vertex(grid.starts[0]))],
            (Position{static_cast<double>(grid.starts[0].x), static_cast<double>(grid.starts[0].y)}));
  const Result a = solve(grid, SolverConfig{}, StopCondition::after(10));
  const Result b = solve(graph, SolverConfig{}, StopCondition::after(10));
  ASSERT_EQ(a.status, Status::Solved);
  ASSERT_EQ(b.status, Status::Solved) << b.message;
  EXPECT_EQ(b.soc, a.soc);
  EXPECT_EQ(b.lower_bound, a.lower_bound);
}

TEST(MapfGraphFile, RefusesMalformedFilesNamingTheLine) {
  swarm::test::TempDir tmp;
  const auto refused = [&](const std::string& text, const std::string& expected) {
    const std::string path = tmp.file("x.graph");
    swarm::test::spit(path, text);
    try {
      (void)load_graph_instance(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const MapFileError& e) {
      EXPECT_EQ(std::string(e.what()), path + expected) << text;
    }
  };
  refused("", ": empty file: expected \"vertices N\", then edge and agent lines");
  refused("# nothing\n\n", ": empty file: expected \"vertices N\", then edge and agent lines");
  refused("edge 0 1\n", ":1: expected \"vertices N\" first (got \"edge\")");
  refused("vertices\n", ":1: expected \"vertices N\" (2 words), got 1 word");
  refused("vertices six\n", ":1: the number of vertices must be an integer from 1 to 10000000 (got \"six\")");
  refused("vertices 0\n", ":1: the number of vertices must be an integer from 1 to 10000000 (got \"0\")");
  refused("vertices 99999999999\n", ":1: the number of vertices must be an integer from 1 to 10000000 (got \"99999999999\")");
  refused("vertices 3\nvertices 4\n", ":2: \"vertices\" is given again (first on line 1)");
  refused("vertices 3\n\nedge 0 3\n", ":3: edge 0 3: vertex 3 is not in the graph (vertices 0..2)");
  refused("vertices 3\nedge 0 -1\n", ":2: edge 0 -1: vertex -1 is not in the graph (vertices 0..2)");
  refused("vertices 3\nedge 0 1.5\n", ":2: edge 0 1.5: vertex ids are integers (got \"1.5\")");
  refused("vertices 3\nedge 0 1 2\n", ":2: expected \"edge U V\" (3 words), got 4 words");
  refused("vertices 3\nedge 2 2\n", ":2: edge 2 2 is a self loop");
  refused("vertices 3\nedge 0 1\nedge 1 0\n", ":3: edge 1 0 repeats line 2");
  refused("vertices 3\nposition 0 1\n", ":2: expected \"position V X Y\" (4 words), got 3 words");
  refused("vertices 3\nposition 0 nan 1\n", ":2: position of vertex 0: x must be a number (got \"nan\")");
  refused("vertices 3\nposition 0 1 y\n", ":2: position of vertex 0: y must be a number (got \"y\")");
  refused("vertices 3\nposition 1 0 0\nposition 1 2 2\n", ":3: position of vertex 1 is already given on line 2");
  refused("vertices 3\nposition 0 0 0\nposition 2 1 1\nagent 0 1\n",
          ": positions are given for 2 of 3 vertices (vertex 1 has none): give one per vertex, or none");
  refused("vertices 3\nagent 0\n", ":2: expected \"agent START GOAL\" (3 words), got 2 words");
  refused("vertices 3\nagent 0 5\n", ":2: agent 0 5: vertex 5 is not in the graph (vertices 0..2)");
  refused("vertices 3\nagent 0 1\nagent 0 2\n", ":3: start 0 is also the start of line 2");
  refused("vertices 3\nagent 0 1\nagent 2 1\n", ":3: goal 1 is also the goal of line 2");
  refused("vertices 3\nedge 0 1\n", ": no agents: expected at least one \"agent START GOAL\" line");
  refused("vertices 3\nvertex 0\n", ":2: unknown statement \"vertex\" (expected vertices, position, edge or agent)");
  refused("vertices 3\n\x01\x02 0 1\n", ":2: unknown statement \"\x01\x02\" (expected vertices, position, edge or agent)");
  try {
    (void)load_graph_instance(tmp.file("missing.graph"));
    ADD_FAILURE() << "a missing file was read";
  } catch (const MapFileError& e) {
    EXPECT_EQ(std::string(e.what()), tmp.file("missing.graph") + ": cannot open the graph file (check the path)");
  }
}

// Comments anywhere, blank lines, tabs, Windows line ends, and statements in any order after
// `vertices`.
TEST(MapfGraphFile, AcceptsCommentsTabsAndAnyOrder) {
  swarm::test::TempDir tmp;
  const std::string path = tmp.file("y.graph");
  swarm::test::spit(path, "  # header\r\nvertices\t3 # three\r\nagent 2 0\r\n\r\nedge 0 1\r\nedge 1 2#tight\r\n");
  const Instance in = load_graph_instance(path);
  EXPECT_EQ(in.graph->edges(), (std::vector<Edge>{{0, 1}, {1, 2}}));
  EXPECT_EQ(in.starts, (std::vector<Cell>{vertex_cell(2)}));
  EXPECT_EQ(lower_bound(in), 2);
}

}  // namespace
