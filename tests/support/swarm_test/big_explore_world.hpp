// A 100 x 100 exploration input with about 2,000 frontier cells (a half-explored hall, a wall with
// doors, specks of unknown): the planner's determinism test and its benchmark plan on it.
#pragma once

#include <vector>

#include "swarm/planner/explore/explore.hpp"
#include "swarm/planner/grid/grid.hpp"

namespace swarm::test {

struct BigExploreWorld {
  planner::OccupancyGrid global{100, 100};
  planner::OccupancyGrid group{100, 100};
  std::vector<planner::Cell> leaders = {{11, 10}, {41, 50}, {21, 90}};
  BigExploreWorld() {
    for (int y = 0; y < 100; ++y) {
      for (int x = 0; x < 100; ++x) {
        const bool wall = x == 0 || y == 0 || x == 99 || y == 99 || (x == 30 && y % 20 < 15);
        const bool speck = x % 3 == 1 && y % 3 == 1;  // ~2,000 frontier cells around them
        planner::CellState g = planner::CellState::Unknown;
        if (wall) g = planner::CellState::Occupied;
        else if (x < 50 && !speck) g = planner::CellState::Free;
        global.set({x, y}, g);
        planner::CellState l = g;
        if (!wall && x >= 50 && x < 70 && y > 30 && y < 70 && !speck) l = planner::CellState::Free;
        group.set({x, y}, l);
      }
    }
  }
  planner::ExploreInput input(int round) const {
    planner::ExploreInput in;
    in.global_map = &global;
    in.group_map = &group;
    in.leader_positions = leaders;
    in.group = 1;
    in.member_positions = {leaders[1], {41, 51}, {40, 51}};
    in.round = round;
    return in;
  }
};

}  // namespace swarm::test
