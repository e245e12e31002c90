// Tour files (planner/tours/tour_file.hpp) parsed from text: cells shifted by the origin, types
// numbered by their destinations, a `map` line read through the caller's loader with the file's
// folder, and bad input named by file and line.
#include "swarm/planner/tours/tour_file.hpp"

#include <gtest/gtest.h>

#include "swarm_test/text.hpp"

namespace swarm::planner {
namespace {

OccupancyGrid no_map(const std::string&, const std::string&) { throw std::runtime_error("no maps here"); }

TEST(TourFile, CellsTypesAndHeadingsFromText) {
  const TourFile f = parse_tour_file(
      "size 6 4   # a room\norigin -3 -2\nstart 0 -2 right\nafter-drop down\n"
      "destination paper 2 1\ndestination can -3 1\nobject can 1 0 fixed\nobject paper -1 -1\nobstacle 0 0 0 1\n",
      "dir/t.tour", no_map);
  EXPECT_EQ(f.map.width(), 6);
  EXPECT_EQ(f.map.height(), 4);
  EXPECT_EQ(f.origin, (Cell{-3, -2}));
  EXPECT_EQ(f.problem.start, (Cell{3, 0}));
  EXPECT_EQ(f.problem.start_heading, kHeadingRight);
  EXPECT_EQ(f.problem.heading_after_drop, kHeadingDown);
  EXPECT_EQ(f.type_names, (std::vector<std::string>{"paper", "can"}));
  EXPECT_EQ(f.problem.destinations, (std::vector<Cell>{{5, 3}, {0, 3}}));
  ASSERT_EQ(f.problem.objects.size(), 2u);
  EXPECT_EQ(f.problem.objects[0].cell, (Cell{4, 2}));
  EXPECT_EQ(f.problem.objects[0].type, 1);
  EXPECT_EQ(f.problem.objects[1].cell, (Cell{2, 1}));
  EXPECT_EQ(f.problem.objects[1].type, 0);
  EXPECT_EQ(f.fixed, (std::vector<bool>{true, false}));
  EXPECT_EQ(f.object_lines, (std::vector<int>{7, 8}));
  EXPECT_TRUE(f.map.is_occupied({3, 2}));  // the obstacle, in file coordinates (0, 0)..(0, 1)
  EXPECT_TRUE(f.map.is_occupied({3, 3}));
  EXPECT_EQ(f.map_text, "6 x 4 cells, 1 obstacle blocks");
}

TEST(TourFile, AMapLineGoesToTheLoaderWithTheFilesFolder) {
  std::string asked;
  const TourFile f = parse_tour_file("map room.yaml\nstart 1 1\n", "scenarios/tour/t.tour",
                                     [&](const std::string& name, const std::string& folder) {
                                       asked = folder + "|" + name;
                                       return OccupancyGrid(3, 3, 0.1, 0, 0, CellState::Free);
                                     });
  EXPECT_EQ(asked, "scenarios/tour|room.yaml");
  EXPECT_EQ(f.problem.start, (Cell{1, 1}));
}

TEST(TourFile, BadInputIsNamedByFileAndLine) {
  const auto error = [](const std::string& text) {
    return swarm::test::error_of<TourFileError>([&] { (void)parse_tour_file(text, "t.tour", no_map); });
  };
  EXPECT_EQ(error("size 4 4\nstart 0 0\nfly 1 2\n"),
            "t.tour:3: unknown statement 'fly'; expected size, map, origin, start, after-drop, destination, object or "
            "obstacle");
  EXPECT_EQ(error("size 4 4\nstart 0 x\n"), "t.tour:2: 'start' takes X Y [HEADING]; 'x' is not an integer");
  EXPECT_EQ(error("size 4 4\nstart 0 0\nobject paper 1 1\n"),
            "t.tour:3: type 'paper' has no destination (add a line 'destination paper X Y')");
  EXPECT_EQ(error("map m\nstart 0 0\n"), "t.tour:1: map 'm': no maps here");
  EXPECT_EQ(error("start 0 0\n"), "t.tour: no 'size W H' or 'map NAME' line: the tour needs a map");
}

}  // namespace
}  // namespace swarm::planner
