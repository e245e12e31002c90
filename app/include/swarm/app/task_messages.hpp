// What the GCS's and the leaders' parts of a task (gcs/gcs_task.hpp, leader/group_task.hpp) send
// and receive, as plain C++: no task sees a generated message. The nodes put these on the wire and
// take them off it (app/task_wire.hpp); which fields a task fills, and what its `values` mean, is
// that task's own contract (tasks/<name>/).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::task {

using planner::Cell;

// What the clock of a tick says, as a task reads it.
struct RobotAt {
  Cell cell;
  bool alive = true;
};
struct Clock {
  std::uint32_t tick = 0;
  std::vector<RobotAt> robots;  // every robot's true cell, by agent id (positions are shared in real time)
  std::vector<int> leaders;     // leaders[g]: the agent that leads group g at this tick
};

// Order.group: an order for every group (one message instead of one per group).
inline constexpr std::uint16_t kAllGroups = 0xFFFF;

enum class OrderKind : std::uint8_t {
  Work = 0,      // the group's work
  Progress = 1,  // other groups' route progress, relayed by the GCS
  Hold = 2,      // stop handing out work; report GroupState::Held when still
  Rotate = 3,    // mapf: robots that move round a cycle, at one tick
};

// A route the GCS planned for one robot.
struct PlannedRoute {
  int robot = 0;  // agent id
  std::vector<Cell> path;
  // Indices into path at which the robot picks up the object under it / drops what it carries
  // (as Route's).
  std::vector<std::uint32_t> pick_steps;
  std::vector<std::uint32_t> drop_steps;
};

// GCS -> one group's leader (or every group's): what the group is to do in a phase. A later order
// (higher seq, per phase and group) replaces an earlier one.
struct Order {
  std::uint16_t group = 0;  // or kAllGroups
  OrderKind kind = OrderKind::Work;
  std::uint32_t seq = 0;
  std::vector<std::int32_t> values;  // the task's numbers
  std::vector<PlannedRoute> routes;  // routes planned at the GCS
};

enum class GroupState : std::uint8_t {
  Working = 0,
  Done = 1,  // the group's work is done
  Held = 2,  // after OrderKind::Hold: every robot of the group stands still
};

// A leader -> the GCS: its group's progress in a phase.
struct Report {
  std::uint16_t group = 0;  // filled in by the leader's node
  GroupState state = GroupState::Working;
  std::vector<Cell> cells;            // e.g. cells newly covered
  std::vector<std::int32_t> values;   // the task's numbers
};

// A leader -> one robot of its group: drive this route (the robot's cell, then one cell per tick)
// as far as step `release` (the whole route: release >= its last index). At pick_steps the robot
// picks up the object under it; at drop_steps it drops what it carries for that destination.
struct Route {
  std::vector<Cell> path;
  std::uint32_t release = 0;
  std::vector<std::uint32_t> pick_steps;
  std::vector<std::uint32_t> drop_steps;
  std::uint32_t start_tick = 0;  // the simulator's tick its first step is made in (0: at once)
  // Nonzero: this is route `grows` again, longer at its end (the same first cells, more after them):
  // the robot keeps its place on it and drives on. 0: a new route.
  std::uint32_t grows = 0;
  // Nonzero: a version of the routes from id `replaces` on, cut short and continued otherwise (a
  // plan cut past every release, tasks/mapf/mapf_gcs.hpp). A robot following one of them keeps its
  // place on this one and drives on: the cells are the same as far as it may have got.
  std::uint32_t replaces = 0;
};

// A leader -> the GCS, telemetry for the run record and the frontier pictures: what it planned in
// a round, and from what.
struct PlanTelemetry {
  std::uint32_t round = 0;
  std::uint8_t plan_case = 0;  // record::PlanCase
  std::vector<std::optional<Cell>> waypoints;
  std::vector<Cell> group_frontiers;
  std::vector<std::vector<Cell>> global_segments;
  std::int32_t chosen_segment = -1;
};

}  // namespace swarm::task
