#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/data.hpp"
#include "swarm/planner/sensing/raycast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "swarm/planner/grid/map_io.hpp"

namespace swarm::planner {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kTol = 1e-5f;

using swarm::test::grid_from;  // rows top first (swarm_test/ascii_grid.hpp)

std::string benchmark_dir() { return swarm::test::benchmarks_dir(); }

OccupancyGrid random_map(int w, int h, double p_occupied, unsigned seed) {
  std::mt19937 rng(seed);
  std::bernoulli_distribution wall(p_occupied);
  OccupancyGrid g(w, h, 0.2, 0.0, 0.0, CellState::Free);
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (wall(rng)) g.set(static_cast<int>(i), CellState::Occupied);
  }
  return g;
}

// ---- cast_ray against hand-computed distances ----------------------------------------------

TEST(CastRay, AxisAlignedBeamsHitWallsAndTheMapEdge) {
  const OccupancyGrid g = grid_from({
      ".....#.",  // y = 2
      ".....#.",  // y = 1
      ".....#.",  // y = 0
  });
  // From the centre of (1, 1) = (1.5, 1.5).
  EXPECT_FLOAT_EQ(cast_ray(g, 1.5, 1.5, 0.0, 20.0f), 3.5f);          // enters (5, 1) at x = 5
  EXPECT_FLOAT_EQ(cast_ray(g, 1.5, 1.5, kPi, 20.0f), 1.5f);          // leaves at x = 0
  EXPECT_FLOAT_EQ(cast_ray(g, 1.5, 1.5, kPi / 2, 20.0f), 1.5f);      // leaves at y = 3
  EXPECT_FLOAT_EQ(cast_ray(g, 1.5, 1.5, 3 * kPi / 2, 20.0f), 1.5f);  // leaves at y = 0
  EXPECT_FLOAT_EQ(cast_ray(g, 1.5, 1.5, 0.0, 3.0f), 3.0f);           // nothing within range
  EXPECT_FLOAT_EQ(cast_ray(g, 1.5, 1.5, 0.0, 3.5f), 3.5f);           // hit exactly at max: none
  // Not from a cell centre: (0.25, 0.75) to the wall at x = 5.
  EXPECT_FLOAT_EQ(cast_ray(g, 0.25, 0.75, 0.0, 20.0f), 4.75f);
  // Beyond the wall, to the right map edge.
  EXPECT_FLOAT_EQ(cast_ray(g, 6.5, 0.5, 0.0, 20.0f), 0.5f);
  EXPECT_FLOAT_EQ(cast_ray(g, 6.5, 0.5, kPi, 20.0f), 0.5f);  // back into the wall at x = 6
}

TEST(CastRay, StartingInsideAWallOrOutsideTheMapIsZero) {
  const OccupancyGrid g = grid_from({"..#.."});
  EXPECT_EQ(cast_ray(g, 2.5, 0.5, 0.0, 10.0f), 0.0f);
  EXPECT_EQ(cast_ray(g, -0.5, 0.5, 0.0, 10.0f), 0.0f);
  EXPECT_EQ(cast_ray(g, 1.5, 1.5, 0.0, 10.0f), 0.0f);
}

TEST(CastRay, SlopeOneHalfCrossesExactlyTheCellsItPassesThrough) {
  // From (0.5, 0.5) with direction (2, 1): y = 0.5 + (x - 0.5) / 2, so the ray is in row 1 for
  // x in [1.5, 3.5), row 2 for x in [3.5, 5.5), row 3 for x in [5.5, 7.5), leaving at y = 4.
  const double a = std::atan2(1.0, 2.0);
  const double per_x = std::sqrt(5.0) / 2.0;  // ray length per unit of x
  OccupancyGrid g(8, 4, 0.2, 0.0, 0.0, CellState::Free);
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, a, 50.0f), 7.0 * per_x, kTol);  // out through y = 4 at x = 7.5
  g.set(Cell{4, 1}, CellState::Occupied);  // below the ray: never crossed
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, a, 50.0f), 7.0 * per_x, kTol);
  g.set(Cell{4, 2}, CellState::Occupied);  // crossed: entered at x = 4
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, a, 50.0f), 3.5 * per_x, kTol);
  g.set(Cell{3, 2}, CellState::Occupied);  // entered earlier, through y = 2 at x = 3.5
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, a, 50.0f), 3.0 * per_x, kTol);
  // The reverse direction from the top-right cell leaves through y = 0 at x = 0.5.
  OccupancyGrid open(8, 4, 0.2, 0.0, 0.0, CellState::Free);
  EXPECT_NEAR(cast_ray(open, 7.5, 3.5, a + kPi, 50.0f), 7.0 * per_x, kTol);
}

TEST(CastRay, FortyFiveDegreesPassesCornersAndCannotSlipBetweenTouchingWalls) {
  const double s2 = std::sqrt(2.0);
  OccupancyGrid g(6, 6, 0.2, 0.0, 0.0, CellState::Free);
  // From (0.5, 0.5) the diagonal passes the corners (1, 1), (2, 2), ... at t = (k - 0.5) * sqrt 2.
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, kPi / 4, 50.0f), 5.5 * s2, kTol);  // leaves at corner (6, 6)
  g.set(Cell{2, 1}, CellState::Occupied);  // touches the corner (2, 2) from below
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, kPi / 4, 50.0f), 1.5 * s2, kTol);
  g.set(Cell{2, 1}, CellState::Free);
  g.set(Cell{2, 3}, CellState::Occupied);  // touches the corner (3, 3) from the left
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, kPi / 4, 50.0f), 2.5 * s2, kTol);
  g.set(Cell{2, 3}, CellState::Free);
  g.set(Cell{4, 4}, CellState::Occupied);  // on the diagonal itself
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, kPi / 4, 50.0f), 3.5 * s2, kTol);
  // Cells touching the diagonal only away from its corners do not matter.
  g.set(Cell{4, 4}, CellState::Free);
  g.set(Cell{0, 2}, CellState::Occupied);
  g.set(Cell{2, 0}, CellState::Occupied);
  EXPECT_NEAR(cast_ray(g, 0.5, 0.5, kPi / 4, 50.0f), 5.5 * s2, kTol);
}

TEST(Scan, BeamIIsCastRayAtBeamAngleBitForBit) {
  const OccupancyGrid g = random_map(40, 30, 0.2, 7);
  std::vector<float> ranges(360);
  for (const Cell origin : {Cell{5, 5}, Cell{20, 15}, Cell{39, 29}}) {
    OccupancyGrid truth = g;
    truth.set(origin, CellState::Free);
    scan(truth, origin, 360, 15.0f, ranges.data());
    for (int i = 0; i < 360; ++i) {
      EXPECT_EQ(ranges[static_cast<std::size_t>(i)],
                cast_ray(truth, origin.x + 0.5, origin.y + 0.5, beam_angle(i, 360), 15.0f))
          << "beam " << i;
    }
  }
  EXPECT_DOUBLE_EQ(beam_angle(90, 360), kPi / 2);
}

// ---- integrate_scan -----------------------------------------------------------------------

TEST(IntegrateScan, FourBeamsMarkTheCrossedCellsFreeAndTheHitOccupied) {
  const OccupancyGrid truth = grid_from({
      ".....#.",  // y = 2
      ".....#.",  // y = 1
      ".....#.",  // y = 0
  });
  float ranges[4];
  scan(truth, {1, 1}, 4, 10.0f, ranges);
  EXPECT_FLOAT_EQ(ranges[0], 3.5f);
  EXPECT_FLOAT_EQ(ranges[1], 1.5f);
  EXPECT_FLOAT_EQ(ranges[2], 1.5f);
  EXPECT_FLOAT_EQ(ranges[3], 1.5f);

  OccupancyGrid map(7, 3);
  std::vector<CellChange> changes;
  EXPECT_EQ(integrate_scan(map, {1, 1}, ranges, 4, 10.0f, &changes), 8);
  const OccupancyGrid expected = grid_from({
      "?.?????",
      ".....#?",
      "?.?????",
  });
  EXPECT_EQ(map, expected);
  ASSERT_EQ(changes.size(), 8u);
  int occupied = 0;
  for (const CellChange& c : changes) occupied += c.state == CellState::Occupied;
  EXPECT_EQ(occupied, 1);
  // The same scan again changes nothing.
  EXPECT_EQ(integrate_scan(map, {1, 1}, ranges, 4, 10.0f, nullptr), 0);
}

TEST(IntegrateScan, MaxRangeBeamsFreeTheCellsUpToTheRange) {
  const OccupancyGrid truth(20, 20, 0.2, 0.0, 0.0, CellState::Free);
  float ranges[4];
  scan(truth, {10, 10}, 4, 3.0f, ranges);
  for (float r : ranges) EXPECT_EQ(r, 3.0f);
  OccupancyGrid map(20, 20);
  // Each beam crosses the cells entered at 0.5, 1.5 and 2.5 (< 3); plus the origin.
  EXPECT_EQ(integrate_scan(map, {10, 10}, ranges, 4, 3.0f, nullptr), 13);
  EXPECT_TRUE(map.is_free({13, 10}));
  EXPECT_TRUE(map.is_unknown({14, 10}));
  EXPECT_TRUE(map.is_free({10, 7}));
  EXPECT_TRUE(map.is_unknown({10, 6}));
  EXPECT_TRUE(map.is_unknown({11, 11}));
}

TEST(IntegrateScan, AHitAtACornerMarksNothingOccupied) {
  OccupancyGrid truth(6, 6, 0.2, 0.0, 0.0, CellState::Free);
  truth.set(Cell{2, 2}, CellState::Occupied);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  float ranges[8] = {nan, nan, nan, nan, nan, nan, nan, nan};
  ranges[1] = cast_ray(truth, 0.5, 0.5, beam_angle(1, 8), 10.0f);  // the 45 degree beam
  EXPECT_NEAR(ranges[1], 1.5 * std::sqrt(2.0), kTol);
  OccupancyGrid map(6, 6);
  std::vector<CellChange> changes;
  EXPECT_EQ(integrate_scan(map, {0, 0}, ranges, 8, 10.0f, &changes), 2);
  const std::vector<CellChange> expected = {{map.index({0, 0}), CellState::Free},
                                            {map.index({1, 1}), CellState::Free}};
  EXPECT_EQ(changes, expected);
}

TEST(IntegrateScan, OccupiedWinsWithinOneScanButAnOldWallCanBeCleared) {
  OccupancyGrid map(20, 20);
  map.set(Cell{11, 10}, CellState::Occupied);  // from an earlier scan
  std::vector<float> ranges(360, std::numeric_limits<float>::quiet_NaN());
  ranges[0] = 2.0f;  // ends inside (12, 10)
  ranges[1] = 5.0f;  // 1 degree up: crosses (11, 10), (12, 10), ... first
  std::vector<CellChange> changes;
  const int n = integrate_scan(map, {10, 10}, ranges.data(), 360, 15.0f, &changes);
  EXPECT_EQ(map.at(Cell{12, 10}), CellState::Occupied);
  EXPECT_EQ(map.at(Cell{11, 10}), CellState::Free);
  EXPECT_EQ(n, static_cast<int>(changes.size()));
  int occupied_changes = 0;
  for (const CellChange& c : changes) {
    if (c.index == map.index({12, 10})) {
      EXPECT_EQ(c.state, CellState::Occupied);
    }
    occupied_changes += c.state == CellState::Occupied;
  }
  EXPECT_EQ(occupied_changes, 2);  // (12, 10) and beam 1's end, (15, 10)
  EXPECT_EQ(map.at(Cell{15, 10}), CellState::Occupied);
}

TEST(IntegrateScan, ChangesReplayTheUpdateExactly) {
  const OccupancyGrid truth = random_map(30, 30, 0.25, 11);
  OccupancyGrid map(30, 30);
  std::vector<float> ranges(360);
  for (const Cell origin : {Cell{3, 3}, Cell{15, 16}, Cell{28, 2}}) {
    if (!truth.is_free(origin)) continue;
    scan(truth, origin, 360, 15.0f, ranges.data());
    OccupancyGrid before = map;
    std::vector<CellChange> changes;
    const int n = integrate_scan(map, origin, ranges.data(), 360, 15.0f, &changes);
    EXPECT_EQ(n, static_cast<int>(changes.size()));
    EXPECT_EQ(before.apply(changes), n);  // each change is real and listed once
    EXPECT_EQ(before, map);
  }
}

// The property the simulator relies on: a scan of the truth, integrated, never contradicts it.
void expect_consistent_with_truth(const OccupancyGrid& truth, int stride, int beams) {
  OccupancyGrid map(truth.width(), truth.height());
  std::vector<float> ranges(static_cast<std::size_t>(beams));
  int origins = 0;
  for (int y = 0; y < truth.height(); y += stride) {
    for (int x = 0; x < truth.width(); x += stride) {
      if (!truth.is_free({x, y})) continue;
      ++origins;
      OccupancyGrid single(truth.width(), truth.height());
      scan(truth, {x, y}, beams, 15.0f, ranges.data());
      integrate_scan(single, {x, y}, ranges.data(), beams, 15.0f, nullptr);
      integrate_scan(map, {x, y}, ranges.data(), beams, 15.0f, nullptr);
      for (std::size_t i = 0; i < truth.size(); ++i) {
        const CellState t = truth.at(static_cast<int>(i));
        const CellState s = single.at(static_cast<int>(i));
        ASSERT_FALSE(s == CellState::Free && t == CellState::Occupied)
            << "origin (" << x << ", " << y << ") freed wall " << i;
        ASSERT_FALSE(s == CellState::Occupied && t == CellState::Free)
            << "origin (" << x << ", " << y << ") walled free cell " << i;
      }
    }
  }
  ASSERT_GT(origins, 0);
  int free_cells = 0, walls = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const CellState t = truth.at(static_cast<int>(i));
    const CellState s = map.at(static_cast<int>(i));
    EXPECT_FALSE(s == CellState::Free && t == CellState::Occupied) << i;
    EXPECT_FALSE(s == CellState::Occupied && t == CellState::Free) << i;
    free_cells += s == CellState::Free;
    walls += s == CellState::Occupied;
  }
  EXPECT_GT(free_cells, 0);
  EXPECT_GT(walls, 0);
}

TEST(IntegrateScan, NeverContradictsTheTruthOnRandomMaps) {
  expect_consistent_with_truth(random_map(40, 40, 0.2, 1), 1, 360);
  expect_consistent_with_truth(random_map(37, 23, 0.4, 2), 1, 360);
  expect_consistent_with_truth(random_map(50, 50, 0.1, 3), 3, 1000);
  expect_consistent_with_truth(random_map(25, 25, 0.3, 4), 1, 7);
}

TEST(IntegrateScan, NeverContradictsTheTruthOnMovingAiMaps) {
  for (const char* name : {"maze-32-32-2.map", "room-32-32-4.map", "random-32-32-20.map"}) {
    SCOPED_TRACE(name);
    const OccupancyGrid truth = load_movingai_map(benchmark_dir() + "/movingai/" + name);
    expect_consistent_with_truth(truth, 1, 360);
  }
}

TEST(IntegrateScan, ExploringEveryFreeCellOfAMazeRecoversItsReachableWalls) {
  const OccupancyGrid truth = load_movingai_map(benchmark_dir() + "/movingai/maze-32-32-2.map");
  OccupancyGrid map(truth.width(), truth.height());
  std::vector<float> ranges(360);
  for (int i = 0; i < static_cast<int>(truth.size()); ++i) {
    if (truth.at(i) != CellState::Free) continue;
    scan(truth, truth.cell_of(i), 360, 15.0f, ranges.data());
    integrate_scan(map, truth.cell_of(i), ranges.data(), 360, 15.0f, nullptr);
  }
  // Every Free cell was a scan origin; every wall next to a Free cell was seen from it.
  for (int i = 0; i < static_cast<int>(truth.size()); ++i) {
    const Cell c = truth.cell_of(i);
    if (truth.at(i) == CellState::Free) {
      EXPECT_EQ(map.at(i), CellState::Free);
      continue;
    }
    bool next_to_free = false;
    for (int k = 0; k < 4; ++k) {
      next_to_free |= truth.is_free({c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]});
    }
    if (next_to_free) {
      EXPECT_EQ(map.at(i), CellState::Occupied) << c.x << "," << c.y;
    }
  }
}

}  // namespace
}  // namespace swarm::planner
