// Releases a robot judges for itself, from the robots' cells that every tick's clock carries.
//
// Driven by the action-dependency graph (adg.hpp), a robot waits at a step until the robots
// planned on its next cell earlier have left it. Its leader sees them leave in the clock, but the
// release it then sends reaches the robot a tick later (and a delayed link later still), and every
// robot that follows another through an aisle pays that once per step. So with each release a
// leader also sends a watch: the steps after the release, in gates, each with how far along its
// route each robot it waits on must be seen. The robot follows those robots in the clock itself and
// drives on in the tick the last of them has gone far enough, as the plan's timing would.
//
// Why it is safe: a watch starts from the progress the leader knew at its tick, a lower bound, and
// counts a watched robot one step further only when a clock shows it on its route's next cell (as
// progress_at does), so it never counts a step not made. A gate's release is what releasable() gives
// once its needs are met, so a robot never enters a cell before the robots planned there earlier
// have left it. A watch that loses a robot (a look missed, a robot further on than its leader knew)
// only stops opening gates; the leader's own releases still come.
//
//   leader: Watch w = watch_release(adg, k, progress, 8);            // plan indices
//   robot:  ReleaseWatch rw(w.routes, w.gates);  each tick: rw.see(cell_of_each_watched_robot)
//           -> rw.opened(): the furthest release open so far (0: none)
//
// Plain values; pure functions; not thread-safe.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/mapf/adg.hpp"

namespace swarm::planner::mapf {

// One gate: the robot may drive as far as route step `release` once every watched robot w has been
// seen at index reached[w] of its cells (0: no need of it).
struct Gate {
  std::uint32_t release = 0;
  std::vector<std::uint32_t> reached;
  friend bool operator==(const Gate&, const Gate&) = default;
};

struct Watch {
  std::vector<int> robots;                // the watched robots (plan indices)
  std::vector<std::vector<Cell>> routes;  // per watched robot: its route from the step it is known at
  std::vector<Gate> gates;                // releases further and further on, in order
  friend bool operator==(const Watch&, const Watch&) = default;
};

// The gates past what `progress` releases robot `robot` to (releasable(), rotations held), at
// most `max_gates`: each the next step that waits, opened by its unmet needs. Stops at a rotation
// (the GCS releases those) and at the route's end. Empty when nothing waits on another robot.
// Each gate's needs include every earlier gate's, so a gate may be dropped (one the robot has
// passed, say: its caller may know less of the others than of it) without making a later one
// wrong.
[[nodiscard]] Watch watch_release(const Dependencies& adg, int robot, const std::vector<std::uint32_t>& progress,
                                  std::size_t max_gates);

// The robot's side: follows each watched robot along its route from index 0 and opens the gates.
class ReleaseWatch {
 public:
  ReleaseWatch(std::vector<std::vector<Cell>> routes, std::vector<Gate> gates);
  // One tick's look: at[w] = where watched robot w stands. Call once per tick, in tick order, from
  // the tick whose progress the watch starts from.
  void see(const std::vector<Cell>& at);
  // The furthest release whose gate is open (0: none yet).
  [[nodiscard]] std::uint32_t opened() const { return opened_; }
  [[nodiscard]] bool all_open() const { return next_gate_ == gates_.size(); }

 private:
  std::vector<std::vector<Cell>> routes_;
  std::vector<Gate> gates_;
  std::vector<std::uint32_t> reached_;
  std::size_t next_gate_ = 0;
  std::uint32_t opened_ = 0;
};

}  // namespace swarm::planner::mapf
