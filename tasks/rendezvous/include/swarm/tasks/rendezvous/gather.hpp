// Where a rendezvous puts the robots (free of DDS; the GCS runs it on the map it knows, the
// simulator's judge on the ground truth).
//
// The centre is the free cell nearest `point` (Euclidean) that some robot can reach; the cells are
// the k free cells nearest the centre in 8-connected steps without corner cutting (a breadth-first
// search in the motion model's fixed neighbour order, planner::start_cells), k being the robots
// that can reach the centre on the 4-connected grid the MAPF planner drives. So the robots stand
// as tightly as the free cells around the point allow, and around the run's start they stand
// exactly on their start cells (which are picked the same way). Robots are then assigned to cells
// by the Hungarian method, minimising the sum of their 4-connected path lengths.
//
//   Gathering g = gather(map, {20, 8}, {{3, 3}, {4, 3}, {30, 2}});
//   // g.goals[i]: robot i's cell, {-1, -1} when it cannot reach the centre
#pragma once

#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::tasks::rendezvous {

struct Gathering {
  planner::Cell centre{-1, -1};        // {-1, -1}: no robot can reach a free cell
  std::vector<planner::Cell> cells;    // the gathering cells, nearest the centre first
  std::vector<planner::Cell> goals;    // per robot: its cell of `cells`, {-1, -1} if it cannot reach it
  double path_sum = 0;                 // the assignment's sum of 4-connected path lengths
};

// Steps from `from` to every cell under `motion` through free cells of `map` (-1: unreachable).
[[nodiscard]] std::vector<int> steps_from(const planner::OccupancyGrid& map, planner::Cell from,
                                          const planner::MotionModel& motion);

// `robots`: the cells of the robots to gather (free cells of `map`; every other robot stands on an
// occupied cell of it).
[[nodiscard]] Gathering gather(const planner::OccupancyGrid& map, planner::Cell point,
                               const std::vector<planner::Cell>& robots);

// How tightly `robots` stand around `centre`, in 8-connected steps from it on `map` (the measure
// the cells are picked by): their sum and largest.
struct Packing {
  long long step_sum = 0;
  int max_steps = 0;
  int unreachable = 0;  // robots from whose cell the centre cannot be reached
};
[[nodiscard]] Packing packing(const planner::OccupancyGrid& map, planner::Cell centre,
                              const std::vector<planner::Cell>& robots);

}  // namespace swarm::tasks::rendezvous
