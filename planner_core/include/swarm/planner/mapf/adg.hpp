// Executing a MAPF plan when robots do not keep its timing: the action-dependency graph (ADG) of
// Hoenig, Kiesel, Tinka, Durham and Ayanian, "Persistent and Robust Execution of MAPF Schedules in
// Warehouses", RA-L 2019.
//
// A plan says where every robot is at every time step. Under link delay a robot learns late that
// it may go on, so the timing slips; what must be kept is the ORDER in which robots use each cell.
// The ADG keeps exactly that:
//   - each robot drives its plan without the waits (its route: the plan's distinct consecutive
//     cells; step k of the route = entering route[k]);
//   - a robot may enter a cell at its step k only after every other robot that the plan has on that
//     cell EARLIER has left it, i.e. has reached the step after its visit (a "type 2" edge, from
//     that robot's leaving to this robot's entering). Only the latest such visit per robot is
//     kept: progress along a route only grows, so the earlier ones follow.
// A valid plan (validate.hpp: no vertex or swap conflicts, robots stay on their goals) gives an
// acyclic graph but for one case: a ROTATION, robots moving round a cycle of cells in one time step
// (standard MAPF allows it; so does the simulator, world.hpp). Its steps form one joint action,
// released to all its robots at once when each stands on its cell and every other need of every
// step of it is met. So driving never deadlocks; and as a robot enters a cell only once its
// predecessors have left, two robots are never on one cell and never swap, whatever the delays.
// The one catch: a rotation's robots must move in the same tick, and under delay they learn of
// their release in different ticks (one that tried early would be refused by the simulator, a
// conflict there). So a live run holds rotations back (Rotations::Held) and releases each one
// that ready_rotations() names as one order with one start tick for all its robots
// (tasks/mapf/mapf_gcs.hpp). `rotations` says how many a plan has.
// What a robot may do is judged from the progress of the others as the caller knows it (possibly
// late): late knowledge only makes robots wait longer, never collide.
//
//   const Dependencies adg = dependencies(plan.paths);       // paths: one cell per time step
//   std::vector<std::uint32_t> progress(n, 0);              // the route step each robot is known at
//   const std::uint32_t go_to = releasable(adg, robot, progress);  // drive as far as this step
//
// Plain values; pure functions; thread-safe.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf {

// Robot `robot` must have reached route step `step` (and so left the cell it was on before).
struct Need {
  int robot = 0;
  std::uint32_t step = 0;
  friend bool operator==(const Need&, const Need&) = default;
};

struct Dependencies {
  std::vector<std::vector<Cell>> routes;  // per robot: its plan without the waits
  // per robot, per route step k (needs[r][0] is empty: the start): what entering route[k] waits for
  std::vector<std::vector<std::vector<Need>>> needs;
  // per robot, per route step k: the plan's time step of entering route[k]
  std::vector<std::vector<int>> planned_time;
  // Rotations: each the (robot, step) of its members, numbered in the order of their time step
  // (a plan grown at its end keeps its rotations' numbers); rotation_of[r][k] = its index, or -1.
  std::vector<std::vector<Need>> rotations;
  std::vector<std::vector<int>> rotation_of;
};

// The ADG of a plan (one timed path per robot, path[t] = cell at time t; robots stay on their last
// cell afterwards). Throws std::invalid_argument if the plan has two robots on one cell at one time
// in a way that gives no order (a vertex conflict): the graph needs a valid plan.
[[nodiscard]] Dependencies dependencies(const std::vector<Path>& paths);

// How releasable() treats a rotation's step. Together: released to each member once every member
// stands ready and every need of every step of it is met (right when all members learn it in one
// tick). Held: never; the caller releases it at one tick for all (ready_rotations).
enum class Rotations { Together, Held };

// The last route step robot `robot` may drive to, given what is known of every robot's progress
// (progress[r] = the route step robot r is known to stand on): the first step whose needs are not
// all met (or, Held, that belongs to a rotation), minus one; its whole route if none.
[[nodiscard]] std::uint32_t releasable(const Dependencies& adg, int robot, const std::vector<std::uint32_t>& progress,
                                       Rotations rotations = Rotations::Together);

// The rotations whose robots all stand on the cell before their step of it (progress = step - 1)
// with every need of every step met: the ones that may go now, in index order.
[[nodiscard]] std::vector<int> ready_rotations(const Dependencies& adg, const std::vector<std::uint32_t>& progress);

// The route step robot `robot` stands on at the plan's time step `time` (the last step entered by
// then): what happens at a time of the timed plan happens at this step of the route.
[[nodiscard]] std::uint32_t step_at(const Dependencies& adg, int robot, int time);
// The plan's last time step: its longest path's (0 for no path).
[[nodiscard]] std::uint32_t last_time(const std::vector<Path>& paths);

// Robot `robot`'s progress as its cell `at` shows it, from `progress` (the step it is known to
// stand on): one step further when it stands on its route's next cell, else `progress`. A robot
// moves at most one cell a tick and a route has no two equal cells in a row, so a caller that
// looks at every tick misses no step; a route may pass a cell twice, so only the next step counts
// (a robot seen elsewhere, or a look missed, leaves it where it was: late, never early).
[[nodiscard]] std::uint32_t progress_at(const Dependencies& adg, int robot, std::uint32_t progress, Cell at);

}  // namespace swarm::planner::mapf
