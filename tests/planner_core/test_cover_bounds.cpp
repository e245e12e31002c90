// Lower bounds on a coverage makespan: worked by hand on small maps, and never above what the
// tours (an independent planner) achieve on the warehouse, where the chessboard colouring makes
// ⌈cells / robots⌉ far too low.
#include "swarm/planner/coverage/cover_bounds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "swarm/planner/coverage/cover_tours.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/data.hpp"

namespace swarm::planner {
namespace {

// Every Free cell but those under a robot.
std::vector<std::uint8_t> uncovered(const OccupancyGrid& g, const std::vector<Cell>& robots) {
  std::vector<std::uint8_t> m(g.size(), 0);
  for (std::size_t i = 0; i < g.size(); ++i) m[i] = g.at(static_cast<int>(i)) == CellState::Free;
  for (const Cell r : robots) m[static_cast<std::size_t>(g.index(r))] = 0;
  return m;
}

// The bounds for robots on the drawing's cells marked by `letters`, every other free cell to cover.
CoverBounds bounds_of(const swarm::test::AsciiMap& art, const std::string& letters) {
  std::vector<Cell> robots;
  for (const char l : letters) robots.push_back(art.at.at(l));
  return cover_bounds(art.grid, uncovered(art.grid, robots), robots);
}

// One robot at the end of a corridor of 10 cells: 9 moves, whichever bound says it.
TEST(CoverBounds, ACorridorTakesItsLength) {
  const auto art = swarm::test::ascii_map({"A........."});
  const CoverBounds b = bounds_of(art, "A");
  EXPECT_TRUE(b.reachable);
  EXPECT_EQ(b.reach_moves, 9);
  // 5 cells of the other colour than A's (1, 3, 5, 7, 9): ⌈k/2⌉ >= 5 needs k = 9.
  EXPECT_EQ(b.colour_moves, 9);
}

// Crossings (x and y even) joined by passages: every passage cell's neighbours are crossings, so
// each robot, starting on a crossing, lands on a passage cell every other move. 17 passage cells
// for 3 robots need ⌈k/2⌉ >= 6, k = 11 moves, where 26 cells over 3 robots would say 9 and the
// farthest cell 5.
TEST(CoverBounds, ALatticeNeedsAMoveIntoEveryPassageAndOneOut) {
  const auto art = swarm::test::ascii_map({
      "C......",
      ".#.#.#.",
      ".......",
      ".#.#.#.",
      "A.....B",
  });
  const CoverBounds b = bounds_of(art, "ABC");
  EXPECT_TRUE(b.reachable);
  EXPECT_EQ(b.reach_moves, 5);
  EXPECT_EQ(b.colour_moves, 11);
}

TEST(CoverBounds, ACellNoRobotReachesIsSaid) {
  const auto art = swarm::test::ascii_map({"A.#.."});
  const CoverBounds b = bounds_of(art, "A");
  EXPECT_FALSE(b.reachable);
  EXPECT_EQ(b.reach_moves, 1);
}

// The whole warehouse-5x8 (67 of its 107 cells are passage cells) from ten random placements of
// 9 robots (the same placements as CoverTours.WholeWarehouseFromRandomPlacementsNearItsBound): no
// tour is shorter than the colour bound, and on 8 of the 10 the tours reach it, so they are
// optimal there. ⌈cells / robots⌉ (12) is short of both.
TEST(CoverBounds, NoTourOnTheWarehouseBeatsTheColourBound) {
  const OccupancyGrid g = load_map_yaml(swarm::test::source_dir() + "/maps/warehouse-5x8.yaml");
  std::vector<Cell> free;
  for (int i = 0; i < static_cast<int>(g.size()); ++i) {
    if (g.at(i) == CellState::Free) free.push_back(g.cell_of(i));
  }
  std::vector<std::uint8_t> every(g.size(), 0);
  for (const Cell c : free) every[static_cast<std::size_t>(g.index(c))] = 1;
  int colour = 0, tours = 0, at_bound = 0;
  for (int seed = 1; seed <= 10; ++seed) {
    Rng rng(static_cast<std::uint64_t>(seed));
    std::vector<Cell> cells = free;
    for (std::size_t i = cells.size(); i > 1; --i) std::swap(cells[i - 1], cells[static_cast<std::size_t>(rng.below(i))]);
    const std::vector<Cell> robots(cells.begin(), cells.begin() + 9);
    const CoverBounds b = cover_bounds(g, uncovered(g, robots), robots);
    const CoverTours t = cover_tours(g, every, robots);
    ASSERT_TRUE(t.solved);
    const int longest = static_cast<int>(longest_moves(t.routes));
    EXPECT_GE(longest, b.colour_moves) << seed;
    EXPECT_GE(longest, b.reach_moves) << seed;
    EXPECT_GT(b.colour_moves, 12) << seed;
    colour += b.colour_moves;
    tours += longest;
    at_bound += longest == b.colour_moves ? 1 : 0;
  }
  EXPECT_EQ(colour, 142);
  EXPECT_EQ(tours, 144);
  EXPECT_EQ(at_bound, 8);  // optimal there: no tour can be shorter
}

}  // namespace
}  // namespace swarm::planner
