// DARP area division: the paper's imbalance numbers, hand-checked divisions and starts, and every
// division of random maps through check_division (coverage_check.hpp), the independent validator.
#include <gtest/gtest.h>

#include <cmath>

#include "swarm/planner/coverage/coverage_check.hpp"
#include "swarm/planner/coverage/darp.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/random_grid.hpp"

namespace {

using namespace swarm::planner;
using swarm::test::ascii_map;

void expect_valid(const OccupancyGrid& map, const DarpRequest& req, const DarpResult& r, bool given = true) {
  for (const std::string& p : check_division(map, req, r, given)) ADD_FAILURE() << p;
}

// docs/papers.md section 2, Table 1: cells per robot after one DARP iteration -> alpha.
TEST(Imbalance, MatchesThePapersTableOne) {
  EXPECT_NEAR(imbalance({249, 542, 381, 1010, 1552, 786}), 0.2512, 5e-5);
  EXPECT_NEAR(imbalance({280, 316, 934, 958, 1637, 395}), 0.2912, 5e-5);
  EXPECT_NEAR(imbalance({622, 690, 505, 730, 1326, 651}), 0.1101, 5e-5);
  EXPECT_NEAR(imbalance({121, 414, 838, 1067, 1537, 543}), 0.2730, 5e-5);
}

TEST(Imbalance, JainIsOneForEqualLoadsAndOneOverNForOneLoad) {
  EXPECT_DOUBLE_EQ(jain_index({5, 5, 5}), 1.0);
  EXPECT_DOUBLE_EQ(jain_index({7, 0, 0, 0}), 0.25);
  EXPECT_DOUBLE_EQ(imbalance({10, 30}, {1, 3}), 0.0);  // loads per unit of weight are equal
  EXPECT_DOUBLE_EQ(jain_index({}), 1.0);
}

// Two robots placed symmetrically on an empty 10 x 5 grid: the first (Voronoi) division is
// already 25 / 25 and connected, so no iteration is needed.
TEST(Darp, SymmetricEmptyGridIsSplitEquallyWithoutIterating) {
  const OccupancyGrid g(10, 5, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{2, 2}, {7, 2}};
  const DarpResult r = divide_areas(g, req);
  ASSERT_EQ(r.status, DarpStatus::Converged) << r.message;
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.cells, (std::vector<int>{25, 25}));
  EXPECT_DOUBLE_EQ(r.alpha0, 0.0);
  for (int x = 0; x < 10; ++x) EXPECT_EQ(r.assignment[g.index({x, 0})], x < 5 ? 0 : 1);
  expect_valid(g, req, r);
}

// Four robots bunched in one corner of an empty grid: the first division is lopsided and DARP
// must iterate to the equal split, 100 cells each within one cell.
TEST(Darp, EmptyGridEndsInAnEqualSplit) {
  for (DarpDistance d : {DarpDistance::Euclidean, DarpDistance::Geodesic}) {
    const OccupancyGrid g(20, 20, 0.2, 0, 0, CellState::Free);
    DarpRequest req;
    req.robots = {{1, 1}, {4, 2}, {2, 5}, {6, 6}};
    DarpConfig cfg;
    cfg.distance = d;
    const DarpResult r = divide_areas(g, req, cfg);
    ASSERT_EQ(r.status, DarpStatus::Converged) << to_string(d);
    EXPECT_GT(r.iterations, 0);
    EXPECT_GT(r.alpha0, 0.2);
    for (int c : r.cells) EXPECT_NEAR(c, 100, 1);
    EXPECT_EQ(r.shares, (std::vector<double>{100, 100, 100, 100}));
    expect_valid(g, req, r);
  }
}

TEST(Darp, UnequalWeightsGiveProportionalShares) {
  const OccupancyGrid g(20, 10, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{2, 5}, {15, 5}};
  req.weights = {1, 3};
  const DarpResult r = divide_areas(g, req);
  ASSERT_EQ(r.status, DarpStatus::Converged);
  EXPECT_EQ(r.shares, (std::vector<double>{50, 150}));
  EXPECT_NEAR(r.cells[0], 50, 1);
  EXPECT_NEAR(r.cells[1], 150, 1);
  EXPECT_NEAR(r.final_imbalance, 0.0, 1e-3);
  expect_valid(g, req, r);
}

// Only the masked cells are divided; a room nobody stands in is reported, not divided.
TEST(Darp, RegionMaskAndUnreachableCells) {
  const auto m = ascii_map({
      "A.....#...",
      "......#...",
      "......#...",
      ".....B#...",
  });
  DarpRequest req;
  req.robots = {m.at.at('A'), m.at.at('B')};
  req.region.assign(m.grid.size(), 1);
  for (int y = 0; y < 4; ++y) req.region[m.grid.index({0, y})] = 0;  // column x = 0 left out...
  req.region[m.grid.index(m.at.at('A'))] = 1;                        // ...but A's own cell
  const DarpResult r = divide_areas(m.grid, req);
  ASSERT_EQ(r.status, DarpStatus::Converged) << r.message;
  EXPECT_EQ(r.unreachable_cells, 12);  // the room right of the wall
  EXPECT_EQ(r.assignment[m.grid.index({8, 1})], kUnreachable);
  EXPECT_EQ(r.assignment[m.grid.index({0, 1})], kOutsideRegion);
  EXPECT_EQ(r.assignment[m.grid.index({6, 1})], kOutsideRegion);  // the wall
  EXPECT_EQ(r.cells[0] + r.cells[1], 24 - 3);
  expect_valid(m.grid, req, r);
}

TEST(Darp, BadInputIsAStatusWithAMessage) {
  const auto m = ascii_map({
      "A.#",
      "...",
  });
  auto status_of = [&](DarpRequest req) { return divide_areas(m.grid, req); };
  DarpRequest none;
  EXPECT_EQ(status_of(none).status, DarpStatus::BadInput);
  DarpRequest wall;
  wall.robots = {{2, 1}};
  EXPECT_EQ(status_of(wall).message, "robot 0 at (2, 1) is not on a free cell");
  DarpRequest outside;
  outside.robots = {{0, 0}, {5, 0}};
  EXPECT_EQ(status_of(outside).message, "robot 1 at (5, 0) is outside the 3 x 2 map");
  DarpRequest twice;
  twice.robots = {{0, 0}, {1, 0}, {0, 0}};
  EXPECT_EQ(status_of(twice).message, "robots 0 and 2 are both at (0, 0)");
  DarpRequest weight;
  weight.robots = {{0, 0}};
  weight.weights = {0};
  EXPECT_EQ(status_of(weight).status, DarpStatus::BadInput);
  weight.weights = {1, 2};
  EXPECT_EQ(status_of(weight).message, "2 weights for 1 robots");
  DarpRequest masked;
  masked.robots = {{0, 0}};
  masked.region.assign(m.grid.size(), 0);
  EXPECT_EQ(status_of(masked).message, "robot 0 at (0, 0) is not on a cell of the region");
  masked.region.resize(3);
  EXPECT_EQ(status_of(masked).status, DarpStatus::BadInput);
  DarpRequest crowded;
  crowded.robots = {{0, 0}, {1, 0}};
  crowded.region.assign(m.grid.size(), 0);
  crowded.region[m.grid.index({0, 0})] = crowded.region[m.grid.index({1, 0})] = 1;
  EXPECT_EQ(status_of(crowded).status, DarpStatus::Converged);  // 2 robots, 2 cells: fine
  crowded.robots.push_back({0, 1});
  crowded.region[m.grid.index({0, 1})] = 1;
  crowded.region[m.grid.index({1, 0})] = 0;  // now (1, 0) is outside: robot 1 is off the region
  EXPECT_EQ(status_of(crowded).status, DarpStatus::BadInput);
}

TEST(Darp, IsDeterministicPerSeed) {
  const OccupancyGrid g(24, 18, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{1, 1}, {6, 2}, {2, 7}, {9, 9}, {4, 12}};
  DarpConfig cfg;
  cfg.seed = 5;
  const DarpResult a = divide_areas(g, req, cfg);
  const DarpResult b = divide_areas(g, req, cfg);
  EXPECT_EQ(a.assignment, b.assignment);
  EXPECT_EQ(a.iterations, b.iterations);
  cfg.seed = 6;
  const DarpResult c = divide_areas(g, req, cfg);
  EXPECT_TRUE(a.iterations != c.iterations || a.assignment != c.assignment);  // other random factors
}

TEST(Darp, StopAndIterationLimitReturnTheBestDivisionSoFar) {
  const OccupancyGrid g(30, 30, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 2}, {3, 0}};
  DarpConfig alone;
  alone.method = DivisionMethod::Darp;
  const DarpResult stopped = divide_areas(g, req, alone, [] { return true; });
  EXPECT_EQ(stopped.status, DarpStatus::Stopped);
  EXPECT_EQ(stopped.iterations, 0);
  expect_valid(g, req, stopped);
  DarpConfig few = alone;
  few.max_iterations = 5;
  const DarpResult failed = divide_areas(g, req, few);
  EXPECT_EQ(failed.status, DarpStatus::Failed);
  EXPECT_EQ(failed.iterations, 5);
  expect_valid(g, req, failed);
}

// A corridor `length` cells long with robots on its first two cells.
DarpResult corridor(int length, const DarpConfig& cfg, DarpRequest& req) {
  req.robots = {{0, 0}, {1, 0}};
  return divide_areas(OccupancyGrid(length, 1, 0.2, 0, 0, CellState::Free), req, cfg);
}

// BFS + K-Means on a corridor 11 cells long, robots on its first two cells: the BFS candidate
// regions are {x = 0} and {x = 1..10}; their means 0 and 5.5 snap to cells 0 and 5 (ties go to
// the lower index). One re-initialisation (L = 1), applied always.
TEST(DarpStarts, BfsKMeansMovesEachStartToItsCandidateRegionsMean) {
  DarpConfig cfg;
  cfg.init = DarpInit::BfsKMeans;
  cfg.reinit_always = true;
  cfg.max_reinitialisations = 1;
  DarpRequest req;
  const DarpResult r = corridor(11, cfg, req);
  ASSERT_EQ(r.starts, (std::vector<Cell>{{0, 0}, {5, 0}}));
  EXPECT_NEAR(r.alpha0, 1 - (11.0 * 11) / (2 * (1 + 100)), 1e-12);  // cells 1 and 10
  ASSERT_EQ(r.alpha_reinit.size(), 1u);
  EXPECT_GE(r.iterations, 1);  // the abandoned probe from the robots' own cells counts
  EXPECT_EQ(r.status, DarpStatus::Converged);
  expect_valid(OccupancyGrid(11, 1, 0.2, 0, 0, CellState::Free), req, r, false);
}

// Selective: an already balanced first division is kept as it is.
TEST(DarpStarts, SelectiveBfsKMeansKeepsABalancedStart) {
  const OccupancyGrid g(10, 5, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{2, 2}, {7, 2}};
  DarpConfig cfg;
  cfg.init = DarpInit::BfsKMeans;
  const DarpResult r = divide_areas(g, req, cfg);
  EXPECT_TRUE(r.alpha_reinit.empty());
  EXPECT_EQ(r.starts, req.robots);
  EXPECT_EQ(r.iterations, 0);
}

// K-Means from the robots' cells 0 and 1 of a 10-cell corridor: Lloyd moves the centres to
// 0 / 5, 1 / 6, 1.5 / 6.5 and settles at 2 / 7 (clusters {0..4} and {5..9}).
TEST(DarpStarts, KMeansGrowsCentresFromTheRobotsCells) {
  DarpConfig cfg;
  cfg.init = DarpInit::KMeans;
  DarpRequest req;
  const DarpResult r = corridor(10, cfg, req);
  EXPECT_EQ(r.starts, (std::vector<Cell>{{2, 0}, {7, 0}}));
  ASSERT_EQ(r.alpha_reinit.size(), 1u);
  EXPECT_DOUBLE_EQ(r.alpha_reinit[0], 0.0);
  EXPECT_EQ(r.cells, (std::vector<int>{5, 5}));
}

TEST(DarpStarts, RandomStartsAreDistinctCellsOfTheRegion) {
  const OccupancyGrid g(12, 12, 0.2, 0, 0, CellState::Free);
  DarpRequest req;
  req.robots = {{0, 0}, {1, 0}, {2, 0}};
  DarpConfig cfg;
  cfg.init = DarpInit::Random;
  const DarpResult r = divide_areas(g, req, cfg);
  ASSERT_EQ(r.status, DarpStatus::Converged);
  EXPECT_NE(r.starts[0], r.starts[1]);
  EXPECT_NE(r.starts[1], r.starts[2]);
  EXPECT_NE(r.starts, req.robots);
  expect_valid(g, req, r, false);
}

// Random maps with walls: every method and both distances give valid divisions (connected,
// holding their starts, within one cell when converged; every reachable cell exactly once).
TEST(Darp, RandomMapsGiveValidDivisions) {
  Rng rng(11);
  int converged = 0, runs = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const OccupancyGrid g = swarm::test::random_walls(rng, 12, 28, 12);
    const int w = g.width(), h = g.height();
    DarpRequest req;
    const int n = rng.uniform_int(2, 5);
    while (static_cast<int>(req.robots.size()) < n) {
      const Cell c{rng.uniform_int(0, w - 1), rng.uniform_int(0, h - 1)};
      if (g.is_free(c) && std::find(req.robots.begin(), req.robots.end(), c) == req.robots.end()) req.robots.push_back(c);
    }
    for (DarpInit init : {DarpInit::Given, DarpInit::Random, DarpInit::KMeans, DarpInit::BfsKMeans}) {
      for (DarpDistance d : {DarpDistance::Euclidean, DarpDistance::Geodesic}) {
        DarpConfig cfg;
        cfg.method = DivisionMethod::Darp;  // DARP alone (test_division_repair.cpp: the default)
        cfg.init = init;
        cfg.distance = d;
        cfg.max_iterations = 2000;
        cfg.seed = trial;
        const DarpResult r = divide_areas(g, req, cfg);
        SCOPED_TRACE("trial " + std::to_string(trial) + " " + to_string(init) + " " + to_string(d));
        ASSERT_NE(r.status, DarpStatus::BadInput) << r.message;
        expect_valid(g, req, r, init == DarpInit::Given);
        converged += r.status == DarpStatus::Converged;
        ++runs;
      }
    }
  }
  EXPECT_GE(converged, runs * 3 / 4);
}

TEST(Darp, NamesRoundTrip) {
  for (DarpInit i : {DarpInit::Given, DarpInit::Random, DarpInit::KMeans, DarpInit::BfsKMeans}) {
    EXPECT_EQ(parse_darp_init(to_string(i)), i);
  }
  EXPECT_EQ(parse_darp_distance("geodesic"), DarpDistance::Geodesic);
  EXPECT_EQ(parse_darp_distance("manhattan"), std::nullopt);
  EXPECT_STREQ(to_string(DarpStatus::Failed), "failed");
  EXPECT_STREQ(to_string(DarpStatus::Impossible), "impossible");
  EXPECT_EQ(parse_division_method("auto"), DivisionMethod::Auto);
  EXPECT_EQ(parse_division_method("darp"), DivisionMethod::Darp);
  EXPECT_EQ(parse_division_method("best"), std::nullopt);
}

}  // namespace
