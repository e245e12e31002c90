// resolve_map_path / resolve_world: finding the map, choosing the start, the robots' cells and the
// errors for starts that cannot work.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <utility>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm_test/text.hpp"

namespace {

namespace cfg = swarm::config;
namespace fs = std::filesystem;
using swarm::planner::Cell;
using swarm::planner::CellState;
using swarm::planner::OccupancyGrid;
using swarm::scenario::Scenario;

std::string error_of(const std::function<void()>& f) { return swarm::test::error_of<cfg::ConfigError>(f, "(no ConfigError)"); }

using swarm::test::contains;

// 20 x 20 cells (4 m x 4 m) of free space inside an outer wall, with a closed 2 x 2 pocket:
// free cells (5..6, 5..6) ringed by walls at x, y = 4 and 7.
OccupancyGrid pocket_map() {
  OccupancyGrid g(20, 20, 0.2, 0.0, 0.0, CellState::Free);
  for (int i = 0; i < 20; ++i) {
    g.set({i, 0}, CellState::Occupied);
    g.set({i, 19}, CellState::Occupied);
    g.set({0, i}, CellState::Occupied);
    g.set({19, i}, CellState::Occupied);
  }
  for (int i = 4; i <= 7; ++i) {
    g.set({i, 4}, CellState::Occupied);
    g.set({i, 7}, CellState::Occupied);
    g.set({4, i}, CellState::Occupied);
    g.set({7, i}, CellState::Occupied);
  }
  g.set({12, 12}, CellState::Unknown);
  return g;
}

class World : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("swarm_config_world_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "maps");
    swarm::planner::save_map_yaml((dir_ / "maps" / "pocket.yaml").string(), pocket_map());
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A scenario on the pocket map, referenced relative to the scenario folder dir_.
  static Scenario on_pocket(int groups, int robots_per_group) {
    Scenario s;
    s.set_name("pocket");
    s.set_map("maps/pocket.yaml");
    s.set_groups(groups);
    s.set_robots_per_group(robots_per_group);
    return s;
  }
  static Scenario with_start(Scenario s, double x, double y) {
    s.mutable_start()->set_x(x);
    s.mutable_start()->set_y(y);
    return s;
  }

  fs::path dir_;
};

TEST_F(World, BuiltInNamesResolveIntoTheDataFolder) {
  for (const std::string& name : cfg::builtin_map_names()) {
    const std::string p = cfg::resolve_map_path(name, dir_.string());
    EXPECT_EQ(p, (fs::path(cfg::data_dir()) / "maps" / (name + ".yaml")).string());
    EXPECT_TRUE(fs::is_regular_file(p)) << p;
  }
  EXPECT_EQ(cfg::builtin_map_names(),
            (std::vector<std::string>{"open", "maze1", "maze2", "small", "clutter", "empty", "warehouse-5x8",
                                      "terminal", "rectangle"}));
}

// Regression: a 33,000 x 6 map with the start at column 32,950 ran 400 ticks with 0 planning
// rounds and exit 0 (coordinates narrowed to 16 bits on the wire). It is refused at load.
TEST_F(World, AMapTooLargeForTheWireCoordinatesIsRefusedNamingTheLimit) {
  swarm::planner::save_map_yaml((dir_ / "maps" / "long.yaml").string(),
                                OccupancyGrid(33000, 6, 0.2, 0.0, 0.0, CellState::Free));
  Scenario s = with_start(on_pocket(1, 1), 32950 * 0.2 + 0.1, 0.5);
  s.set_map("maps/long.yaml");
  const std::string e = error_of([&] { (void)cfg::resolve_world(s, dir_.string()); });
  EXPECT_TRUE(contains(e, "33000 x 6 cells; at most 32767 cells per side")) << e;
  EXPECT_TRUE(contains(e, "long.yaml")) << e;
}

// A MovingAI benchmark map has no scale: its cells are the scenario's map_resolution_m.
TEST_F(World, AMovingAiMapIsReadAtTheScenariosResolution) {
  OccupancyGrid blocked = pocket_map();
  blocked.set({12, 12}, CellState::Occupied);  // .map has no unknown cells
  swarm::planner::save_movingai_map((dir_ / "maps" / "pocket.map").string(), blocked);
  EXPECT_TRUE(cfg::is_movingai_map("maps/pocket.map"));
  EXPECT_FALSE(cfg::is_movingai_map("maps/pocket.yaml"));
  Scenario s = on_pocket(1, 2);
  s.set_map("maps/pocket.map");
  s.set_map_resolution_m(0.5);
  const cfg::World w = cfg::resolve_world(s, dir_.string());
  EXPECT_EQ(w.frame.width, 20);
  EXPECT_EQ(w.frame.height, 20);
  EXPECT_DOUBLE_EQ(w.frame.resolution, 0.5);
  for (int i = 0; i < static_cast<int>(blocked.size()); ++i) {
    EXPECT_EQ(w.truth.is_free(w.truth.cell_of(i)), blocked.is_free(blocked.cell_of(i))) << i;
  }
  s.set_map_resolution_m(0);
  const std::string e = error_of([&] { (void)cfg::resolve_world(s, dir_.string()); });
  EXPECT_TRUE(contains(e, "map_resolution_m")) << e;
}

TEST_F(World, PathsAreTakenFromTheScenarioFolder) {
  const std::string expected = (dir_ / "maps" / "pocket.yaml").string();
  EXPECT_EQ(cfg::resolve_map_path("maps/pocket.yaml", dir_.string()), expected);
  EXPECT_EQ(cfg::resolve_map_path("./maps/../maps/pocket.yaml", dir_.string()), expected);
  EXPECT_EQ(cfg::resolve_map_path(expected, "/nonexistent"), expected);  // absolute: as is
}

TEST_F(World, UnknownMapNameListsTheBuiltIns) {
  const std::string e = error_of([&] { (void)cfg::resolve_map_path("maze3", dir_.string()); });
  EXPECT_EQ(e.rfind("unknown map 'maze3': not a built-in (open, maze1, maze2, small, clutter, "
                    "empty, warehouse-5x8, terminal, rectangle) nor an existing file",
                    0),
            0u)
      << e;
  Scenario s = on_pocket(1, 1);
  s.set_map("maze3");
  const std::string w = error_of([&] { (void)cfg::resolve_world(s, dir_.string(), "s.pbtxt"); });
  EXPECT_EQ(w.rfind("s.pbtxt: field map: unknown map 'maze3'", 0), 0u) << w;
}

TEST_F(World, DataDirFollowsTheEnvironment) {
  const char* before = std::getenv("SWARM_DATA_DIR");
  const std::string saved = before != nullptr ? before : "";
  ::unsetenv("SWARM_DATA_DIR");
  const std::string built_in = cfg::data_dir();
  EXPECT_TRUE(fs::is_directory(fs::path(built_in) / "maps")) << built_in;
  ::setenv("SWARM_DATA_DIR", dir_.c_str(), 1);
  EXPECT_EQ(cfg::data_dir(), dir_.string());
  // The data folder has no maze1: the error says how to fix that.
  const std::string e = error_of([&] { (void)cfg::resolve_map_path("maze1", ""); });
  EXPECT_TRUE(contains(e, "SWARM_DATA_DIR")) << e;
  ::setenv("SWARM_DATA_DIR", "", 1);  // empty counts as unset
  EXPECT_EQ(cfg::data_dir(), built_in);
  if (before != nullptr) {
    ::setenv("SWARM_DATA_DIR", saved.c_str(), 1);
  } else {
    ::unsetenv("SWARM_DATA_DIR");
  }
}

TEST_F(World, BrokenMapFileKeepsTheMapErrorMessage) {
  fs::create_directories(dir_ / "bad");
  std::ofstream(dir_ / "bad" / "m.yaml") << "image: m.pgm\nresolution: abc\norigin: [0, 0, 0]\n";
  std::string map_error;
  try {
    (void)swarm::planner::load_map_yaml((dir_ / "bad" / "m.yaml").string());
  } catch (const swarm::planner::MapFileError& e) {
    map_error = e.what();
  }
  ASSERT_FALSE(map_error.empty());
  Scenario s = on_pocket(1, 1);
  s.set_map("bad/m.yaml");
  EXPECT_EQ(error_of([&] { (void)cfg::resolve_world(s, dir_.string()); }), map_error);
}

TEST_F(World, DefaultStartIsTheFreeCellNearestTheCentreAndIsRecorded) {
  const cfg::World w = cfg::resolve_world(on_pocket(2, 3), dir_.string());
  EXPECT_EQ(w.start, (Cell{10, 10}));
  EXPECT_EQ(w.map_path, (dir_ / "maps" / "pocket.yaml").string());
  ASSERT_TRUE(w.scenario.has_start());
  EXPECT_DOUBLE_EQ(w.scenario.start().x(), 2.1);
  EXPECT_DOUBLE_EQ(w.scenario.start().y(), 2.1);
  EXPECT_EQ(w.truth.cell_at(w.scenario.start().x(), w.scenario.start().y()), w.start);
  // Re-resolving the recorded scenario gives the same world.
  const cfg::World again = cfg::resolve_world(w.scenario, dir_.string());
  EXPECT_EQ(again.start, w.start);
  EXPECT_EQ(again.robot_cells, w.robot_cells);
}

TEST_F(World, DefaultStartAvoidsAWallAtTheCentre) {
  OccupancyGrid g = pocket_map();
  g.set({10, 10}, CellState::Occupied);
  swarm::planner::save_map_yaml((dir_ / "maps" / "pocket.yaml").string(), g);
  const cfg::World w = cfg::resolve_world(on_pocket(1, 1), dir_.string());
  EXPECT_EQ(w.start, (Cell{10, 9}));  // one of the four nearest; ties go to the lowest y, then x
}

TEST_F(World, RobotCellsAreDistinctFreeAndReachable) {
  const cfg::World w = cfg::resolve_world(with_start(on_pocket(3, 3), 3.0, 1.0), dir_.string());
  EXPECT_EQ(w.start, (Cell{15, 5}));
  EXPECT_DOUBLE_EQ(w.scenario.start().x(), 3.0);  // a given start is kept as given
  ASSERT_EQ(w.robot_cells.size(), 9u);
  const auto mask = swarm::planner::reachable_mask(w.truth, {w.start});
  std::set<std::pair<int, int>> seen;
  for (const Cell c : w.robot_cells) {
    EXPECT_TRUE(w.truth.is_free(c));
    EXPECT_TRUE(mask[w.truth.index(c)]);
    EXPECT_TRUE(seen.insert({c.x, c.y}).second) << "two robots on (" << c.x << ", " << c.y << ")";
  }
}

TEST_F(World, StartInsideAWallSaysWhichCellAndSuggestsAFreeOne) {
  const Scenario s = with_start(on_pocket(1, 1), 0.9, 1.5);  // cell (4, 7): the pocket's wall
  const std::string e = error_of([&] { (void)cfg::resolve_world(s, dir_.string(), "s.pbtxt"); });
  EXPECT_EQ(e, "s.pbtxt: start (0.90, 1.50) m is cell (4, 7), which is occupied in " +
                   (dir_ / "maps" / "pocket.yaml").string() +
                   "; pick a free cell, e.g. (0.70, 1.50)")
      << e;
}

TEST_F(World, StartOnAnUnknownCellIsRefused) {
  const Scenario s = with_start(on_pocket(1, 1), 2.5, 2.5);  // cell (12, 12)
  const std::string e = error_of([&] { (void)cfg::resolve_world(s, dir_.string(), "s.pbtxt"); });
  EXPECT_TRUE(contains(e, "is cell (12, 12), which is unknown in ")) << e;
}

TEST_F(World, StartOutsideTheMapGivesTheMapsExtent) {
  const Scenario s = with_start(on_pocket(1, 1), 4.0, 1.0);  // x = 4.0 is just past the edge
  const std::string e = error_of([&] { (void)cfg::resolve_world(s, dir_.string(), "s.pbtxt"); });
  EXPECT_TRUE(contains(e, "s.pbtxt: start (4.00, 1.00) m is outside the map ")) << e;
  EXPECT_TRUE(contains(e, "spans x [0.00, 4.00) m and y [0.00, 4.00) m")) << e;
  EXPECT_TRUE(contains(e, "e.g. (2.10, 2.10)")) << e;
  const Scenario far = with_start(on_pocket(1, 1), -1e300, 1e300);
  EXPECT_TRUE(contains(error_of([&] { (void)cfg::resolve_world(far, dir_.string()); }),
                       "is outside the map"));
}

TEST_F(World, SealedStartWithMoreRobotsThanCellsIsRefused) {
  const Scenario s = with_start(on_pocket(3, 3), 1.1, 1.1);  // cell (5, 5), inside the pocket
  const std::string e = error_of([&] { (void)cfg::resolve_world(s, dir_.string(), "s.pbtxt"); });
  EXPECT_EQ(e.rfind("s.pbtxt: start (1.10, 1.10) m is cell (5, 5), from which only 4 free cells "
                    "are reachable in ",
                    0),
            0u)
      << e;
  EXPECT_TRUE(contains(e, "fewer than the 9 robots (3 groups x 3)")) << e;
  EXPECT_TRUE(contains(e, "e.g. (")) << e;
  // Four robots fit in the pocket.
  const cfg::World w = cfg::resolve_world(with_start(on_pocket(2, 2), 1.1, 1.1), dir_.string());
  EXPECT_EQ(w.robot_cells.size(), 4u);
}

TEST_F(World, MoreRobotsThanAnyAreaHoldsAsksForFewerRobots) {
  const std::string e =
      error_of([&] { (void)cfg::resolve_world(on_pocket(20, 20), dir_.string()); });
  EXPECT_TRUE(contains(e, "only 307 free cells are reachable")) << e;
  EXPECT_TRUE(contains(e, "use fewer robots: no free area of ")) << e;
  EXPECT_TRUE(contains(e, " holds 400 (the largest has 307 cells)")) << e;
}

TEST_F(World, ImpossibleValuesAreCaughtBeforeTheMapIsRead) {
  Scenario s = on_pocket(0, 3);
  s.set_map("does-not-exist");
  EXPECT_EQ(error_of([&] { (void)cfg::resolve_world(s, dir_.string()); }),
            "scenario 'pocket': field groups: must be >= 1 (got 0)");
}

}  // namespace
