// The traffic planner (planner/traffic/traffic.hpp): every window it plans is checked step by step
// against the simulator's own conflict rule (find_step_conflicts) and the motion model, and robots
// reach their goals in the places where robots usually gridlock: a one-cell corridor, a ring, a
// door between two rooms, a dead robot in the way.
#include "swarm/planner/traffic/traffic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm_test/data.hpp"
#include "swarm_test/free_region.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace swarm::planner::traffic {
namespace {

// The independent check of one window: each path starts where its robot stands and has steps + 1
// cells; every step is a legal action of the motion model; no two robots share a cell or swap in
// any step; a fixed robot never moves; each goal behind a robot was stood on at the path index
// reached_at gives, in order, or is one of its skipped goals.
void expect_valid(const OccupancyGrid& map, MotionModel motion, const std::vector<Agent>& agents, const Window& w,
                  int steps) {
  ASSERT_EQ(w.paths.size(), agents.size());
  ASSERT_EQ(w.reached_at.size(), agents.size());
  for (std::size_t a = 0; a < agents.size(); ++a) {
    ASSERT_EQ(w.paths[a].size(), static_cast<std::size_t>(steps) + 1) << "robot " << a;
    EXPECT_EQ(w.paths[a][0], agents[a].at) << "robot " << a;
    ASSERT_EQ(w.reached_at[a].size(), static_cast<std::size_t>(w.done[a])) << "robot " << a;
    int last = 0;
    std::size_t skipped = 0;
    for (std::size_t g = 0; g < w.reached_at[a].size(); ++g) {
      const int i = w.reached_at[a][g];
      if (i < 0) {
        ++skipped;
        EXPECT_TRUE(agents[a].fixed || std::find(w.skipped[a].begin(), w.skipped[a].end(), static_cast<int>(g)) !=
                                           w.skipped[a].end())
            << "robot " << a << " goal " << g;
        continue;
      }
      EXPECT_GE(i, last) << "robot " << a << " goal " << g;
      ASSERT_LE(i, steps);
      EXPECT_EQ(w.paths[a][static_cast<std::size_t>(i)], agents[a].goals[g]) << "robot " << a << " goal " << g;
      last = i;
    }
    if (!agents[a].fixed) EXPECT_EQ(skipped, w.skipped[a].size()) << "robot " << a;
  }
  for (int s = 0; s < steps; ++s) {
    std::vector<Cell> from;
    std::vector<Cell> to;
    for (std::size_t a = 0; a < agents.size(); ++a) {
      from.push_back(w.paths[a][static_cast<std::size_t>(s)]);
      to.push_back(w.paths[a][static_cast<std::size_t>(s) + 1]);
      EXPECT_TRUE(motion.legal(map, from.back(), to.back())) << "robot " << a << " step " << s;
      if (agents[a].fixed) {
        EXPECT_EQ(from.back(), to.back()) << "fixed robot " << a << " moved";
      }
    }
    const StepConflicts c = find_step_conflicts(from, to);
    EXPECT_TRUE(c.empty()) << c.vertex.size() << " vertex and " << c.edge.size() << " edge conflicts at step " << s;
  }
}

// Plans windows of `steps` until every robot's goals are behind it (or `max_windows`), moving the
// robots along each window and checking it. Returns the steps taken, -1 if goals remain.
int drive(Planner& p, const OccupancyGrid& map, MotionModel motion, std::vector<Agent>& agents, int steps,
          int max_windows, std::vector<std::vector<Cell>>* trail = nullptr) {
  if (trail != nullptr) trail->assign(agents.size(), {});
  for (int k = 0; k < max_windows; ++k) {
    bool any = false;
    for (const Agent& a : agents) any = any || !a.goals.empty();
    if (!any) return k * steps;
    const Window w = p.plan(agents, steps);
    expect_valid(map, motion, agents, w, steps);
    for (std::size_t a = 0; a < agents.size(); ++a) {
      if (trail != nullptr) (*trail)[a].insert((*trail)[a].end(), w.paths[a].begin(), w.paths[a].end());
      agents[a].at = w.paths[a].back();
      agents[a].goals.erase(agents[a].goals.begin(), agents[a].goals.begin() + w.done[a]);
    }
  }
  for (const Agent& a : agents) {
    if (!a.goals.empty()) return -1;
  }
  return max_windows * steps;
}

// `robots` robots on distinct random cells of `cells`, each with five random goals among them.
std::vector<Agent> random_agents(const OccupancyGrid& map, const std::vector<Cell>& cells, std::size_t robots, Rng& rng) {
  std::vector<Agent> agents;
  std::set<int> taken;
  while (agents.size() < robots) {
    const Cell c = cells[rng.below(cells.size())];
    if (!taken.insert(map.index(c)).second) continue;
    Agent a{c, {}};
    for (int g = 0; g < 5; ++g) a.goals.push_back(cells[rng.below(cells.size())]);
    agents.push_back(a);
  }
  return agents;
}

TEST(Traffic, TwoRobotsMeetingHeadOnInAOneCellCorridorPass) {
  // Two rooms joined by a corridor one cell wide and six long.
  const auto art = swarm::test::ascii_map({
      "############",
      "#..######..#",
      "#A........B#",
      "#..######..#",
      "############",
  });
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('B')}}, {art.at.at('B'), {art.at.at('A')}}};
  Planner p(art.grid, MotionModel::four(), {.seed = 1});
  const int took = drive(p, art.grid, MotionModel::four(), agents, 8, 10);
  ASSERT_GT(took, 0);
  EXPECT_LE(took, 32);
}

// The same meeting where the corridor has no room at either end, only one pocket in its middle
// (a tree): PIBT alone never gets them past each other. With the swap, the robot heading away
// from the pocket backs up, pulling the other along, until one can step into the pocket.
TEST(Traffic, TwoRobotsMeetingHeadOnInACorridorWithOnePocketPass) {
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    const auto art = swarm::test::ascii_map({
        "#########",
        "#A.....B#",
        "####.####",
        "#########",
    });
    std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('B')}}, {art.at.at('B'), {art.at.at('A')}}};
    Planner p(art.grid, MotionModel::four(), {.seed = seed});
    const int took = drive(p, art.grid, MotionModel::four(), agents, 8, 10);
    EXPECT_GT(took, 0) << seed;
    EXPECT_LE(took, 2 * 8) << seed;
    EXPECT_EQ(p.rescues(), 0u) << seed;  // the swap alone
  }
}

// In the same corridor A, at the far end, is bound for the cell beyond B's goal: B must first step
// into the pocket and let A by. PIBT stands or pushes them back and forth; after kNoProgressSteps
// without progress the planner rescues them with a complete plan (LaCAM) round the two.
TEST(Traffic, ARobotBoundPastAnothersGoalInACorridorIsRescued) {
  const auto art = swarm::test::ascii_map({
      "#########",
      "#abx..BA#",
      "####.####",
      "#########",
  });
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('a')}}, {art.at.at('B'), {art.at.at('b')}}};
  Planner p(art.grid, MotionModel::four(), {.seed = 19});
  const int took = drive(p, art.grid, MotionModel::four(), agents, 8, 10);
  EXPECT_GT(took, 0);
  EXPECT_LE(took, 4 * 8);
  EXPECT_EQ(p.rescues(), 1u);
  EXPECT_EQ(p.rescues_failed(), 0u);
}

// Every meeting on two small trees (a corridor with one pocket, one with two), 2 to 4 robots on
// random cells with random goals, 50 seeds each: every one that has a plan at all (LaCAM, complete,
// says which) is driven to its end, and where none exists (robots on a tree cannot always trade
// places) nothing is tried by a conflict (drive() checks every step).
TEST(Traffic, EveryMeetingOnSmallTreesThatHasAPlanIsDriven) {
  const std::vector<std::vector<std::string>> trees = {
      {"#########", "#.......#", "####.####", "#########"},
      {"#########", "#.......#", "##.###.##", "#########"},
  };
  int feasible = 0, driven = 0, infeasible = 0, rescued = 0;
  for (const auto& rows : trees) {
    const OccupancyGrid map = swarm::test::grid_from(rows);
    const std::vector<Cell> cells = swarm::test::free_region(map);
    for (std::size_t n = 2; n <= 4; ++n) {
      for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        Rng rng(seed * 31 + n);
        std::vector<Cell> from = cells, to = cells;
        for (std::size_t i = from.size(); i > 1; --i) std::swap(from[i - 1], from[rng.below(i)]);
        for (std::size_t i = to.size(); i > 1; --i) std::swap(to[i - 1], to[rng.below(i)]);
        std::vector<Agent> agents;
        for (std::size_t a = 0; a < n; ++a) agents.push_back({from[a], {to[a]}});
        const mapf::Instance in{map, MotionModel::four(), std::vector<Cell>(from.begin(), from.begin() + static_cast<std::ptrdiff_t>(n)),
                                std::vector<Cell>(to.begin(), to.begin() + static_cast<std::ptrdiff_t>(n))};
        mapf::SolverConfig lacam;
        lacam.kind = mapf::SolverKind::Lacam;
        const mapf::Result r = mapf::solve(in, lacam, mapf::StopCondition::never());
        Planner p(map, MotionModel::four(), {.seed = seed});
        if (r.status == mapf::Status::Infeasible) {
          // No plan puts them all on their goals at once; they may still each pass theirs.
          ++infeasible;
          (void)drive(p, map, MotionModel::four(), agents, 8, 10);
          continue;
        }
        ASSERT_EQ(r.status, mapf::Status::Solved);
        ++feasible;
        driven += drive(p, map, MotionModel::four(), agents, 8, 10) > 0 ? 1 : 0;
        rescued += p.rescues() > 0 ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(driven, feasible);
  EXPECT_EQ(feasible + infeasible, 300);
  EXPECT_EQ(infeasible, 39);
  EXPECT_EQ(rescued, 88);  // PIBT with its swap stalls in this many
}

// A robot dies in the way round a ring: the one heading past it must go the long way round, 27
// steps from 1. Every step of that detour is progress on the new distances, so it is no stall and
// no rescue is made (one measured against its best on the old distances would see 26 steps
// without progress).
TEST(Traffic, ADetourRoundADeadRobotIsProgress) {
  const auto art = swarm::test::ascii_map({
      "############",
      "#A.BG......#",
      "#.########.#",
      "#.########.#",
      "#.########.#",
      "#..........#",
      "############",
  });
  Planner p(art.grid, MotionModel::four(), {.seed = 3});
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('G')}}, {{10, 1}, {}}};
  Window w = p.plan(agents, 1);  // one step towards G: 2 from it
  expect_valid(art.grid, MotionModel::four(), agents, w, 1);
  agents[0].at = w.paths[0].back();
  ASSERT_EQ(agents[0].at, (Cell{2, 5}));
  agents[1] = {art.at.at('B'), {}, true};  // now dead between it and G
  const int took = drive(p, art.grid, MotionModel::four(), agents, 8, 8);
  EXPECT_GT(took, 0);
  EXPECT_EQ(p.rescues(), 0u);
  EXPECT_EQ(p.rescues_failed(), 0u);
}

// Three robots in a dead-end corridor off a room, the two at its far end bound for the room and the
// one at its mouth for the far end: only by backing the third out into the room first can they
// pass, which PIBT does by itself where the corridor opens into a room. 8-connected, as
// exploration's and collection's robots move.
TEST(Traffic, RobotsInADeadEndPassThroughTheRoomItOpensInto) {
  const auto art = swarm::test::ascii_map({
      "##########",
      "#...######",
      "#...C.BA##",
      "#...######",
      "##########",
  });
  std::vector<Agent> agents = {{art.at.at('A'), {{1, 3}}}, {art.at.at('B'), {{1, 1}}}, {art.at.at('C'), {art.at.at('A')}}};
  Planner p(art.grid, MotionModel::eight(), {.seed = 5});
  const int took = drive(p, art.grid, MotionModel::eight(), agents, 8, 20);
  EXPECT_GT(took, 0);
  EXPECT_EQ(p.rescues(), 0u);  // priority inheritance backs the third robot out on its own
}

// An explored map grows: the door between two rooms is not known free at first, so the goal
// beyond it is skipped, not chased; once the map knows the door, the next windows go through it.
TEST(Traffic, ANewMapOpensTheWayToAGoalThatWasSkipped) {
  const auto art = swarm::test::ascii_map({
      "#########",
      "#A..#..B#",
      "#...#...#",
      "#.......#",
      "#########",
  });
  OccupancyGrid closed = art.grid;
  for (int y = 1; y <= 3; ++y) closed.set({4, y}, CellState::Unknown);  // the door and the wall beside it
  Planner p(closed, MotionModel::four(), {.seed = 3});
  std::vector<Agent> agents = {{art.at.at('A'), {art.at.at('B')}}};
  const Window unknown = p.plan(agents, 4);
  ASSERT_EQ(unknown.done[0], 1);
  EXPECT_EQ(unknown.reached_at[0][0], -1);  // B lies beyond cells not known free: skipped
  EXPECT_EQ(unknown.paths[0].back(), art.at.at('A'));
  p.set_map(art.grid);
  const int took = drive(p, art.grid, MotionModel::four(), agents, 4, 10);
  EXPECT_EQ(took, 4 * 3);  // 10 steps: to the door's row, through it, and back up: three windows of 4
  EXPECT_THROW(p.set_map(OccupancyGrid(3, 3)), std::invalid_argument);
}

TEST(Traffic, EightRobotsOnARingOfEightCellsRotate) {
  // Every cell of the ring is taken: nobody can move unless all move together.
  const auto art = swarm::test::ascii_map({
      "#####",
      "#abc#",
      "#h#d#",
      "#gfe#",
      "#####",
  });
  const std::string ring = "abcdefgh";
  std::vector<Agent> agents;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    agents.push_back({art.at.at(ring[i]), {art.at.at(ring[(i + 2) % ring.size()])}});
  }
  Planner p(art.grid, MotionModel::four(), {.seed = 3});
  EXPECT_EQ(drive(p, art.grid, MotionModel::four(), agents, 4, 10), 4);  // two steps, in one window
}

TEST(Traffic, TwoGroupsSwapRoomsThroughOneDoor) {
  const auto art = swarm::test::ascii_map({
      "#########",
      "#a..#..d#",
      "#b.....e#",
      "#c..#..f#",
      "#########",
  });
  std::vector<Agent> agents;
  for (const char c : std::string("abc")) agents.push_back({art.at.at(c), {art.at.at(static_cast<char>(c + 3))}});
  for (const char c : std::string("def")) agents.push_back({art.at.at(c), {art.at.at(static_cast<char>(c - 3))}});
  Planner p(art.grid, MotionModel::four(), {.seed = 5});
  const int took = drive(p, art.grid, MotionModel::four(), agents, 8, 20);
  ASSERT_GT(took, 0);
  EXPECT_LE(took, 48);
}

TEST(Traffic, ARobotGoesAroundADeadRobotAndSkipsAGoalOnlyTheDeadRobotsCellReaches) {
  // A loop: the short way from S to G passes D, a dead robot; the long way goes round. Cell E is a
  // dead end behind D's twin X.
  const auto art = swarm::test::ascii_map({
      "#########",
      "#.......#",
      "#.#####.#",
      "#S..D..G#",
      "#####X###",
      "#####E###",
      "#########",
  });
  const Cell d = art.at.at('D');
  const Cell x = art.at.at('X');
  std::vector<Agent> agents = {{art.at.at('S'), {art.at.at('E'), art.at.at('G')}}, {d, {}, true}, {x, {}, true}};
  Planner p(art.grid, MotionModel::four(), {.seed = 2});
  const Window first = p.plan(agents, 1);
  ASSERT_EQ(first.skipped[0], std::vector<int>{0});  // E: only through X
  EXPECT_EQ(first.done[0], 1);
  std::vector<std::vector<Cell>> trail;
  const int took = drive(p, art.grid, MotionModel::four(), agents, 6, 10, &trail);
  ASSERT_GT(took, 0);
  for (const Cell c : trail[0]) EXPECT_FALSE(c == d || c == x) << to_string(c);
  EXPECT_EQ(agents[1].at, d);
}

TEST(Traffic, ARobotWithoutGoalsStepsAsideAndARouteIsVisitedCellByCell) {
  // A coverage-like route along the bottom row and back along the top; an idle robot sits on it.
  const auto art = swarm::test::ascii_map({
      "########",
      "#......#",
      "#R..I..#",
      "########",
  });
  std::vector<Cell> route;
  for (int x = 1; x <= 6; ++x) route.push_back({x, 1});
  for (int x = 6; x >= 1; --x) route.push_back({x, 2});
  std::vector<Agent> agents = {{art.at.at('R'), route}, {art.at.at('I'), {}}};
  Planner p(art.grid, MotionModel::four(), {.seed = 9});
  std::vector<std::vector<Cell>> trail;
  const int took = drive(p, art.grid, MotionModel::four(), agents, 5, 10, &trail);
  ASSERT_GT(took, 0);
  std::set<std::pair<int, int>> visited;
  for (const Cell c : trail[0]) visited.insert({c.x, c.y});
  for (const Cell c : route) EXPECT_EQ(visited.count({c.x, c.y}), 1u) << to_string(c);
}

TEST(Traffic, EightConnectedRobotsKeepTheSameRules) {
  const auto art = swarm::test::ascii_map({
      "#######",
      "#a...b#",
      "#..#..#",
      "#c...d#",
      "#######",
  });
  std::vector<Agent> agents = {{art.at.at('a'), {art.at.at('d')}},
                               {art.at.at('d'), {art.at.at('a')}},
                               {art.at.at('b'), {art.at.at('c')}},
                               {art.at.at('c'), {art.at.at('b')}}};
  Planner p(art.grid, MotionModel::eight(), {.seed = 4});
  const int took = drive(p, art.grid, MotionModel::eight(), agents, 4, 10);
  ASSERT_GT(took, 0);
  EXPECT_LE(took, 16);
}

// Robots bound for one drop cell in a corridor of the warehouse (the collect phase after member-1-2
// was lost at tick 100, as the GCS planned it at tick 179: robots 0, 1, 2, 3 and 6 all have (1, 1)
// among their goals; robot 5, lost, is fixed). Two bound for the same cell never need to trade
// places: before, robots 2 and 6 took turns backing up for each other, stepping in and out of
// (4, 1) for two windows while (1, 1) was taken, until a rescue.
TEST(Traffic, RobotsBoundForOneCellQueueInsteadOfBackingUpForEachOther) {
  const OccupancyGrid map = load_map_yaml(swarm::test::source_dir() + "/maps/warehouse-5x8.yaml");
  std::vector<Agent> agents = {
      {{7, 8}, {{7, 8}, {1, 1}, {3, 9}, {5, 7}}},  {{3, 1}, {{2, 3}, {9, 3}, {1, 3}, {1, 1}}},
      {{13, 6}, {{13, 7}, {1, 1}, {11, 4}, {5, 7}}}, {{2, 9}, {{1, 8}, {9, 3}, {1, 7}, {1, 1}}},
      {{15, 3}, {{11, 1}, {5, 7}}},                  {{9, 9}, {}, true},
      {{13, 9}, {{13, 8}, {1, 1}, {11, 9}, {9, 3}}}, {{9, 4}, {{3, 4}, {4, 5}, {5, 7}}},
      {{7, 1}, {{3, 1}, {5, 4}, {9, 3}}}};
  Planner p(map, MotionModel::eight(), {.seed = mix_seed({1, 9103})});
  const int took = drive(p, map, MotionModel::eight(), agents, 32, 8);
  ASSERT_GT(took, 0);
  EXPECT_LE(took, 64);
  EXPECT_EQ(p.rescues(), 0);
}

TEST(Traffic, TheSameInputsGiveTheSameWindows) {
  const auto art = swarm::test::ascii_map({"#######", "#a...b#", "#..#..#", "#c...d#", "#######"});
  const std::vector<Agent> agents = {{art.at.at('a'), {art.at.at('d'), art.at.at('b')}},
                                     {art.at.at('d'), {art.at.at('a')}},
                                     {art.at.at('b'), {}}};
  Planner p1(art.grid, MotionModel::four(), {.seed = 11});
  Planner p2(art.grid, MotionModel::four(), {.seed = 11});
  const Window w1 = p1.plan(agents, 12);
  const Window w2 = p2.plan(agents, 12);
  EXPECT_EQ(w1.paths, w2.paths);
  EXPECT_EQ(w1.done, w2.done);
}

TEST(Traffic, BadInputIsRefusedNamingTheRobot) {
  const auto art = swarm::test::ascii_map({"#####", "#a.b#", "#####"});
  Planner p(art.grid, MotionModel::four());
  const auto message = [&](const std::vector<Agent>& agents) {
    try {
      (void)p.plan(agents, 1);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{{0, 0}, {}}}).find("robot 0 stands on (0, 0)"), std::string::npos);
  EXPECT_NE(message({{art.at.at('a'), {}}, {art.at.at('a'), {}}}).find("robots 0 and 1 stand on one cell"),
            std::string::npos);
  // A refused call leaves the planner usable.
  EXPECT_EQ(p.plan({{art.at.at('a'), {art.at.at('b')}}, {art.at.at('b'), {}}}, 2).paths.size(), 2u);
  EXPECT_NE(message({{art.at.at('a'), {}}}).find("planned for 2 robots before, now 1"), std::string::npos);
}

// Random rooms-and-corridors maps (a grid of 5 x 5 rooms with doors), 40 robots with five random
// goals each: every window is valid, and every goal is reached.
TEST(Traffic, FortyRobotsWithRandomGoalsOnRoomMapsReachEveryGoal) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Rng rng(seed);
    const int rooms = 5;
    const int side = 5;
    const int w = rooms * (side + 1) + 1;
    OccupancyGrid map(w, w, 0.2, 0, 0, CellState::Occupied);
    std::vector<Cell> free;
    for (int y = 0; y < w; ++y) {
      for (int x = 0; x < w; ++x) {
        const bool wall_x = x % (side + 1) == 0;
        const bool wall_y = y % (side + 1) == 0;
        const bool door_x = wall_x && y % (side + 1) == 1 + static_cast<int>((x / (side + 1) + y / (side + 1)) % side);
        const bool door_y = wall_y && x % (side + 1) == 1 + static_cast<int>((x / (side + 1) * 3 + y / (side + 1)) % side);
        const bool border = x == 0 || y == 0 || x == w - 1 || y == w - 1;
        if (border || ((wall_x || wall_y) && !door_x && !door_y)) continue;
        map.set(Cell{x, y}, CellState::Free);
        free.push_back({x, y});
      }
    }
    std::vector<Agent> agents = random_agents(map, free, 40, rng);
    Planner p(map, MotionModel::four(), {.seed = seed});
    const int took = drive(p, map, MotionModel::four(), agents, 16, 100);
    EXPECT_GT(took, 0) << "seed " << seed;
  }
}


// ---- Maps nobody tuned the planner for --------------------------------------------------------

struct MapCase {
  std::string name;
  bool movingai = false;
};

void PrintTo(const MapCase& c, std::ostream* os) { *os << c.name; }

class TrafficOnMap : public ::testing::TestWithParam<MapCase> {
 protected:
  OccupancyGrid load() const {
    const MapCase& c = GetParam();
    if (c.movingai) return load_movingai_map(swarm::test::benchmarks_dir() + "/movingai/" + c.name + ".map");
    return load_map_yaml(swarm::test::source_dir() + "/maps/" + c.name + ".yaml");
  }
};

// Nine robots (and thirty) with five random goals each, seeds 1-3: every goal is reached.
TEST_P(TrafficOnMap, RobotsWithRandomGoalsReachEveryOne) {
  const OccupancyGrid map = load();
  const std::vector<Cell> cells = swarm::test::free_region(map);
  for (const std::size_t robots : {std::size_t{9}, std::size_t{30}}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Rng rng(mix_seed({seed, robots}));
      std::vector<Agent> agents = random_agents(map, cells, robots, rng);
      Planner p(map, MotionModel::four(), {.seed = seed});
      const int took = drive(p, map, MotionModel::four(), agents, 16, 400);
      EXPECT_GT(took, 0) << robots << " robots, seed " << seed;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Maps, TrafficOnMap,
                         ::testing::Values(MapCase{"small"}, MapCase{"maze1"}, MapCase{"maze2"}, MapCase{"open"},
                                           MapCase{"warehouse-5x8"}, MapCase{"clutter"}, MapCase{"terminal"},
                                           MapCase{"maze-32-32-2", true}, MapCase{"room-32-32-4", true},
                                           MapCase{"warehouse-10-20-10-2-1", true}),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& c : n) {
                             if (c == '-') c = '_';
                           }
                           return n;
                         });

// A rescue's search is capped by the robots it plans: 512 polls (LaCAM's budget) up to 256 robots,
// fewer beyond, so that 1,000 robots' configurations stay within kRescueConfigEntries.
TEST(Traffic, ARescuesSearchBudgetShrinksWithItsRobots) {
  EXPECT_EQ(rescue_polls(0), 512);
  EXPECT_EQ(rescue_polls(9), 512);
  EXPECT_EQ(rescue_polls(256), 512);
  EXPECT_EQ(rescue_polls(257), 510);
  EXPECT_EQ(rescue_polls(1000), 131);
  EXPECT_EQ(rescue_polls(std::size_t{1} << 30), 1);
  for (std::size_t robots = 1; robots <= 4096; robots *= 2) {
    EXPECT_LE(static_cast<std::size_t>(rescue_polls(robots)) * 64 * robots,
              std::max(kRescueConfigEntries, 64 * robots));
  }
}

}  // namespace
}  // namespace swarm::planner::traffic
