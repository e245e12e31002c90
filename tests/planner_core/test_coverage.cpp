#include "swarm/planner/coverage/coverage.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::planner {
namespace {

const double kStep = 0.1 / 0.17;  // the paper's 10 cm cell at 0.17 m/s

TEST(CoverageTime, StepsAndTurnsAtThePapersRates) {
  const CoverageTimeModel model;
  EXPECT_NEAR(model.step_s(), kStep, 1e-12);
  // right, right, up (90 degrees: 1 s), down (180 degrees: 2 s).
  const std::vector<Cell> path{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 0}};
  EXPECT_NEAR(path_time_s(path, model), 4 * kStep + 1 + 2, 1e-12);
  EXPECT_EQ(model.turn_s(1), 0.5);
  EXPECT_EQ(model.turn_s(3), 1.5);
  EXPECT_EQ(path_time_s({{4, 4}}, model), 0.0);
}

TEST(CoverageCurve, CountsFirstVisitsOfRegionCellsOverTime) {
  const OccupancyGrid map(4, 2, 0.1, 0, 0, CellState::Free);
  CellMask region = free_cells(map);
  region[static_cast<std::size_t>(map.index({3, 0}))] = 0;  // 7 cells to clean
  // (0,0) (1,0) (2,0) (3,0: not in the region) (3,1) turn (2,1) (2,0: seen) ...
  const std::vector<Cell> path{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 0}};
  const CoverageCurve c = coverage_curve(region, map, path, {});
  EXPECT_EQ(c.region_cells, 7);
  ASSERT_EQ(c.samples.size(), 5u);
  EXPECT_EQ(c.samples[0].time_s, 0.0);
  EXPECT_NEAR(c.samples[2].time_s, 2 * kStep, 1e-12);
  EXPECT_NEAR(c.samples[3].time_s, 4 * kStep + 1, 1e-12);  // (3, 1): after the turn up
  EXPECT_NEAR(c.samples[4].time_s, 5 * kStep + 2, 1e-12);  // (2, 1): after the turn left
  EXPECT_NEAR(c.total_time_s, 6 * kStep + 3, 1e-12);
  EXPECT_NEAR(c.fraction_at(2.5 * kStep), 3.0 / 7, 1e-12);
  EXPECT_EQ(c.fraction_at(-1), 0.0);
  EXPECT_NEAR(*c.time_to(4.0 / 7), 4 * kStep + 1, 1e-12);
  EXPECT_EQ(c.time_to(1.0), std::nullopt);  // two cells are never visited
}

TEST(CoveragePathCheck, AcceptsAGoodPathAndNamesWhatIsWrong) {
  const OccupancyGrid map = swarm::test::grid_from({
      "...",
      ".#.",
      "...",
  });
  const CellMask region = free_cells(map);
  CoveragePath good;
  good.cells = {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {2, 1}, {2, 0}, {1, 0}};
  EXPECT_EQ(check_coverage_path(map, region, {0, 0}, good), "");
  CoveragePath diagonal = good;
  diagonal.cells.push_back({0, 1});
  EXPECT_EQ(check_coverage_path(map, region, {0, 0}, diagonal), "step 8 is not adjacent");
  CoveragePath through_wall = good;
  through_wall.cells.push_back({1, 1});
  EXPECT_EQ(check_coverage_path(map, region, {0, 0}, through_wall), "step 8 is blocked");
  CoveragePath short_one = good;
  short_one.cells.pop_back();
  EXPECT_EQ(check_coverage_path(map, region, {0, 0}, short_one), "region cell (1, 0) is never covered");
  CoveragePath lying = short_one;
  lying.missed = {{1, 0}};  // reachable, so not an excuse
  EXPECT_EQ(check_coverage_path(map, region, {0, 0}, lying), "a reachable cell is listed as missed");
  EXPECT_EQ(check_coverage_path(map, region, {1, 0}, good), "the path does not start at the start");
}

}  // namespace
}  // namespace swarm::planner
