// Spanning-tree coverage: every path goes through check_coverage_path (coverage_check.hpp), the
// independent validator; lengths and turns are checked against hand-counted values.
#include <gtest/gtest.h>

#include "swarm/planner/coverage/coverage_check.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm/planner/coverage/stc.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace {

using namespace swarm::planner;
using swarm::test::ascii_map;
using swarm::test::grid_from;

void expect_valid(const OccupancyGrid& region, Cell start, const StcPath& p) {
  ASSERT_EQ(p.status, StcStatus::Ok);
  const std::vector<std::string> problems = check_coverage_path(region, start, p.cells);
  for (const std::string& s : problems) ADD_FAILURE() << s;
  EXPECT_EQ(p.length, static_cast<int>(p.cells.size()) - 1);
  EXPECT_EQ(p.turns, count_turns(p.cells).quarter_turns());
  EXPECT_EQ(p.revisits, static_cast<int>(p.cells.size()) - p.covered);
}

// Covers the art's Free cells from 'S' and validates the path.
StcPath cover(const swarm::test::AsciiMap& m) {
  const StcPath p = spanning_tree_coverage(m.grid, m.at.at('S'));
  expect_valid(m.grid, m.at.at('S'), p);
  return p;
}

TEST(CountTurns, CountsQuarterTurnsOnceAndReversalsTwice) {
  EXPECT_EQ(count_turns({{0, 0}, {1, 0}, {2, 0}}).quarter_turns(), 0);
  EXPECT_EQ(count_turns({{0, 0}, {1, 0}, {1, 1}}).quarter_turns(), 1);
  EXPECT_EQ(count_turns({{0, 0}, {1, 0}, {0, 0}}).quarter_turns(), 2);
  EXPECT_EQ(count_turns({{0, 0}, {1, 0}, {1, 1}, {0, 1}}).quarter_turns(), 2);
  EXPECT_EQ(count_turns({{0, 0}}).quarter_turns(), 0);
}

TEST(Stc, OneCellIsAPathOfLengthZero) {
  const auto m = ascii_map({"#S#"});
  const StcPath p = cover(m);
  EXPECT_EQ(p.cells.size(), 1u);
  EXPECT_EQ(p.turns, 0);
}

TEST(Stc, TwoByTwoBlockIsALoopOfThreeMovesAndTwoTurns) {
  const auto m = ascii_map({"..", "S."});
  const StcPath p = cover(m);
  EXPECT_EQ(p.length, 3);
  EXPECT_EQ(p.turns, 2);
  EXPECT_EQ(p.revisits, 0);
}

// Whole 2 x 2 blocks only: STC visits every cell exactly once (a Hamiltonian path).
TEST(Stc, RegionOfWholeBlocksIsCoveredWithoutRepeats) {
  const auto m = ascii_map({
      "........",
      "........",
      "..##....",
      "..##....",
      "S.......",
      "........",
  });
  const StcPath p = cover(m);
  EXPECT_EQ(p.covered, 44);
  EXPECT_EQ(p.revisits, 0);
  EXPECT_EQ(p.length, 43);
}

// A 4 x 4 square from a corner: 15 moves, no repeat, and 6 turns, as few as the boustrophedon
// (R R R U L L L U R R R U L L L).
TEST(Stc, FourByFourSquareTakesFifteenMovesAndSixTurns) {
  const auto m = ascii_map({"....", "....", "....", "S..."});
  const StcPath p = cover(m);
  EXPECT_EQ(p.length, 15);
  EXPECT_EQ(p.revisits, 0);
  EXPECT_EQ(p.turns, 6);
}

// Odd widths and heights leave partial blocks on every lattice placement. A 3 x 3 square from a
// corner still has a path without repeats (8 moves: 00 10 20 21 22 12 11 01 02, 5 turns); a 5 x 5
// square costs one repeat (25 moves for 24 new cells): the L-shaped partial blocks of its border.
TEST(Stc, PartialBlocksAreCoveredWithFewRepeats) {
  const auto m = ascii_map({"...", "...", "S.."});
  const StcPath p = cover(m);
  EXPECT_EQ(p.covered, 9);
  EXPECT_EQ(p.length, 8);
  EXPECT_EQ(p.revisits, 0);
  EXPECT_EQ(p.turns, 5);
  const OccupancyGrid five(5, 5, 0.2, 0, 0, CellState::Free);
  const StcPath q = spanning_tree_coverage(five, {0, 0});
  expect_valid(five, {0, 0}, q);
  EXPECT_EQ(q.length, 25);
  EXPECT_EQ(q.revisits, 1);
}

TEST(Stc, OneCellWideCorridorIsWalkedOnce) {
  const auto m = ascii_map({"S......"});
  const StcPath p = cover(m);
  EXPECT_EQ(p.length, 6);
  EXPECT_EQ(p.turns, 0);
}

// A corridor with the start in the middle must go one way and come back.
TEST(Stc, StartInTheMiddleOfACorridorWalksOneSideTwice) {
  const auto m = ascii_map({"..S...."});
  const StcPath p = cover(m);
  EXPECT_EQ(p.length, 2 + 2 + 4);  // to the near end (2), back (2), to the far end (4)
  EXPECT_EQ(p.revisits, 2);
}

TEST(Stc, DiagonalCellsOfOneBlockAreSeparateNodes) {
  // (0,0) and (1,1) are in the same 2 x 2 block for lattice (0, 0) but not adjacent.
  const auto m = ascii_map({
      "#...",
      "S#..",
  });
  const StcPath p = spanning_tree_coverage(m.grid, m.at.at('S'));
  EXPECT_EQ(p.covered, 1);  // S touches no other free cell
  EXPECT_EQ(p.left_out, 5);
  const auto n = ascii_map({
      ".S..",
      "..#.",
      "....",
  });
  cover(n);
}

TEST(Stc, DisconnectedRegionCoversTheStartsPieceAndReportsTheRest) {
  const auto m = ascii_map({
      "S..#..",
      "...#..",
  });
  const StcPath p = cover(m);
  EXPECT_EQ(p.covered, 6);
  EXPECT_EQ(p.left_out, 4);
}

TEST(Stc, StartOutsideTheRegionIsAStatus) {
  const auto m = ascii_map({"S#.."});
  const StcPath p = spanning_tree_coverage(m.grid, {1, 0});
  EXPECT_EQ(p.status, StcStatus::StartOutsideRegion);
  EXPECT_TRUE(p.cells.empty());
}

// Random blobs (ragged borders, holes, partial blocks everywhere): every path valid, and the
// repeats stay a small fraction of the cells.
TEST(Stc, RandomRegionsAreAlwaysFullyCovered) {
  Rng rng(7);
  for (int trial = 0; trial < 60; ++trial) {
    const int w = rng.uniform_int(3, 30), h = rng.uniform_int(3, 30);
    OccupancyGrid g(w, h, 0.2, 0, 0, CellState::Occupied);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (rng.bernoulli(0.8)) g.set({x, y}, CellState::Free);
      }
    }
    Cell start{rng.uniform_int(0, w - 1), rng.uniform_int(0, h - 1)};
    g.set(start, CellState::Free);
    const StcPath p = spanning_tree_coverage(g, start);
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_valid(g, start, p);
    EXPECT_LE(p.revisits, p.covered) << "at most one repeat per cell on these blobs";
  }
}

TEST(Stc, IsDeterministic) {
  const OccupancyGrid g = grid_from({
      "..........",
      ".##....#..",
      "......##..",
      "..#.......",
      "..........",
  });
  const StcPath a = spanning_tree_coverage(g, {0, 0});
  const StcPath b = spanning_tree_coverage(g, {0, 0});
  EXPECT_EQ(a.cells, b.cells);
}

// Doing at least as well as a single lattice placement (the reference's only one).
TEST(Stc, AllLatticePlacementsNeverLoseToOne) {
  const OccupancyGrid g = grid_from({
      ".........",
      ".........",
      "...##....",
      ".........",
      ".........",
  });
  StcConfig one;
  one.all_lattice_offsets = false;
  const StcPath a = spanning_tree_coverage(g, {0, 0});
  const StcPath b = spanning_tree_coverage(g, {0, 0}, one);
  EXPECT_TRUE(a.length < b.length || (a.length == b.length && a.turns <= b.turns));
}

}  // namespace
