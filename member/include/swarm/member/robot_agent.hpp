// One robot's own logic, free of DDS: it maps what its LiDAR sees and drives exactly the routes
// its leader gives it (the traffic layer's, docs/traffic.md), as far as they are released. It
// plans no path of its own: every move of every robot comes from one conflict-free plan. Used by
// swarm-member for its robot and by swarm-leader for the leader's own robot.
//
// Its parts of a route go to the simulator as routes (sim/world.hpp) numbered 1, 2, ...; every
// scan comes with the simulator's word on the latest route it applied (planner::RouteProgress),
// so the robot knows exactly where along its route it is, and that a route still in flight (sent,
// not yet applied: a delayed link) must not be judged yet.
//
//   RobotAgent robot(map_width, map_height, resolution);
//   auto changes = robot.sense(pose, ranges, max_range, report);  // send these to the leader
//   robot.follow(id, cells, release);
//   RobotAgent::Step s = robot.step(tick);  // s.path_changed -> send s.path as route s.route_id
//
// Not thread-safe.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/route.hpp"

namespace swarm::member {

class RobotAgent {
 public:
  RobotAgent(int width, int height, double resolution);

  // Integrates a scan taken at `pose` (ranges in cells); returns the cells it changed.
  std::vector<planner::CellChange> sense(planner::Cell pose, const std::vector<float>& ranges, float max_range,
                                         const planner::RouteProgress& route = {});
  // Map knowledge from elsewhere (the leader's group map); returns how many cells changed.
  int learn(const std::vector<planner::CellChange>& changes);
  // Follow the leader's route `id` exactly (planner/grid/route.hpp: cells[0] is where the robot stands
  // when it starts), as far as index `release`; the objects under the robot are picked up at the
  // indices in `picks` and dropped at those in `drops`. Replaces an earlier route.
  // The robot drives the released part, then waits for release() to go on. With a `start_tick`
  // (a step several robots make together) its first part goes to the simulator at once, to set
  // off in that tick of the simulator's, however long the command takes on its way. An empty
  // route means "stop where you stand": the simulator is told at once, and the route's progress
  // turns Stopped once the simulator confirms it (until then Active), so a leader knows when the
  // robot stands still.
  // Route ids only grow (a leader numbers its routes, a standby's above its predecessor's): a
  // route older than one followed already was overtaken on the way and is ignored. The route it
  // follows, sent again with its cells so far first and more after them, grows: the robot keeps
  // its place and drives on as released (a leader extending a plan by its next window). A newer
  // route that replaces routes from id `replaces` on, the one it follows among them (a plan cut
  // short and continued otherwise), keeps its place too if it has the same cells as far as the
  // robot may have got: its step, its release and the part the simulator drives; otherwise it is
  // a new route.
  void follow(std::uint32_t id, std::vector<planner::Cell> cells, std::uint32_t release,
              std::vector<std::uint32_t> picks = {}, std::vector<std::uint32_t> drops = {},
              std::uint32_t start_tick = 0, std::uint32_t replaces = 0);
  // Route `id` may be driven as far as index `up_to`. A release may come before its route (they
  // travel on different topics, and a lost message is sent again later): it is kept until the
  // route comes.
  void release(std::uint32_t id, std::uint32_t up_to);

  struct Step {
    bool path_changed = false;
    std::vector<planner::Cell> path;           // the new route (empty = stop), if path_changed
    std::uint32_t route_id = 0;                // its number, if path_changed
    std::vector<std::uint32_t> pick_steps;     // its pick-up and drop indices (following a route)
    std::vector<std::uint32_t> drop_steps;
    std::uint32_t start_tick = 0;              // the simulator holds it till then (0: at once)
  };
  // `tick`: the lockstep tick (for a route's start tick).
  Step step(std::uint32_t tick = 0);

  // Where the robot is along the leader's route it follows (id 0: none): the index it stands on
  // and the state (Active while it drives or waits for a release, Finished at the end, Abandoned
  // when it cannot go on: a wall, or it is not where the route says).
  planner::RouteProgress following() const { return follow_progress_; }

  // What the gripper senses with every scan (Sense.carrying): the objects the robot holds, by number.
  void sense_gripper(std::vector<std::uint32_t> objects) { carrying_ = std::move(objects); }
  const std::vector<std::uint32_t>& carrying() const { return carrying_; }

  const planner::OccupancyGrid& map() const { return map_; }
  planner::Cell pose() const { return pose_; }
  // The number of the latest part sent to the simulator.
  std::uint32_t route_id() const { return sent_id_; }

 private:
  void step_following(Step& out, std::uint32_t tick);
  // follow()'s route `id` in place of the one followed, keeping its place; false if they differ
  // where the robot may have got.
  bool take_cut(std::uint32_t id, std::vector<planner::Cell>& cells, std::uint32_t release,
                std::vector<std::uint32_t>& picks, std::vector<std::uint32_t>& drops);

  std::vector<std::uint32_t> carrying_;

  planner::OccupancyGrid map_;
  planner::Cell pose_{-1, -1};
  std::uint32_t sent_id_ = 0;
  planner::RouteProgress report_;

  // Following the leader's route: its cells, how far it is released, and which simulator route
  // (sent_id_) carries which part of it (leader index = base + simulator index).
  struct Follow {
    std::vector<planner::Cell> cells;
    // How far it is released; may lie past cells, in a next window of the route still on its way.
    std::uint32_t release = 0;
    std::vector<std::uint32_t> picks, drops;
    std::uint32_t sim_id = 0;  // 0: no part sent yet
    std::uint32_t base = 0;
    std::uint32_t sent_to = 0;
    std::uint32_t start_tick = 0;
  };
  std::optional<Follow> follow_;
  planner::RouteProgress follow_progress_;
  std::uint32_t newest_route_ = 0;  // the highest route id followed
  // Releases of routes not followed (yet): route id -> index; the few latest.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> early_releases_;
};

}  // namespace swarm::member
