// From a division to every robot's drive: the approach to a relocated start, then STC; checked
// with the motion model on the map and with check_coverage_path on each region.
#include <gtest/gtest.h>

#include "swarm/planner/coverage/coverage_check.hpp"
#include "swarm/planner/coverage/coverage_plan.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace {

using namespace swarm::planner;

// Robots bunched in a corner, BFS + K-Means moves their starts: each robot first drives to its
// region, then covers it; the whole drive is legal 4-connected steps on the map.
TEST(CoveragePlan, RobotsOutsideTheirRegionsDriveThereFirst) {
  const OccupancyGrid map(16, 12, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{0, 0}, {1, 0}, {0, 1}};
  DarpConfig cfg;
  cfg.init = DarpInit::BfsKMeans;
  cfg.reinit_always = true;
  const DarpResult d = divide_areas(map, req, cfg);
  ASSERT_EQ(d.status, DarpStatus::Converged);
  const std::vector<CoveragePlan> plans = plan_coverage(map, d, req.robots);
  ASSERT_EQ(plans.size(), 3u);
  int approached = 0;
  for (std::size_t r = 0; r < plans.size(); ++r) {
    const CoveragePlan& p = plans[r];
    ASSERT_TRUE(p.reachable);
    const std::vector<Cell> drive = p.path();
    ASSERT_FALSE(drive.empty());
    EXPECT_EQ(drive.front(), req.robots[r]);
    for (std::size_t k = 1; k < drive.size(); ++k) {
      EXPECT_EQ(MotionModel::four().check(map, drive[k - 1], drive[k]), MoveCheck::Ok) << "step " << k;
    }
    const OccupancyGrid region = region_of(map, d.assignment, static_cast<int>(r));
    const Cell entry = p.approach.empty() ? req.robots[r] : p.approach.back();
    EXPECT_TRUE(region.is_free(entry));
    for (const std::string& problem : check_coverage_path(region, entry, p.coverage.cells)) ADD_FAILURE() << problem;
    if (!p.approach.empty()) {
      ++approached;
      for (std::size_t k = 0; k + 1 < p.approach.size(); ++k) EXPECT_FALSE(region.is_free(p.approach[k]));
    }
  }
  EXPECT_GE(approached, 1) << "at least one start moved away from its robot";
}

TEST(CoveragePlan, GivenStartsNeedNoApproach) {
  const OccupancyGrid map(10, 6, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{1, 1}, {8, 4}};
  const DarpResult d = divide_areas(map, req);
  const std::vector<CoveragePlan> plans = plan_coverage(map, d, req.robots);
  for (std::size_t r = 0; r < plans.size(); ++r) {
    EXPECT_TRUE(plans[r].approach.empty());
    EXPECT_EQ(plans[r].path(), plans[r].coverage.cells);
    EXPECT_EQ(plans[r].coverage.covered, d.cells[r]);
  }
}

TEST(CoveragePlan, ARegionBehindAWallIsUnreachable) {
  // Robot 0 stands in the left room; its division (given by hand) is the right room only.
  OccupancyGrid map(7, 3, 0.2, 0, 0, CellState::Free);
  for (int y = 0; y < 3; ++y) map.set({3, y}, CellState::Occupied);
  DarpResult d;
  d.assignment.assign(map.size(), kOutsideRegion);
  for (int y = 0; y < 3; ++y) {
    for (int x = 4; x < 7; ++x) d.assignment[map.index({x, y})] = 0;
  }
  const std::vector<CoveragePlan> plans = plan_coverage(map, d, {{0, 0}});
  EXPECT_FALSE(plans[0].reachable);
  EXPECT_TRUE(plans[0].path().empty());
}

}  // namespace
