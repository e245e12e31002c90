#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/data.hpp"
#include "swarm/planner/grid/astar.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "swarm/planner/grid/map_io.hpp"

namespace swarm::planner {

void PrintTo(const Cell& c, std::ostream* os) { *os << "(" << c.x << ", " << c.y << ")"; }

namespace {

const double kSqrt2 = std::sqrt(2.0);

using swarm::test::grid_from;  // rows top first (swarm_test/ascii_grid.hpp)

std::string benchmark_dir() { return swarm::test::benchmarks_dir(); }

// Every step is to an 8-neighbour, passable, and no diagonal step cuts a corner.
void expect_valid(const OccupancyGrid& g, const std::vector<Cell>& path, bool unknown_is_free) {
  const auto passable = [&](Cell c) {
    return g.is_free(c) || (unknown_is_free && g.is_unknown(c));
  };
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Cell a = path[i - 1];
    const Cell b = path[i];
    const int dx = std::abs(a.x - b.x);
    const int dy = std::abs(a.y - b.y);
    ASSERT_TRUE(dx <= 1 && dy <= 1 && dx + dy > 0) << "step " << i;
    ASSERT_TRUE(passable(b)) << "step " << i;
    if (dx + dy == 2) {
      ASSERT_TRUE(passable({b.x, a.y}) && passable({a.x, b.y})) << "corner cut at step " << i;
    }
  }
}

TEST(AStar, OpenGridPathIsOctileOptimal) {
  const OccupancyGrid g(10, 10, 0.2, 0.0, 0.0, CellState::Free);
  const auto path = astar(g, {0, 0}, {7, 3});
  ASSERT_TRUE(path);
  EXPECT_EQ(path->front(), (Cell{0, 0}));
  EXPECT_EQ(path->back(), (Cell{7, 3}));
  EXPECT_EQ(path->size(), 8u);
  EXPECT_NEAR(path_length(*path), 4 + 3 * kSqrt2, 1e-12);
  expect_valid(g, *path, false);
}

TEST(AStar, DetoursAroundAWallWithoutCuttingItsEnd) {
  const OccupancyGrid g = grid_from({
      "..........",  // y = 4
      "....#.....",  // y = 3
      "....#.....",  // y = 2
      "....#.....",  // y = 1
      "....#.....",  // y = 0
  });
  const auto path = astar(g, {2, 0}, {6, 0});
  ASSERT_TRUE(path);
  // (2,0) -> (3,4) costs 3 + sqrt2; (3,4) -> (5,4) costs 2 since (4,4) may not be entered
  // diagonally past (4,3); (5,4) -> (6,0) costs 3 + sqrt2.
  EXPECT_NEAR(path_length(*path), 8 + 2 * kSqrt2, 1e-12);
  expect_valid(g, *path, false);
  EXPECT_NE(std::find(path->begin(), path->end(), Cell{4, 4}), path->end());
}

TEST(AStar, NeverCutsACorner) {
  const OccupancyGrid blocked = grid_from({
      "#.",  // y = 1
      ".#",  // y = 0
  });
  EXPECT_FALSE(astar(blocked, {0, 0}, {1, 1}));
  const OccupancyGrid half = grid_from({
      "..",  // y = 1
      ".#",  // y = 0
  });
  const auto path = astar(half, {0, 0}, {1, 1});
  ASSERT_TRUE(path);
  const std::vector<Cell> expected = {{0, 0}, {0, 1}, {1, 1}};
  EXPECT_EQ(*path, expected);
  EXPECT_DOUBLE_EQ(path_length(*path), 2.0);
}

TEST(AStar, UnknownIsPassableOnlyWhenAllowed) {
  const OccupancyGrid g = grid_from({
      "...",  // y = 2
      "#?#",  // y = 1
      "...",  // y = 0
  });
  const auto optimistic = astar(g, {1, 0}, {1, 2});
  ASSERT_TRUE(optimistic);
  EXPECT_DOUBLE_EQ(path_length(*optimistic), 2.0);
  EXPECT_FALSE(astar(g, {1, 0}, {1, 2}, {.unknown_is_free = false}));
  EXPECT_FALSE(astar(g, {0, 0}, {1, 1}, {.unknown_is_free = false}));  // Unknown goal
}

TEST(AStar, StartIsAlwaysAllowed) {
  const OccupancyGrid g = grid_from({"#.."});
  const auto path = astar(g, {0, 0}, {2, 0}, {.unknown_is_free = false});
  ASSERT_TRUE(path);
  EXPECT_EQ(path->size(), 3u);
  EXPECT_EQ(*astar(g, {0, 0}, {0, 0}), (std::vector<Cell>{Cell{0, 0}}));
}

TEST(AStar, UnreachableOrInvalidGoalsReturnNullopt) {
  OccupancyGrid g(200, 200, 0.2, 0.0, 0.0, CellState::Free);
  for (int i = 0; i < 200; ++i) g.set(Cell{100, i}, CellState::Occupied);
  EXPECT_FALSE(astar(g, {10, 10}, {150, 150}));  // explores the whole left half, then stops
  EXPECT_FALSE(astar(g, {10, 10}, {100, 5}));     // goal Occupied
  EXPECT_FALSE(astar(g, {10, 10}, {-1, 5}));      // goal out of bounds
  EXPECT_FALSE(astar(g, {200, 0}, {1, 1}));       // start out of bounds
  EXPECT_TRUE(astar(g, {10, 10}, {99, 199}));
}

TEST(AStar, IsDeterministic) {
  const OccupancyGrid g(30, 30, 0.2, 0.0, 0.0, CellState::Free);
  const auto a = astar(g, {0, 0}, {29, 17});
  OccupancyGrid other(60, 60, 0.2, 0.0, 0.0, CellState::Free);
  (void)astar(other, {59, 59}, {0, 3});  // reuses per-thread memory in between
  const auto b = astar(g, {0, 0}, {29, 17});
  ASSERT_TRUE(a && b);
  EXPECT_EQ(*a, *b);
}

// MovingAI scenarios list octile optimal lengths (no corner cutting) for each start/goal pair.
TEST(AStar, MatchesMovingAiOptimalLengths) {
  for (const char* name : {"maze-32-32-2", "room-32-32-4", "random-32-32-20"}) {
    SCOPED_TRACE(name);
    const std::string dir = benchmark_dir() + "/movingai/";
    const OccupancyGrid map = load_movingai_map(dir + name + ".map");
    std::ifstream scen(dir + name + "-random-1.scen");
    ASSERT_TRUE(scen) << "missing " << dir << name << "-random-1.scen (set SWARM_BENCHMARKS_DIR)";
    std::string line;
    std::getline(scen, line);  // version 1
    int checked = 0;
    while (std::getline(scen, line)) {
      std::istringstream ls(line);
      int bucket = 0, w = 0, h = 0, sx = 0, sy = 0, gx = 0, gy = 0;
      double optimal = 0.0;
      std::string file;
      if (!(ls >> bucket >> file >> w >> h >> sx >> sy >> gx >> gy >> optimal)) continue;
      const auto path = astar(map, from_movingai_xy(map, sx, sy), from_movingai_xy(map, gx, gy),
                              {.unknown_is_free = false});
      ASSERT_TRUE(path) << line;
      EXPECT_NEAR(path_length(*path), optimal, 1e-6) << line;
      expect_valid(map, *path, false);
      ++checked;
    }
    EXPECT_GT(checked, 300);
  }
}

TEST(PathLength, SumsStepLengths) {
  EXPECT_EQ(path_length({}), 0.0);
  EXPECT_EQ(path_length({{3, 3}}), 0.0);
  EXPECT_DOUBLE_EQ(path_length({{0, 0}, {1, 1}, {1, 2}, {2, 2}}), 2 + kSqrt2);
}

}  // namespace
}  // namespace swarm::planner
