// The simulated world, free of DDS: ground truth, robot bodies and their motion, LiDAR, and the
// ground-truth numbers a run is judged by. The simulator process is the only holder of it.
//
// Routes. A robot is given a route: the cell it stands on, then one cell per tick (the same cell
// again = a wait; a neighbouring cell = a step, under the phase's motion model, planner/grid/motion.hpp).
// Each tick every robot with a route performs its next action. A route whose first cell is not
// where the robot stands when it arrives is rejected (the robot stops; its agent sees the state in
// its next Sense). Where the robot is in its route is an index, never looked up by cell, so a route
// may pass a cell several times.
//
// Moves are resolved all at once, independently of robot ids (resolve()):
//   1. An action the motion model forbids (a wall, outside the map, a corner cut, a jump) is a
//      wall stop: the robot stays and its route is abandoned.
//   2. Every robot intends a cell: its next route cell, or its own cell (waiting, idle, lost).
//      Conflicts among the intentions (planner::find_step_conflicts): two or more robots meant for
//      one cell is a vertex conflict; two robots meant to swap is an edge conflict. Every robot
//      that meant to MOVE in a conflict stays this tick and tries the same action next tick.
//   3. A mover whose target cell is held by a robot that stays (because its own move failed) stays
//      too: a blocked move. This is repeated until nothing changes.
//   4. Every remaining mover moves: followers into cells vacated this tick, and rotations of three
//      or more robots, move together.
// Counted per robot: moves, waits, vertex and edge conflicts it took part in, blocked moves, wall
// stops, the rotation between its consecutive moves (planner/tours/turns.hpp); and per tick the conflict
// events (one per cell, one per swapping pair).
//
//   World w(truth, robot_cells, {.beams = 360, .range_cells = 15});
//   w.set_motion(planner::MotionModel::four());
//   w.command(robot, route_id, route);   // when a motion command is due
//   w.move();                            // once per tick, before scanning
//   w.scan(robot, ranges);               // ranges in cells
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/coverage/coverage_tracker.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"
#include "swarm/planner/grid/route.hpp"
#include "swarm/planner/tours/tour.hpp"
#include "swarm/record/metrics.hpp"

namespace swarm::sim {

struct LidarConfig {
  int beams = 360;
  float range_cells = 15.0f;
};

using planner::RouteState;

// Per robot, cumulative: what the simulator saw the robot do (record/metrics.hpp names them).
using MotionCounts = record::MotionCounts;

// The whole team's conflict events (a vertex conflict of three robots is one event).
struct ConflictEvents {
  std::uint64_t vertex = 0;
  std::uint64_t edge = 0;
};

// One tick's resolution, on plain data (World::move applies it). `intended[i]` is where robot i
// means to be after the tick (its own cell to stay); every intended move is already legal.
struct Resolution {
  std::vector<planner::Cell> next;  // where each robot is after the tick
  std::vector<std::uint8_t> moved;  // 1 = performed its move
  std::vector<std::uint8_t> vertex, edge, blocked;  // per robot: why its move failed
  ConflictEvents events;
};
[[nodiscard]] Resolution resolve(const std::vector<planner::Cell>& current,
                                 const std::vector<planner::Cell>& intended);

class World {
 public:
  // `footprint_radius`: a robot covers every cell within this many cells (Euclidean) of its cell.
  World(planner::OccupancyGrid truth, std::vector<planner::Cell> robot_cells, LidarConfig lidar,
        int footprint_radius = 0);

  void set_motion(const planner::MotionModel& motion) { motion_ = motion; }
  const planner::MotionModel& motion() const { return motion_; }

  // A new route for `robot` (see the file comment); an empty route stops it. Route ids only grow
  // (a robot numbers its commands): one not above the robot's current id was overtaken on its way
  // and is ignored. At the route indices
  // in `picks` the robot picks up every object lying on its cell; at those in `drops` it drops
  // all it carries: an object at its type's destination is delivered, elsewhere it lies there.
  void command(int robot, std::uint32_t route_id, const std::vector<planner::Cell>& route,
               const std::vector<std::uint32_t>& picks = {}, const std::vector<std::uint32_t>& drops = {});
  // The same, to be given at tick `start_tick` (start_due): robots that must step together (a
  // rotation) set off in one tick whenever each command came. The robot's route until then goes
  // on; a newer command given before replaces it, as command() would.
  void command_at(std::uint32_t start_tick, int robot, std::uint32_t route_id, std::vector<planner::Cell> route,
                  std::vector<std::uint32_t> picks = {}, std::vector<std::uint32_t> drops = {});
  // Gives the commands held for `tick` or before; call before move().
  void start_due(std::uint32_t tick);

  // The robot stops where it stands, its route given up (a robot lost to the swarm).
  void stop(int robot);

  // Collect (docs/papers.md section 4): the objects, each lying on its cell, and each type's destination.
  void set_objects(std::vector<planner::TourObject> objects, std::vector<planner::Cell> destinations);
  // A lost robot: what it carries lies beside it again (planner::put_down_cell).
  void put_down(int robot);
  struct CollectCounts {
    int objects = 0;
    int picked = 0;       // pick-ups (an object put down and picked up again counts twice)
    int delivered = 0;    // objects at their type's destination (each once: then they are gone)
    int wrong_drops = 0;  // objects dropped anywhere else
  };
  const CollectCounts& collect() const { return collect_; }
  // The numbers of the objects robot `robot` carries (what its gripper senses), ascending.
  std::vector<std::uint32_t> carried_by(int robot) const;
  // Where each object is, for watchers: x, y and holder per object in order, the holder being the
  // robot carrying it (then x, y are that robot's cell), kLying or kDelivered.
  static constexpr int kLying = -1, kDelivered = -2;
  std::vector<int> object_states() const;
  // Every robot performs its next action.
  void move();
  // Scans from the robot's cell and records what it saw in the explored map.
  void scan(int robot, std::vector<float>& ranges);

  const std::vector<planner::Cell>& robots() const { return robots_; }
  const planner::OccupancyGrid& truth() const { return truth_; }
  const LidarConfig& lidar() const { return lidar_; }

  const planner::RouteProgress& route(int robot) const { return progress_[robot]; }

  // Share of the free cells reachable from the start that some scan has seen.
  double explored_fraction() const;
  int reachable_free_cells() const { return reachable_free_; }
  // Coverage: the free cells robots have stood on (within the footprint) since the last reset,
  // out of those reachable under the current motion model from where the robots stand at the
  // reset (the cells a coverage phase must visit).
  void reset_coverage();
  double covered_fraction() const { return coverage_.fraction(); }
  int coverage_target_cells() const { return coverage_.target_cells(); }
  int footprint_radius() const { return footprint_radius_; }
  int covered_cells() const { return coverage_.covered_cells(); }
  bool is_covered(planner::Cell c) const { return coverage_.is_covered(c); }
  std::vector<std::uint8_t> uncovered() const { return coverage_.uncovered(); }  // a mask of the map's size

  const std::vector<MotionCounts>& counts() const { return counts_; }
  // Diagonal moves made so far, all robots: with counts()' moves, the driven length in cells
  // (straight 1, diagonal sqrt 2), which the tours' planner minimises.
  std::uint64_t diagonal_moves() const { return diagonal_moves_; }
  MotionCounts total_counts() const;
  const ConflictEvents& events() const { return events_; }
  // From here on, longest_blocked_since_mark() counts blocked runs from this tick (a phase's start).
  void mark();
  // Per robot: the longest run of consecutive blocked ticks since the last mark() (a run going on
  // at the mark counts from it).
  const std::vector<std::uint64_t>& longest_blocked_since_mark() const { return longest_since_mark_; }

 private:
  planner::OccupancyGrid truth_;
  LidarConfig lidar_;
  int footprint_radius_;
  planner::MotionModel motion_ = planner::MotionModel::eight();
  std::vector<planner::Cell> robots_;
  std::vector<std::vector<planner::Cell>> routes_;
  std::vector<planner::RouteProgress> progress_;
  planner::OccupancyGrid seen_;              // union of every scan
  std::vector<std::uint8_t> reachable_;      // ground truth: free cells reachable from the start
  planner::CoverageTracker coverage_;
  int reachable_free_ = 0;
  int reachable_seen_ = 0;
  std::vector<MotionCounts> counts_;
  std::vector<std::uint64_t> blocked_run_;         // per robot: consecutive blocked ticks up to now
  std::vector<std::uint64_t> run_since_mark_;      // the same, counted from the last mark()
  std::vector<std::uint64_t> longest_since_mark_;
  std::vector<int> heading_;  // of each robot's last move, -1 before its first
  std::uint64_t diagonal_moves_ = 0;
  std::vector<std::vector<std::uint32_t>> picks_, drops_;  // per robot, of its route
  struct Held {
    std::uint32_t start_tick = 0;
    int robot = 0;
    std::uint32_t route_id = 0;
    std::vector<planner::Cell> route;
    std::vector<std::uint32_t> picks, drops;
  };
  std::vector<Held> held_;  // command_at's, not yet due
  // Collect: each object's state: lying on `cell`, carried (carrier >= 0) or delivered.
  struct Object {
    planner::Cell cell;
    int type = 0;
    int carrier = -1;
    bool delivered = false;
  };
  std::vector<Object> objects_;
  std::vector<planner::Cell> destinations_;
  CollectCounts collect_;
  void act(int robot);  // the pick-up / drop at the robot's route index, if any
  ConflictEvents events_;
};

}  // namespace swarm::sim
