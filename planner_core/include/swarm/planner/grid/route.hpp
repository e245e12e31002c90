// Routes: what a robot is told to drive and how far it got. A route is the robot's cell, then one
// cell per tick (the same cell again = a wait), each action legal under the phase's motion model
// (motion.hpp). The simulator executes routes (sim/world.hpp) and reports, with every scan, a
// RouteProgress on the robot's latest route; agents use it to know exactly where along a route
// their robot is, even when a route passes a cell twice.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

enum class RouteState : std::uint8_t {
  None = 0,       // no route applied yet
  Active = 1,     // being followed
  Finished = 2,   // its last cell reached
  Rejected = 3,   // it did not start on the robot's cell when it arrived
  Abandoned = 4,  // an action the motion model forbids (a wall stop): the robot stopped there
  Stopped = 5,    // an empty route: stop here
};

struct RouteProgress {
  std::uint32_t id = 0;    // the route's number (chosen by its sender; 0 = none)
  std::uint32_t step = 0;  // index of the route cell the robot stands on
  RouteState state = RouteState::None;
  // A route's follower (member::RobotAgent) counts it on a route with picks or drops (else 0): the
  // route's picks and drops at the steps below it are done, the simulator having taken the parts
  // that carry them. Until then a robot
  // at step 0 may not have made its first step's act (its route still on the way to the simulator,
  // or not yet released). The simulator's own progress leaves it 0: its step says as much.
  std::uint32_t acted = 0;
  friend bool operator==(const RouteProgress&, const RouteProgress&) = default;
};

// A route that waits `ticks` ticks on `cell`, then follows `path` (path.front() == cell or empty).
[[nodiscard]] std::vector<Cell> wait_then(Cell cell, int ticks, const std::vector<Cell>& path);

}  // namespace swarm::planner
