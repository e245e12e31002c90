// Routes for the live coverage task: every cell of the set visited by the routes together, each
// route a legal 4-connected walk from its robot's cell; several divisions, the best kept.
#include "swarm/planner/coverage/cover_routes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "swarm/planner/coverage/coverage_check.hpp"
#include "swarm/planner/grid/motion.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace swarm::planner {
namespace {

std::vector<std::uint8_t> free_cells(const OccupancyGrid& g) {
  std::vector<std::uint8_t> m(g.size(), 0);
  for (std::size_t i = 0; i < g.size(); ++i) m[i] = g.at(static_cast<int>(i)) == CellState::Free;
  return m;
}

// The longest route's length in cells (its moves and one).
std::size_t longest(const CoverRoutes& r) {
  std::size_t most = 0;
  for (const auto& route : r.routes) most = std::max(most, route.size());
  return most;
}

// Independent check (coverage_check.hpp): each route starts at its robot, every step is a legal
// 4-connected action on the map, and together the routes stand on every reachable cell of the set.
void expect_covers(const OccupancyGrid& map, const std::vector<std::uint8_t>& set, const std::vector<Cell>& robots,
                   const std::vector<std::vector<Cell>>& routes) {
  for (const std::string& p : check_cover_routes(map, set, robots, routes)) ADD_FAILURE() << p;
}

// A robot whose nearest cell of the set lies in a sliver of it (two cells cut off from the rest,
// as an orphan piece another division gave its group) starts in the large piece instead: it
// would get nothing else. The sliver goes to the nearest robot, and the routes cover everything.
TEST(CoverRoutes, ARobotDoesNotStartInASliverOfTheSet) {
  const auto art = swarm::test::ascii_map({
      "..........",
      "..........",
      "..........",
      "#########.",
      "S..A.....B",
  });
  std::vector<std::uint8_t> set = free_cells(art.grid);
  for (int x = 2; x < 10; ++x) set[static_cast<std::size_t>(art.grid.index({x, 0}))] = 0;  // the corridor: not to cover
  const std::vector<Cell> robots = {art.at.at('A'), art.at.at('B')};
  // The corridor (not in the set) joins S's sliver, (0, 0) and (1, 0), to the room: A is 2 steps
  // from the sliver and 7 from the room.
  const CoverRoutes r = divide_and_route(art.grid, set, robots, {}, CoverRoutesConfig{});
  EXPECT_GT(r.region_cells[0], 10) << "robot A started in the sliver";
  EXPECT_GT(r.region_cells[1], 10);
  // Each route covers the piece its region grew from (not the sliver, which is nearer to A; the
  // live task divides what is left again once the routes are driven).
  std::vector<std::uint8_t> sliver(set.size(), 0);
  sliver[static_cast<std::size_t>(art.grid.index({0, 0}))] = sliver[static_cast<std::size_t>(art.grid.index({1, 0}))] = 1;
  std::vector<std::uint8_t> room = set;
  for (std::size_t i = 0; i < set.size(); ++i) room[i] = set[i] && !sliver[i];
  expect_covers(art.grid, room, robots, r.routes);
}

TEST(CoverRoutes, TwoRobotsOnAnOpenRoomSplitItEquallyAndCoverEveryCell) {
  const OccupancyGrid map(10, 6, 0.2, 0.0, 0.0, CellState::Free);
  const std::vector<Cell> robots = {{0, 0}, {9, 5}};
  CoverRoutesConfig cfg;
  cfg.darp.init = DarpInit::Given;
  const CoverRoutes r = divide_and_route(map, free_cells(map), robots, {}, cfg);
  EXPECT_EQ(r.darp.status, DarpStatus::Converged);
  EXPECT_EQ(r.region_cells, (std::vector<int>{30, 30}));
  expect_covers(map, free_cells(map), robots, r.routes);
  // Each robot stands in its own region: STC visits each of its 30 cells, 29 steps at the least.
  for (const auto& route : r.routes) EXPECT_GE(route.size(), 30u);
}

// A comb: one-cell teeth off a spine, each swept there and back. Of the divisions tried, the one
// whose longest route is shortest is kept: never longer than the first, every cell still covered.
TEST(CoverRoutes, OfSeveralDivisionsTheOneWithTheShortestLongestRouteIsKept) {
  std::vector<std::string> rows;
  for (int y = 0; y < 14; ++y) {
    std::string row;
    for (int x = 0; x < 25; ++x) row += (y == 13 || y == 12 || x % 3 == 0) ? '.' : '#';
    rows.push_back(row);
  }
  const OccupancyGrid map = swarm::test::grid_from(rows);
  const std::vector<Cell> robots = {{0, 0}, {1, 0}, {2, 0}};
  CoverRoutesConfig one;
  one.darp.init = DarpInit::Given;
  CoverRoutesConfig three = one;
  three.candidates = 3;
  const CoverRoutes first = divide_and_route(map, free_cells(map), robots, {}, one);
  const CoverRoutes best = divide_and_route(map, free_cells(map), robots, {}, three);
  EXPECT_EQ(first.candidates_tried, 1);
  EXPECT_EQ(best.candidates_tried, 3);
  EXPECT_EQ(best.darp.status, DarpStatus::Converged);
  // Measured: 96 moves from the robots' own cells, 92 from K-Means starts (candidate 1).
  EXPECT_EQ(longest(first), 96u);
  EXPECT_EQ(longest(best), 92u);
  EXPECT_EQ(best.chosen, 1);
  expect_covers(map, free_cells(map), robots, first.routes);
  expect_covers(map, free_cells(map), robots, best.routes);
}

// Equal cells are not equal work: on the left a comb of one-cell teeth, each swept there and back,
// on the right open floor, swept once. Balancing rounds give the comb's robots fewer cells and the
// floor's more, and the longest route comes down; every cell is still covered.
TEST(CoverRoutes, BalancingRoundsDivideByWorkAndShortenTheLongestRoute) {
  std::vector<std::string> rows;
  for (int y = 0; y < 12; ++y) {
    std::string row;
    for (int x = 0; x < 30; ++x) row += (x >= 16 || y == 11 || x % 2 == 0) ? '.' : '#';
    rows.push_back(row);
  }
  const OccupancyGrid map = swarm::test::grid_from(rows);
  const std::vector<Cell> robots = {{0, 11}, {8, 11}, {20, 11}, {28, 11}};
  CoverRoutesConfig cells_alone;
  cells_alone.candidates = 3;
  CoverRoutesConfig by_work = cells_alone;
  by_work.balance_rounds = 16;
  const CoverRoutes a = divide_and_route(map, free_cells(map), robots, {}, cells_alone);
  const CoverRoutes b = divide_and_route(map, free_cells(map), robots, {}, by_work);
  EXPECT_EQ(a.balance_rounds, 0);
  EXPECT_EQ(b.balance_rounds, 16);
  EXPECT_GE(b.chosen, 3) << "no balancing round was kept";
  // Measured: the longest route 109 cells long (108 moves) with equal cells (272 cells, 68 each),
  // 85 (84 moves) with the comb's robots given 52 and 55 cells and the floor's 82 and 83.
  EXPECT_EQ(longest(a), 109u);
  EXPECT_EQ(longest(b), 85u);
  EXPECT_EQ(b.region_cells, (std::vector<int>{52, 55, 82, 83}));
  expect_covers(map, free_cells(map), robots, a.routes);
  expect_covers(map, free_cells(map), robots, b.routes);
}

TEST(CoverRoutes, RobotsOutsideTheSetDriveToItsNearestCellsFirst) {
  const auto art = swarm::test::ascii_map({
      "A.........",
      "##.#######",
      "....B.....",
      "..........",
  });
  const OccupancyGrid& map = art.grid;
  std::vector<std::uint8_t> set(map.size(), 0);  // the lower room only
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 10; ++x) set[static_cast<std::size_t>(map.index({x, y}))] = 1;
  }
  const std::vector<Cell> robots = {art.at.at('A'), art.at.at('B')};
  const CoverRoutes r = divide_and_route(map, set, robots, {}, CoverRoutesConfig{});
  EXPECT_EQ(r.starts[0], (Cell{2, 1}));  // through the door (2, 2)
  EXPECT_EQ(r.starts[1], (Cell{4, 1}));
  expect_covers(map, set, robots, r.routes);
  EXPECT_EQ(r.routes[0][1], (Cell{1, 3}));  // A leaves its room first
}

TEST(CoverRoutes, APieceWithNoRobotGoesToTheNearest) {
  // Two rooms joined by a corridor that is not in the set: DARP cannot reach the right room's
  // piece from the robot in the left one; it is assigned anyway (the live task divides it again
  // once the route is driven).
  const auto art = swarm::test::ascii_map({
      "R..#...",
      "......." ,
      "...#...",
  });
  const OccupancyGrid& map = art.grid;
  std::vector<std::uint8_t> set = free_cells(map);
  set[static_cast<std::size_t>(map.index({3, 1}))] = 0;  // the doorway is already covered
  const CoverRoutes r = divide_and_route(map, set, {art.at.at('R')}, {}, CoverRoutesConfig{});
  EXPECT_EQ(r.region_cells[0], 18);  // both pieces are its
  // The route covers the left piece, the one its robot stands in.
  std::vector<std::uint8_t> left = set;
  for (int x = 4; x < 7; ++x) {
    for (int y = 0; y < 3; ++y) left[static_cast<std::size_t>(map.index({x, y}))] = 0;
  }
  expect_covers(map, left, {art.at.at('R')}, r.routes);
}

}  // namespace
}  // namespace swarm::planner
