// The pieces of a set of cells and the cells that join them, on drawings where they can be
// counted by eye.
#include "swarm/planner/coverage/region_graph.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::planner {
namespace {

// Every Free cell but those marked by `covered` (letters of the drawing).
std::vector<std::uint8_t> set_without(const swarm::test::AsciiMap& art, const std::string& covered) {
  std::vector<std::uint8_t> m(art.grid.size(), 0);
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = art.grid.at(static_cast<int>(i)) == CellState::Free;
  for (const char l : covered) m[static_cast<std::size_t>(art.grid.index(art.at.at(l)))] = 0;
  return m;
}

int pieces(const OccupancyGrid& map, const std::vector<std::uint8_t>& mask) {
  int count = 0;
  (void)components(RegionGraph::build(region_grid(map, mask)), count);
  return count;
}

// join_pieces on `set`: the pieces before and after, and the cells it added (row-major order).
struct Joined {
  int before = 0, after = 0;
  std::vector<Cell> added;
};

Joined join(const OccupancyGrid& map, const std::vector<std::uint8_t>& set) {
  int reported = -1;
  const std::vector<std::uint8_t> joined = join_pieces(map, set, &reported);
  Joined out{pieces(map, set), pieces(map, joined), {}};
  EXPECT_EQ(reported, out.before);
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const auto i = static_cast<std::size_t>(map.index({x, y}));
      EXPECT_TRUE(set[i] <= joined[i]) << "a cell of the set was taken out";
      if (joined[i] && !set[i]) out.added.push_back({x, y});
    }
  }
  return out;
}

// Two rooms of 3 x 3 behind a one-cell door, a robot (A) standing in it: two pieces, joined by
// A's cell and nothing else.
TEST(JoinPieces, ARobotInAOneCellDoorJoinsTheRooms) {
  const auto art = swarm::test::ascii_map({
      "...#...",
      "...A...",
      "...#...",
  });
  const Joined j = join(art.grid, set_without(art, "A"));
  EXPECT_EQ(j.before, 2);
  EXPECT_EQ(j.after, 1);
  EXPECT_EQ(j.added, std::vector<Cell>{art.at.at('A')});
}

// The office plan's case: robot A in a one-cell door, robot B right behind it in the room. The
// room is still one piece around B, but the door cell touches no cell of it: the rooms are joined
// through both robots' cells.
TEST(JoinPieces, ARobotInADoorAndOneBehindItAreBothAdded) {
  const auto art = swarm::test::ascii_map({
      "...#...",
      "...AB..",
      "...#...",
  });
  const Joined j = join(art.grid, set_without(art, "AB"));
  EXPECT_EQ(j.before, 2);
  EXPECT_EQ(j.after, 1);
  EXPECT_EQ(j.added, (std::vector<Cell>{art.at.at('A'), art.at.at('B')}));
}

// Robots in the open (A) or against a wall (B) split nothing: the set comes back as it was.
TEST(JoinPieces, ACellInsideOnePieceIsNotAdded) {
  const auto art = swarm::test::ascii_map({
      ".....",
      ".A...",
      "....B",
  });
  const Joined j = join(art.grid, set_without(art, "AB"));
  EXPECT_EQ(j.before, 1);
  EXPECT_TRUE(j.added.empty());
}

// A two-cell door with a robot in each cell: one of them is enough to join the rooms. A third
// piece, a cell walled off from the rest, no path reaches: it stays apart.
TEST(JoinPieces, OnePathJoinsTwoPiecesAndAWalledOffPieceStaysApart) {
  const auto art = swarm::test::ascii_map({
      "...#...",
      "...A...",
      "...B...",
      "...#...",
      "#######",
      ".######",
  });
  const Joined j = join(art.grid, set_without(art, "AB"));
  EXPECT_EQ(j.before, 3);
  EXPECT_EQ(j.after, 2);
  ASSERT_EQ(j.added.size(), 1u);
  EXPECT_TRUE(j.added[0] == art.at.at('A') || j.added[0] == art.at.at('B'));
}

// From the largest piece the nearest is joined first, by the shortest way, then the next: a
// corridor stub two covered cells (a, b) from the big room, and one cell (X) three covered cells
// from it along the top row.
TEST(JoinPieces, TheNearestPieceIsJoinedByTheShortestWay) {
  const auto art = swarm::test::ascii_map({
      "X........",
      "#####....",
      "..ab.....",
      "#####....",
  });
  std::vector<std::uint8_t> set = set_without(art, "ab");
  for (int x = 1; x <= 3; ++x) set[static_cast<std::size_t>(art.grid.index({x, 3}))] = 0;  // covered
  const Joined j = join(art.grid, set);
  EXPECT_EQ(j.before, 3);
  EXPECT_EQ(j.after, 1);
  // a and b join the stub; the top row's three covered cells join X.
  EXPECT_EQ(j.added, (std::vector<Cell>{art.at.at('a'), art.at.at('b'), Cell{1, 3}, Cell{2, 3}, Cell{3, 3}}));
}

}  // namespace
}  // namespace swarm::planner
