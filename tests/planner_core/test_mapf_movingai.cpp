// MovingAI `.scen` and `.map` files in and out (planner/mapf/movingai_scen.hpp, map_io.hpp).
#include <gtest/gtest.h>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/data.hpp"
#include "swarm_test/files.hpp"
#include "swarm_test/text.hpp"

namespace {

using swarm::planner::Cell;
using swarm::planner::MapFileError;
using namespace swarm::planner::mapf;
using swarm::test::contains;

const std::string kDir = swarm::test::benchmarks_dir() + "/movingai/";

TEST(MapfMovingAi, ReadsTheFirstKRowsInGridCoordinates) {
  const auto map = swarm::planner::load_movingai_map(kDir + "random-32-32-20.map");
  const Scenario scen = load_movingai_scen(kDir + "random-32-32-20-random-1.scen");
  ASSERT_EQ(scen.rows.size(), 409u);
  // First row: "7 random-32-32-20.map 32 32 5 16 31 24 31.31370850".
  EXPECT_EQ(scen.rows[0].bucket, 7);
  EXPECT_EQ(scen.rows[0].start_x, 5);
  EXPECT_EQ(scen.rows[0].start_y, 16);
  EXPECT_DOUBLE_EQ(scen.rows[0].optimal_length, 31.31370850);
  const Instance in = instance_from_scen(map, scen, 3, "random-32-32-20.map");
  ASSERT_EQ(in.agents(), 3);
  EXPECT_EQ(in.starts[0], (Cell{5, 31 - 16}));  // y counted from the top in the file
  EXPECT_EQ(in.goals[0], (Cell{31, 31 - 24}));
  EXPECT_EQ(to_movingai_xy(map, in.goals[0]), (Cell{31, 24}));
}

std::string error_of(const std::function<void()>& f) { return swarm::test::error_of<MapFileError>(f); }

TEST(MapfMovingAi, NamesTheFileAndLineOfBadInput) {
  swarm::test::TempDir tmp;
  const auto map = swarm::test::grid_from({"....", ".#..", "...."});  // 4 x 3
  const std::string good = "version 1\n0\tm.map\t4\t3\t0\t0\t3\t2\t4\n";
  swarm::test::spit(tmp.file("a.scen"), good + "0\tm.map\t4\t3\t1\t1\t2\t2\t1\n");  // start (1,1) from the top: the wall
  const Scenario a = load_movingai_scen(tmp.file("a.scen"));
  EXPECT_TRUE(contains(error_of([&] { (void)instance_from_scen(map, a, 2, "m.map"); }), "a.scen:3: start (1, 1) is on a blocked cell"));
  EXPECT_TRUE(contains(error_of([&] { (void)instance_from_scen(map, a, 5, "m.map"); }), "5 agents asked for, but the scenario has only 2 rows"));
  EXPECT_TRUE(contains(error_of([&] { (void)instance_from_scen(map, a, 1, "other.map"); }), "a.scen:2: the scenario is for map \"m.map\""));
  swarm::test::spit(tmp.file("b.scen"), "version 1\n0\tm.map\t5\t3\t0\t0\t3\t2\t4\n");
  EXPECT_TRUE(contains(error_of([&] { (void)instance_from_scen(map, load_movingai_scen(tmp.file("b.scen")), 1); }),
                       "b.scen:2: the scenario's map is 5 x 3"));
  swarm::test::spit(tmp.file("c.scen"), good + "0\tm.map\t4\t3\t3\t2\t0\t0\t4\n");  // same goal? no: swapped ends
  EXPECT_EQ(instance_from_scen(map, load_movingai_scen(tmp.file("c.scen")), 2).agents(), 2);
  swarm::test::spit(tmp.file("d.scen"), good + "0\tm.map\t4\t3\t2\t0\t3\t2\t4\n");  // goal (3,2) again
  EXPECT_TRUE(contains(error_of([&] { (void)instance_from_scen(map, load_movingai_scen(tmp.file("d.scen")), 2); }),
                       "d.scen:3: goal (3, 2) is also the goal of line 2"));
  swarm::test::spit(tmp.file("e.scen"), "version 1\n0\tm.map\t4\t3\tx\t0\t3\t2\t4\n");
  EXPECT_TRUE(contains(error_of([&] { (void)load_movingai_scen(tmp.file("e.scen")); }), "e.scen:2: start x must be an integer"));
  EXPECT_TRUE(contains(error_of([&] { (void)load_movingai_scen(tmp.file("missing.scen")); }), "cannot open"));
}

TEST(MapfMovingAi, WritesScenAndMapFilesThatReadBack) {
  swarm::test::TempDir tmp;
  const auto map = swarm::test::grid_from({".....", ".##..", "....."});
  Instance in;
  in.map = map;
  in.starts = {{0, 0}, {4, 2}};
  in.goals = {{4, 0}, {0, 2}};
  swarm::planner::save_movingai_map(tmp.file("m.map"), map);
  save_movingai_scen(tmp.file("m.scen"), in, "m.map");
  const auto back = swarm::planner::load_movingai_map(tmp.file("m.map"));
  EXPECT_EQ(back, map);
  const Instance again = instance_from_scen(back, load_movingai_scen(tmp.file("m.scen")), 2, "m.map");
  EXPECT_EQ(again.starts, in.starts);
  EXPECT_EQ(again.goals, in.goals);
  // Agent 0: (0,0) -> (4,0) along the bottom row, 4 cells: optimal length 4.
  EXPECT_DOUBLE_EQ(load_movingai_scen(tmp.file("m.scen")).rows[0].optimal_length, 4.0);
}

}  // namespace
