// A dry run of the traffic layer (traffic.hpp): the moves a set of goal sequences will cost once
// the planner has fitted them together, before any robot is sent. A route's own length says
// nothing of the robots it crosses: where two routes meet head-on in an aisle, one robot stands
// aside or waits, and that is what the makespan pays. Tasks that weigh several plans (cover's
// divisions) rehearse each and keep the one the layer drives fastest.
//
//   traffic::Rehearsal r = traffic::rehearse(map, agents, 32, {.seed = 7}, 2000);
//   if (r.finished) r.makespan;   // steps until every agent has every goal behind it
//   int ticks = traffic::driven_ticks(r.paths, [](int from, int to) { return 1; });
//
// Driven by the plan's action-dependency graph (planner/mapf/adg.hpp), a robot enters a cell only
// once the robots planned there before have left, and without the plan's waits: a robot that waits
// on nobody drives on. driven_ticks() estimates that drive with a cost per dependency (the
// caller's `lag`, in ticks, from the robot waited for leaving to the one waiting entering).
//
// The windows are planned as the layer plans them while driving (each from where the last ends,
// the robots' priorities kept), so with the driver's seed and window the rehearsal is the plan.
// Deterministic. Cost: the planner's, for the whole plan.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"
#include "swarm/planner/traffic/traffic.hpp"

namespace swarm::planner::traffic {

struct Rehearsal {
  bool finished = false;  // every goal behind every agent within max_steps
  int makespan = 0;       // steps until the last goal was reached (or skipped); max_steps if not finished
  int moves = 0;          // cells changed, over all agents
  int skipped = 0;        // goals skipped as unreachable
  std::vector<std::vector<Cell>> paths;  // per agent: its timed path, the windows one after another
};

// `map`: as the driver plans on it (the agents' cells free). Throws as Planner::plan does.
[[nodiscard]] Rehearsal rehearse(const OccupancyGrid& map, const MotionModel& motion, std::vector<Agent> agents,
                                 int window, const Config& config, int max_steps);

// Ticks until every robot has driven its route of `paths` (timed, valid: no two robots on a cell)
// when each route step is entered as soon as its robot stands before it and, for each robot the
// plan has there earlier, lag(that robot, this robot) ticks after that robot left. That holds
// where the plan has a robot follow another into the cell it leaves in the same step, too: the
// follower learns of it a tick late, so a queue of robots that the plan moves as one pays a lag
// per robot. Rotations (robots moving round a cycle in one step) go together. start[r]: the tick
// robot r stands ready at (its route's arrival; 0 where start has no entry).
[[nodiscard]] int driven_ticks(const std::vector<std::vector<Cell>>& paths, const std::function<int(int, int)>& lag,
                               const std::vector<int>& start = {});
// driven_ticks() of one plan for each of several start vectors (its routes arriving at different
// ticks, as a link's jitter and loss make them): the plan's graph is built once.
[[nodiscard]] std::vector<int> driven_ticks_per_start(const std::vector<std::vector<Cell>>& paths,
                                                      const std::function<int(int, int)>& lag,
                                                      const std::vector<std::vector<int>>& starts);

}  // namespace swarm::planner::traffic
