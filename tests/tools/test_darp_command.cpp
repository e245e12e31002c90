// `swarm darp`: a map file and robots in, division.png and result.json out, exit 0 / 1 / 2 / 3; every
// bad input of issue 8 exits 2 naming the flag, file and line.
#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

#include "darp_command.hpp"
#include "swarm_test/files.hpp"

namespace {

using swarm::test::slurp;
using swarm::test::spit;
using swarm::test::TempDir;
using swarm::tools::DarpOptions;

struct Outcome {
  int status;
  std::string out, err;
  nlohmann::json result;
};

class DarpCommand : public ::testing::Test {
 protected:
  // A MovingAI map: row 0 is the top; '@' blocked.
  std::string map(const std::vector<std::string>& rows, const std::string& name = "m.map") {
    std::string text = "type octile\nheight " + std::to_string(rows.size()) + "\nwidth " +
                       std::to_string(rows.front().size()) + "\nmap\n";
    for (const std::string& r : rows) text += r + "\n";
    spit(dir_.file(name), text);
    return dir_.file(name);
  }
  Outcome run(DarpOptions o) {
    if (o.out_dir.empty()) o.out_dir = dir_.file("out");
    std::ostringstream out, err;
    Outcome r{swarm::tools::darp_command(o, out, err), out.str(), err.str(), {}};
    if (r.status != 2) r.result = nlohmann::json::parse(slurp(o.out_dir + "/result.json"));
    return r;
  }
  TempDir dir_;
};

const std::vector<std::string> kSmall = {
    "......",
    ".@@...",
    "......",
    "......",
};

TEST_F(DarpCommand, WritesTheResultInTheFilesCoordinates) {
  DarpOptions o;
  o.map = map(kSmall);
  o.robots = "0,0;5,3";
  const Outcome r = run(o);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json& j = r.result;
  for (const char* key : {"status", "iterations", "alpha0", "alpha_reinit", "cells", "seconds_division",
                          "seconds_paths", "assignment", "paths", "path_length", "turns"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["cells"][0].get<int>() + j["cells"][1].get<int>(), 22);  // 22 free cells...
  EXPECT_NEAR(j["cells"][0].get<int>(), 11, 1);                       // ...within one of 11 each
  ASSERT_EQ(j["assignment"].size(), 4u);                // one array per file row, top row first
  EXPECT_EQ(j["assignment"][1][1], -1);                 // the '@' at column 1, row 1
  EXPECT_EQ(j["assignment"][0][0], 0);
  EXPECT_EQ(j["assignment"][3][5], 1);
  EXPECT_EQ(j["robots"], nlohmann::json({{0, 0}, {5, 3}}));
  EXPECT_EQ(j["paths"][0][0], nlohmann::json({0, 0}));
  EXPECT_EQ(j["paths"][1][0], nlohmann::json({5, 3}));
  EXPECT_EQ(j["path_length"][0], j["paths"][0].size() - 1);
  EXPECT_TRUE(j["problems"].empty());
  EXPECT_FALSE(slurp(dir_.file("out/division.png")).empty());
}

TEST_F(DarpCommand, RobotsFileUsesColumnAndRowFromTheTop) {
  spit(dir_.file("r.robots"), "# x y\n0 3\n\n5 0\n");
  DarpOptions o;
  o.map = map(kSmall);
  o.robots_file = dir_.file("r.robots");
  const Outcome r = run(o);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.result["robots"], nlohmann::json({{0, 3}, {5, 0}}));
  EXPECT_EQ(r.result["assignment"][3][0], 0);  // robot 0 at the bottom-left of the file
}

TEST_F(DarpCommand, UnreachableCellsAreReportedNotRejected) {
  DarpOptions o;
  o.map = map({"..@..", "..@.."});
  o.robots = "0,0;1,1";
  const Outcome r = run(o);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.result["unreachable_cells"], 4);
  EXPECT_EQ(r.result["assignment"][0][4], -2);
  EXPECT_NE(r.out.find("4 free cells no robot can reach"), std::string::npos) << r.out;
}

TEST_F(DarpCommand, NotConvergedExitsOne) {
  DarpOptions o;
  o.map = map(kSmall);
  o.robots = "0,0;1,0";
  o.max_iterations = 0;
  o.method = "darp";
  const Outcome r = run(o);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.result["status"], "failed");
  EXPECT_EQ(r.result["finished_by"], "darp");
}

// The default method finishes what DARP leaves: the same start, no DARP iteration, converged by
// the repair, and says so.
TEST_F(DarpCommand, TheDefaultMethodRepairsWhatDarpLeaves) {
  DarpOptions o;
  o.map = map(kSmall);
  o.robots = "0,0;1,0";
  o.max_iterations = 0;
  const Outcome r = run(o);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.result["status"], "converged");
  EXPECT_EQ(r.result["method"], "auto");
  EXPECT_EQ(r.result["finished_by"], "repair");
  EXPECT_GT(r.result["repair_moves"].get<int>(), 0);
  EXPECT_EQ(r.result["cells"], nlohmann::json({11, 11}));
  EXPECT_NE(r.out.find("finished by repair"), std::string::npos) << r.out;
}

// Three arms of 4 cells on one centre cell, two robots (shares 6.5): a region without the centre
// fits in one arm, so no division within one cell exists. Exit 3, the reason, the best division.
TEST_F(DarpCommand, NoBalancedDivisionExitsThreeWithTheReason) {
  DarpOptions o;
  o.map = map({"@@@@.@@@@",
               "@@@@.@@@@",
               "@@@@.@@@@",
               "@@@@.@@@@",
               ".........",
               "@@@@@@@@@"});
  o.robots = "4,0;8,4";
  const Outcome r = run(o);
  EXPECT_EQ(r.status, 3) << r.out << r.err;
  EXPECT_EQ(r.result["status"], "impossible");
  EXPECT_NE(r.result["message"].get<std::string>().find("parts of 4, 4 and 4 cells"), std::string::npos)
      << r.result["message"];
  EXPECT_NE(r.out.find("no division within 1 cell of every share exists"), std::string::npos) << r.out;
  EXPECT_TRUE(r.result["problems"].empty()) << r.result["problems"];
}

// Every bad input: exit 2 and one message that names where the problem is.
TEST_F(DarpCommand, BadInputExitsTwoNamingTheProblem) {
  const std::string m = map(kSmall);
  auto expect_bad = [&](DarpOptions o, const std::string& message) {
    std::ostringstream out, err;
    if (o.out_dir.empty()) o.out_dir = dir_.file("out");
    EXPECT_EQ(swarm::tools::darp_command(o, out, err), 2) << message;
    EXPECT_NE(err.str().find(message), std::string::npos) << err.str();
  };
  DarpOptions o;
  o.map = m;
  o.robots = "1,1";
  expect_bad(o, "--robots entry 0: robot at (1, 1) is on a blocked cell");
  o.robots = "0,0";
  o.method = "best";
  expect_bad(o, "--method \"best\": expected auto or darp");
  o.method = "auto";
  o.robots = "0,0;6,0";
  expect_bad(o, "--robots entry 1: robot at (6, 0) is outside the map (6 x 4 cells");
  o.robots = "0,0;3,2;0,0";
  expect_bad(o, "--robots entry 2: a second robot at (0, 0) (the first: --robots entry 0)");
  o.robots = "0,0;x";
  expect_bad(o, "--robots entry 1 (\"x\"): expected x,y");
  o.robots = "";
  spit(dir_.file("bad.robots"), "0 0\n1 two\n");
  o.robots_file = dir_.file("bad.robots");
  expect_bad(o, dir_.file("bad.robots") + ":2: expected \"x y\"");
  o.robots_file = "";
  o.count = 40;
  expect_bad(o, "--count 40: more robots than free cells");
  o.count = 2;
  o.robots = "0,0";
  expect_bad(o, "give the robots one way");
  o.robots = "";
  o.init = "voronoi";
  expect_bad(o, "--init \"voronoi\": expected given, random, kmeans or bfs-kmeans");
  o.init = "given";
  o.weights = "1,0";
  expect_bad(o, "--weights: entry 1 (\"0\") must be a positive number");
  DarpOptions walls;
  walls.map = map({"@@", "@@"}, "walls.map");
  walls.count = 1;
  expect_bad(walls, "the map has no free cell");
  DarpOptions missing;
  missing.map = dir_.file("nope.map");
  missing.count = 1;
  expect_bad(missing, "nope.map");
}

TEST_F(DarpCommand, PlacesRobotsByCountAndSeedReproducibly) {
  DarpOptions o;
  o.map = map(kSmall);
  o.count = 3;
  o.placement = "bunched";
  o.seed = 4;
  const Outcome a = run(o);
  o.out_dir = dir_.file("again");
  const Outcome b = run(o);
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.result["robots"], b.result["robots"]);
  EXPECT_EQ(a.result["robots"].size(), 3u);
}

}  // namespace
