// What a phase's task fixes in advance at load (its registry row's `resolve`), and bad input in it
// named by field: mapf goals (tasks/mapf/mapf_goals.hpp), collect objects and destinations
// (tasks/collect/collect_world.hpp).
#include <gtest/gtest.h>

#include <any>
#include <functional>

#include "swarm/config/scenario.hpp"
#include "swarm/tasks/collect/collect_world.hpp"
#include "swarm/tasks/mapf/mapf_goals.hpp"
#include "swarm/tasks/registry.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/text.hpp"

namespace swarm::tasks {
namespace {

using planner::Cell;

// 6 x 3 cells of 0.2 m: a wall at x = 3 in the middle row.
planner::OccupancyGrid room() { return swarm::test::grid_from({"......", "...#..", "......"}); }

swarm::scenario::Phase phase_from(const std::string& text) {
  const auto s = config::parse_scenario_text("mission { phase { " + text + " } }", "test");
  return s.mission().phase(0);
}

std::string error_of(const std::function<void()>& f) { return swarm::test::error_of<config::ConfigError>(f); }

TEST(MapfGoals, PointsBecomeCellsAndBadOnesAreNamed) {
  const auto map = room();
  const auto ok = phase_from("mapf { goals { x: 0.1 y: 0.1 } goals { x: 1.1 y: 0.5 } }");
  EXPECT_EQ(mapf_goals(ok.mapf(), map, 2, "f"), (std::vector<Cell>{{0, 0}, {5, 2}}));
  EXPECT_TRUE(mapf_goals(phase_from("mapf {}").mapf(), map, 2, "f").empty());  // random, later
  EXPECT_EQ(error_of([&] { (void)mapf_goals(phase_from("mapf { goals { x: 0.7 y: 0.3 } }").mapf(), map, 1, "f"); }),
            "f.goals[0] (robot 0): the goal, cell (3, 1), is not a free cell of the map");
  EXPECT_EQ(error_of([&] { (void)mapf_goals(phase_from("mapf { goals { x: 5 y: 0.1 } }").mapf(), map, 1, "f"); }),
            "f.goals[0] (robot 0): the goal is outside the map");
  EXPECT_EQ(error_of([&] {
              (void)mapf_goals(phase_from("mapf { goals { x: 0.1 y: 0.1 } goals { x: 0.15 y: 0.15 } }").mapf(), map, 2, "f");
            }),
            "f.goals[1] (robot 1): another robot has the same goal cell (0, 0)");
}

TEST(CollectWorld, ScatteredObjectsAreDistinctReachableAndDeterministic) {
  const auto map = room();
  const auto c = phase_from("collect { scatter: 2 types: 2 }").collect();
  const CollectWorld a = collect_world(c, map, {{0, 0}}, 7, "f");
  const CollectWorld b = collect_world(c, map, {{0, 0}}, 7, "f");
  ASSERT_EQ(a.objects.size(), 4u);
  ASSERT_EQ(a.destinations.size(), 2u);
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(a.objects[i].cell, b.objects[i].cell);
    EXPECT_EQ(a.objects[i].type, static_cast<int>(i / 2));
    EXPECT_TRUE(map.is_free(a.objects[i].cell));
    EXPECT_NE(a.objects[i].cell, (Cell{0, 0}));  // not a robot's start cell
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(a.objects[i].cell, a.objects[j].cell);
  }
}

TEST(CollectWorld, BadObjectsAndDestinationsAreNamed) {
  const auto map = room();
  EXPECT_EQ(error_of([&] {
              (void)collect_world(phase_from("collect { objects { at { x: 0.7 y: 0.3 } type: 0 } destinations { x: 0.1 y: 0.1 } }").collect(),
                                  map, {{0, 0}}, 1, "f");
            }),
            "f.objects[0]: on a cell that is not free");
  EXPECT_EQ(error_of([&] {
              (void)collect_world(phase_from("collect { objects { at { x: 0.3 y: 0.1 } type: 1 } destinations { x: 0.1 y: 0.1 } }").collect(),
                                  map, {{0, 0}}, 1, "f");
            }),
            "f.objects[0]: its type 1 has no destination (1 given)");
  EXPECT_EQ(error_of([&] {
              (void)collect_world(phase_from("collect { destinations { x: 9 y: 9 } }").collect(), map, {{0, 0}}, 1, "f");
            }),
            "f.destinations[0]: outside the map");
  // A free cell walled in on four sides (no diagonal cuts a corner): no robot can reach it.
  const auto pocket = swarm::test::grid_from({"..#...", ".#.#..", "..#..."});
  EXPECT_EQ(error_of([&] {
              (void)collect_world(phase_from("collect { objects { at { x: 0.5 y: 0.3 } type: 0 } destinations { x: 0.1 y: 0.1 } }").collect(),
                                  pocket, {{0, 0}}, 1, "f");
            }),
            "f.objects[0]: no robot can reach it");
}

TEST(ResolveMission, EachPhaseGetsItsGoalsOrObjects) {
  config::World w;
  w.scenario = config::parse_scenario_text(
      "groups: 1 robots_per_group: 2 "
      "mission { phase { explore {} } phase { mapf { goals { x: 0.1 y: 0.1 } goals { x: 1.1 y: 0.5 } } }"
      " phase { collect { types: 1 objects { at { x: 0.3 y: 0.1 } type: 0 } destinations { x: 0.1 y: 0.5 } } } }",
      "t");
  w.truth = room();
  w.robot_cells = {{0, 1}, {1, 1}};
  w.frame = config::MapFrame::of(w.truth);
  resolve_mission(w, "t");
  ASSERT_EQ(w.phase_data.size(), 3u);
  EXPECT_FALSE(w.phase_data[0].has_value());  // exploration fixes nothing in advance
  EXPECT_EQ(std::any_cast<const std::vector<Cell>&>(w.phase_data[1]), (std::vector<Cell>{{0, 0}, {5, 2}}));
  const auto& c = std::any_cast<const CollectWorld&>(w.phase_data[2]);
  ASSERT_EQ(c.objects.size(), 1u);
  EXPECT_EQ(c.objects[0].cell, (Cell{1, 0}));
  EXPECT_EQ(c.destinations, (std::vector<Cell>{{0, 2}}));
  // A bad goal is named by its phase.
  w.scenario = config::parse_scenario_text(
      "groups: 1 robots_per_group: 2 mission { phase { mapf { goals { x: 0.7 y: 0.3 } goals { x: 0.1 y: 0.1 } } } }", "t");
  EXPECT_NE(error_of([&] { resolve_mission(w, "s"); }).find("s: mission.phase[0].mapf"), std::string::npos);
}

}  // namespace
}  // namespace swarm::tasks
