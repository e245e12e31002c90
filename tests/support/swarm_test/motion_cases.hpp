// One table of simultaneous-move cases with their expected conflicts, shared by the simulator's
// tests (sim::resolve, which executes moves) and the planners' validators (planner::
// find_step_conflicts, and the MAPF validator built on it), so the simulator and the planners
// cannot disagree on what a conflict is.
//
// Each case: robots at `from`, meaning to be at `to` after one tick (to == from: wait/stay), on an
// obstacle-free grid; the expected conflict events; and, for the simulator, who ends where.
#pragma once

#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::test {

struct MotionCase {
  std::string name;
  std::vector<planner::Cell> from;
  std::vector<planner::Cell> to;
  int vertex_events = 0;  // cells two or more robots end on
  int edge_events = 0;    // swapping pairs
  // The simulator's outcome: where each robot is after the tick, and how many blocked moves.
  std::vector<planner::Cell> after;
  int blocked = 0;
};

inline std::vector<MotionCase> motion_cases() {
  return {
      {"swap", {{0, 0}, {1, 0}}, {{1, 0}, {0, 0}}, 0, 1, {{0, 0}, {1, 0}}, 0},
      {"two into one cell", {{0, 0}, {2, 0}}, {{1, 0}, {1, 0}}, 1, 0, {{0, 0}, {2, 0}}, 0},
      {"into a waiting robot", {{0, 0}, {1, 0}}, {{1, 0}, {1, 0}}, 1, 0, {{0, 0}, {1, 0}}, 0},
      {"a wait keeps the robot", {{3, 3}}, {{3, 3}}, 0, 0, {{3, 3}}, 0},
      {"chain of followers", {{0, 0}, {1, 0}, {2, 0}}, {{1, 0}, {2, 0}, {3, 0}}, 0, 0,
       {{1, 0}, {2, 0}, {3, 0}}, 0},
      {"chain behind a failed swap", {{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {{1, 0}, {2, 0}, {3, 0}, {2, 0}}, 1, 1,
       {{0, 0}, {1, 0}, {2, 0}, {3, 0}}, 1},
      {"rotation of four", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1, 0}, {1, 1}, {0, 1}, {0, 0}}, 0, 0,
       {{1, 0}, {1, 1}, {0, 1}, {0, 0}}, 0},
      {"rotation of three", {{0, 0}, {1, 0}, {1, 1}}, {{1, 0}, {1, 1}, {0, 0}}, 0, 0, {{1, 0}, {1, 1}, {0, 0}}, 0},
      {"three into one cell", {{0, 1}, {1, 0}, {2, 1}}, {{1, 1}, {1, 1}, {1, 1}}, 1, 0,
       {{0, 1}, {1, 0}, {2, 1}}, 0},
      {"follower of a robot in a vertex conflict", {{0, 0}, {1, 0}, {2, 1}}, {{1, 0}, {2, 0}, {2, 0}}, 1, 0,
       {{0, 0}, {1, 0}, {2, 1}}, 1},
      {"independent moves", {{0, 0}, {5, 5}}, {{0, 1}, {5, 4}}, 0, 0, {{0, 1}, {5, 4}}, 0},
      {"follow into a cell left by a diagonal move", {{0, 0}, {1, 0}}, {{1, 0}, {2, 1}}, 0, 0, {{1, 0}, {2, 1}}, 0},
  };
}

}  // namespace swarm::test
