// The built-in maps (maps/*.pgm + .yaml, written by maps/generate.py): size, free cells, walls all
// around, and every free cell reachable from the default start through openings >= 0.6 m wide.
#include <gtest/gtest.h>

#include <deque>
#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/warehouse.hpp"

namespace {

namespace cfg = swarm::config;
using swarm::planner::Cell;
using swarm::planner::CellState;
using swarm::planner::OccupancyGrid;

struct Expected {
  const char* name;
  int width;
  int height;
  long free_cells;  // as printed by maps/generate.py; change both together
  double resolution = 0.2;
  bool footprint = true;  // a 0.6 m robot reaches every free cell (not in the Group-k rooms, whose
                          // robot is one 10 cm cell)
};

class BuiltinMap : public ::testing::TestWithParam<Expected> {
 protected:
  OccupancyGrid load() const {
    return swarm::planner::load_map_yaml(cfg::resolve_map_path(GetParam().name, ""));
  }
};

long count(const OccupancyGrid& g, CellState s) {
  long n = 0;
  for (CellState c : g.data()) n += c == s;
  return n;
}

TEST_P(BuiltinMap, HasItsSizeAndFreeCells) {
  const OccupancyGrid g = load();
  EXPECT_EQ(g.width(), GetParam().width);
  EXPECT_EQ(g.height(), GetParam().height);
  EXPECT_DOUBLE_EQ(g.resolution(), GetParam().resolution);
  EXPECT_DOUBLE_EQ(g.origin_x(), 0.0);
  EXPECT_DOUBLE_EQ(g.origin_y(), 0.0);
  EXPECT_EQ(count(g, CellState::Free), GetParam().free_cells);
  EXPECT_EQ(count(g, CellState::Unknown), 0);
}

TEST_P(BuiltinMap, IsWalledAllAround) {
  const OccupancyGrid g = load();
  for (int x = 0; x < g.width(); ++x) {
    EXPECT_TRUE(g.is_occupied({x, 0}) && g.is_occupied({x, g.height() - 1})) << "x = " << x;
  }
  for (int y = 0; y < g.height(); ++y) {
    EXPECT_TRUE(g.is_occupied({0, y}) && g.is_occupied({g.width() - 1, y})) << "y = " << y;
  }
}

TEST_P(BuiltinMap, EveryFreeCellIsReachableFromTheCentreStart) {
  swarm::scenario::Scenario s;
  s.set_map(GetParam().name);
  const cfg::World w = cfg::resolve_world(s, "");
  EXPECT_EQ(w.start, (Cell{w.truth.width() / 2, w.truth.height() / 2})) << "the centre is free";
  const auto mask = swarm::planner::reachable_mask(w.truth, {w.start});
  for (int i = 0; i < static_cast<int>(w.truth.size()); ++i) {
    if (w.truth.at(i) == CellState::Free && !mask[i]) {
      ADD_FAILURE() << "free cell (" << w.truth.cell_of(i).x << ", " << w.truth.cell_of(i).y
                    << ") is unreachable";
      break;
    }
  }
  EXPECT_EQ(w.robot_cells.size(), 9u);
}

// A 3 x 3 cell (0.6 m) footprint must pass every door and gap and get next to every free cell:
// the cells where it fits form one connected area, and every free cell touches that area.
TEST_P(BuiltinMap, OpeningsAreAtLeastThreeCellsWide) {
  if (!GetParam().footprint) GTEST_SKIP() << "a room for a one-cell robot";
  const OccupancyGrid g = load();
  auto fits = [&](Cell c) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (!g.is_free({c.x + dx, c.y + dy})) return false;
      }
    }
    return true;
  };
  const Cell start{g.width() / 2, g.height() / 2};
  ASSERT_TRUE(fits(start));
  std::vector<char> seen(g.size(), 0);
  std::vector<char> near(g.size(), 0);  // within one cell of a reached footprint centre
  std::deque<Cell> todo{start};
  seen[g.index(start)] = 1;
  while (!todo.empty()) {
    const Cell c = todo.front();
    todo.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) near[g.index({c.x + dx, c.y + dy})] = 1;
    }
    for (int k = 0; k < 4; ++k) {
      const Cell n{c.x + swarm::planner::kNeighbourDx[k], c.y + swarm::planner::kNeighbourDy[k]};
      if (g.in_bounds(n) && !seen[g.index(n)] && fits(n)) {
        seen[g.index(n)] = 1;
        todo.push_back(n);
      }
    }
  }
  long missed = 0;
  for (int i = 0; i < static_cast<int>(g.size()); ++i) {
    missed += g.at(i) == CellState::Free && !near[i];
  }
  EXPECT_EQ(missed, 0) << "free cells a 0.6 m wide robot cannot get next to";
}

INSTANTIATE_TEST_SUITE_P(Maps, BuiltinMap,
                         ::testing::Values(Expected{"open", 100, 100, 9332},
                                           Expected{"maze1", 100, 100, 8940},
                                           Expected{"maze2", 100, 100, 8687},
                                           Expected{"small", 40, 40, 1398},
                                           Expected{"clutter", 60, 50, 2513, 0.1, false},
                                           Expected{"empty", 60, 50, 2784, 0.1, false},
                                           Expected{"terminal", 140, 100, 4582},
                                           Expected{"rectangle", 80, 60, 4508}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(BuiltinMaps, AreAllListed) {
  EXPECT_EQ(cfg::builtin_map_names().size(), 9u);
}

// The MAPF paper's world (a multi-agent path finding map: one-cell aisles on purpose, so not the
// 0.6 m footprint checks above): the same cells as planner/mapf/warehouse.hpp's warehouse_map.
TEST(BuiltinMaps, WarehouseIsThePapersFiveByEightWorld) {
  const OccupancyGrid g = swarm::planner::load_map_yaml(cfg::resolve_map_path("warehouse-5x8", ""));
  EXPECT_EQ(g.width(), 17);
  EXPECT_EQ(g.height(), 11);
  EXPECT_EQ(count(g, CellState::Free), 107);  // 40 intersections + 67 passage middles
  const OccupancyGrid w = swarm::planner::mapf::warehouse_map(5, 8);
  for (int i = 0; i < static_cast<int>(g.size()); ++i) EXPECT_EQ(g.at(i), w.at(i)) << "cell " << i;
}

}  // namespace
