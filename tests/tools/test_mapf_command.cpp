// `swarm mapf` and `swarm experiment mapf` (tools/cli/mapf_command.hpp, tools/experiments/experiment_mapf.hpp): what
// they write, their exit statuses and the messages for bad input. No process is started.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "experiment_mapf.hpp"
#include "mapf_command.hpp"
#include "swarm_test/data.hpp"
#include "swarm_test/files.hpp"
#include "swarm_test/text.hpp"

namespace {

using swarm::test::contains;
using swarm::tools::MapfOptions;
namespace fs = std::filesystem;

struct Outcome {
  int code;
  std::string out, err;
};

Outcome run(MapfOptions o) {
  o.quiet = true;
  std::ostringstream out, err;
  const int code = swarm::tools::mapf_command(o, out, err);
  return {code, out.str(), err.str()};
}

// A 5 x 3 MovingAI map and a scenario (y counted from the top, as the format says).
struct Files {
  swarm::test::TempDir tmp;
  std::string map = tmp.file("tiny.map");
  std::string scen = tmp.file("tiny.scen");
  Files() {
    swarm::test::spit(map, "type octile\nheight 3\nwidth 5\nmap\n.....\n.@@..\n.....\n");
    swarm::test::spit(scen, "version 1\n0\ttiny.map\t5\t3\t0\t0\t4\t2\t6\n0\ttiny.map\t5\t3\t4\t2\t0\t0\t6\n");
  }
};

// A graph file (planner/mapf/graph_file.hpp), no positions: the path 0 - 1 - 2 - 3 with the side
// branch 1 - 4, two agents swapping its ends. Optimum 8 (test_mapf_graph.cpp works it out): agent
// 0 waits in the branch while agent 1 goes by.
constexpr const char* kBranchGraph = "vertices 5\nedge 0 1\nedge 1 2\nedge 2 3\nedge 1 4\nagent 0 3\nagent 3 0\n";

TEST(MapfCommand, SolvesAScenarioAndWritesItsFiles) {
  Files f;
  MapfOptions o;
  o.map = f.map;
  o.scen = f.scen;
  o.agents = 2;
  o.out_dir = f.tmp.file("out");
  const Outcome r = run(o);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"result.json", "paths.png", "animation.html", "instance.scen", "map.map"}) {
    EXPECT_TRUE(fs::exists(fs::path(o.out_dir) / name)) << name;
  }
  const auto j = nlohmann::json::parse(swarm::test::slurp(o.out_dir + "/result.json"));
  EXPECT_EQ(j["status"], "solved");
  EXPECT_EQ(j["collisions"], 0);
  // Both agents go around the wall: 6 steps each, and they can pass each other.
  EXPECT_EQ(j["lower_bound"], 12);
  EXPECT_EQ(j["soc"], 12);
  // Paths in the file's coordinates: agent 0 starts at (0, 0) (top left) and ends at (4, 2).
  EXPECT_EQ(j["paths"][0].front(), nlohmann::json::array({0, 0}));
  EXPECT_EQ(j["paths"][0].back(), nlohmann::json::array({4, 2}));
  EXPECT_EQ(j["paths"][1].front(), nlohmann::json::array({4, 2}));
  EXPECT_TRUE(contains(swarm::test::slurp(o.out_dir + "/animation.html"), "data:image/png;base64,"));
}

TEST(MapfCommand, RunsThePapersGaOnTheWarehouse) {
  swarm::test::TempDir tmp;
  MapfOptions o;
  o.map = "warehouse-5x8";
  o.random = 5;
  o.seed = 1;
  o.solver = "ga";
  o.out_dir = tmp.file("out");
  const Outcome r = run(o);
  EXPECT_TRUE(r.code == 0 || r.code == 1) << r.err;
  const auto j = nlohmann::json::parse(swarm::test::slurp(o.out_dir + "/result.json"));
  EXPECT_EQ(j["rules"], "paper-warehouse");
  EXPECT_EQ(j["paths"].size(), 5u);
  EXPECT_TRUE(j.contains("stop_time_per_agent"));
}

TEST(MapfCommand, AnUnsolvableInstanceExitsOneWithinItsLimit) {
  swarm::test::TempDir tmp;
  swarm::test::spit(tmp.file("dead.map"), "type octile\nheight 2\nwidth 3\nmap\n...\n@@@\n");
  swarm::test::spit(tmp.file("dead.scen"), "version 1\n0\tdead.map\t3\t2\t0\t0\t1\t0\t1\n0\tdead.map\t3\t2\t1\t0\t0\t0\t1\n");
  MapfOptions o;
  o.map = tmp.file("dead.map");
  o.scen = tmp.file("dead.scen");
  o.agents = 2;
  o.time_limit_s = 0.2;
  o.out_dir = tmp.file("out");
  const Outcome r = run(o);
  EXPECT_EQ(r.code, 1);
  const auto j = nlohmann::json::parse(swarm::test::slurp(o.out_dir + "/result.json"));
  EXPECT_TRUE(j["status"] == "timeout" || j["status"] == "infeasible");
  EXPECT_LT(j["seconds"].get<double>(), 0.35);
}

TEST(MapfCommand, BadInputExitsTwoNamingTheFileOrFlag) {
  Files f;
  const auto bad = [&](MapfOptions o, const std::string& expected) {
    o.out_dir = f.tmp.file("bad");
    const Outcome r = run(o);
    EXPECT_EQ(r.code, 2) << expected;
    EXPECT_TRUE(contains(r.err, expected)) << r.err;
  };
  MapfOptions o;
  o.map = f.map;
  o.scen = f.scen;
  o.agents = 2;
  MapfOptions x = o;
  x.solver = "astar";
  bad(x, "--solver: unknown solver 'astar'");
  x = o;
  x.agents = 3;
  bad(x, "tiny.scen: 3 agents asked for, but the scenario has only 2 rows");
  x = o;
  x.map = f.tmp.file("missing.map");
  bad(x, "missing.map");
  x = o;
  x.solver = "ga";
  bad(x, "the paper's GA runs only on --map warehouse-RxC");
  x = o;
  x.agents.reset();
  bad(x, "--agents: required with --scen");
  x = o;
  x.w = 0.5;
  bad(x, "--w");
  // A start on a wall, and two agents on one goal: the scenario's line is named.
  swarm::test::spit(f.tmp.file("wall.scen"), "version 1\n0\ttiny.map\t5\t3\t1\t1\t4\t2\t6\n");
  x = o;
  x.scen = f.tmp.file("wall.scen");
  x.agents = 1;
  bad(x, "wall.scen:2: start (1, 1) is on a blocked cell");
  swarm::test::spit(f.tmp.file("same.scen"), "version 1\n0\ttiny.map\t5\t3\t0\t0\t4\t2\t6\n0\ttiny.map\t5\t3\t0\t2\t4\t2\t6\n");
  x.scen = f.tmp.file("same.scen");
  x.agents = 2;
  bad(x, "same.scen:3: goal (4, 2) is also the goal of line 2");
  swarm::test::spit(f.tmp.file("other.scen"), "version 1\n0\tother.map\t5\t3\t0\t0\t4\t2\t6\n");
  x.scen = f.tmp.file("other.scen");
  x.agents = 1;
  bad(x, "other.scen:2: the scenario is for map \"other.map\"");
  // A goal outside the map, and a scenario written for a map of another size.
  swarm::test::spit(f.tmp.file("out.scen"), "version 1\n0\ttiny.map\t5\t3\t0\t0\t9\t2\t6\n");
  x.scen = f.tmp.file("out.scen");
  bad(x, "out.scen:2: goal (9, 2) is outside the 5 x 3 map");
  swarm::test::spit(f.tmp.file("size.scen"), "version 1\n0\ttiny.map\t8\t8\t0\t0\t4\t2\t6\n");
  x.scen = f.tmp.file("size.scen");
  bad(x, "size.scen:2: the scenario's map is 8 x 8, the map is 5 x 3");
  x = o;
  x.scen.clear();
  x.agents.reset();
  x.map = "warehouse-5x8";
  x.random = 41;
  bad(x, "--random: 41 robots do not fit on the 40 intersections");
  bad(MapfOptions{}, "--map: required");
  // --graph: a malformed or missing file, other flags that give the instance, the GA.
  swarm::test::spit(f.tmp.file("broken.graph"), "vertices 5\nedge 0 1\nedge 0 7\nagent 0 1\n");
  MapfOptions g;
  g.graph = f.tmp.file("broken.graph");
  bad(g, "broken.graph:3: edge 0 7: vertex 7 is not in the graph (vertices 0..4)");
  g.graph = f.tmp.file("missing.graph");
  bad(g, "missing.graph: cannot open the graph file");
  swarm::test::spit(f.tmp.file("branch.graph"), kBranchGraph);
  g.graph = f.tmp.file("branch.graph");
  x = o;
  x.graph = g.graph;
  bad(x, "--graph: the file holds the graph and its agents; give it without --map, --scen, --agents and --random");
  x = g;
  x.random = 3;
  bad(x, "--graph: the file holds the graph and its agents");
  x = g;
  x.solver = "ga";
  bad(x, "--solver ga: the paper's GA runs only on --map warehouse-RxC");
}

TEST(MapfCommand, SolvesAGraphFile) {
  swarm::test::TempDir tmp;
  swarm::test::spit(tmp.file("branch.graph"), kBranchGraph);
  MapfOptions o;
  o.graph = tmp.file("branch.graph");
  o.out_dir = tmp.file("out");
  const Outcome r = run(o);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"result.json", "paths.png", "animation.html", "instance.graph"}) {
    EXPECT_TRUE(fs::exists(fs::path(o.out_dir) / name)) << name;
  }
  EXPECT_FALSE(fs::exists(fs::path(o.out_dir) / "map.map"));
  const auto j = nlohmann::json::parse(swarm::test::slurp(o.out_dir + "/result.json"));
  EXPECT_EQ(j["graph"], o.graph);
  EXPECT_FALSE(j.contains("map"));
  EXPECT_EQ(j["status"], "solved");
  EXPECT_EQ(j["soc"], 8);
  EXPECT_EQ(j["lower_bound"], 6);
  EXPECT_EQ(j["makespan"], 5);
  EXPECT_EQ(j["coordinates"], "vertex ids of the graph file");
  EXPECT_EQ(j["starts"], nlohmann::json::array({0, 3}));
  EXPECT_EQ(j["goals"], nlohmann::json::array({3, 0}));
  // Vertex ids per time step.
  EXPECT_EQ(j["paths"][0], nlohmann::json::array({0, 1, 4, 1, 2, 3}));
  EXPECT_EQ(j["paths"][1], nlohmann::json::array({3, 2, 1, 0}));
  // The instance written back reads as the same graph and agents.
  EXPECT_TRUE(contains(swarm::test::slurp(o.out_dir + "/instance.graph"), "edge 1 4\nagent 0 3\nagent 3 0\n"));
  // LaCAM solves it too (its plan may cost more).
  o.solver = "lacam";
  o.out_dir = tmp.file("lacam");
  const Outcome l = run(o);
  EXPECT_EQ(l.code, 0) << l.err;
  EXPECT_GE(nlohmann::json::parse(swarm::test::slurp(o.out_dir + "/result.json"))["soc"].get<int>(), 8);
}

TEST(MapfCommand, AnUnsolvableGraphExitsOne) {
  swarm::test::TempDir tmp;
  // Two agents swapping the ends of a path: nobody can pass.
  swarm::test::spit(tmp.file("path.graph"), "vertices 4\nedge 0 1\nedge 1 2\nedge 2 3\nagent 0 3\nagent 3 0\n");
  MapfOptions o;
  o.graph = tmp.file("path.graph");
  o.solver = "lacam";
  o.time_limit_s = 2;
  o.out_dir = tmp.file("out");
  const Outcome r = run(o);
  EXPECT_EQ(r.code, 1) << r.err;
  const auto j = nlohmann::json::parse(swarm::test::slurp(o.out_dir + "/result.json"));
  EXPECT_EQ(j["status"], "infeasible");
  EXPECT_LT(j["seconds"].get<double>(), 1.0);
}

TEST(ExperimentMapf, WritesTablesAndPlots) {
  swarm::test::TempDir tmp;
  swarm::tools::MapfExperimentOptions o;
  o.part = "all";
  o.robots = {5};
  o.runs = 2;
  o.paper_solvers = {"cbs", "ecbs"};
  o.movingai_dir = swarm::test::benchmarks_dir() + "/movingai";
  o.maps = {"random-32-32-20"};
  o.agents = {5};
  o.scenarios = 2;
  o.movingai_solvers = {"cbs", "lacam"};
  o.out_dir = tmp.file("exp");
  std::ostringstream out, err;
  ASSERT_EQ(swarm::tools::experiment_mapf_command(o, out, err), 0) << err.str();
  for (const char* name : {"table.txt", "results.csv", "results.json", "paper.png", "movingai-random-32-32-20.png"}) {
    EXPECT_TRUE(fs::exists(fs::path(o.out_dir) / name)) << name;
  }
  const std::string table = swarm::test::slurp(o.out_dir + "/table.txt");
  EXPECT_TRUE(contains(table, "collisions per run")) << table;
  EXPECT_TRUE(contains(table, "2/2")) << table;  // 5 agents on random-32-32-20: both solvers, both scenarios
  EXPECT_TRUE(contains(out.str(), "[1/"));     // progress lines
  o.part = "everything";
  std::ostringstream out2, err2;
  EXPECT_EQ(swarm::tools::experiment_mapf_command(o, out2, err2), 2);
  EXPECT_TRUE(contains(err2.str(), "--part"));
}

}  // namespace
