// A member's side of its leader's release watches (planner/mapf/release_watch.hpp). A watch is
// made at the leader's tick and reaches the robot a link's delay later, so the robots' cells of
// the last clocks are kept and the watch is followed from its own tick on: no step a watched robot
// made meanwhile is missed. Free of DDS; not thread-safe.
//
//   WatchedReleases w;
//   w.watch(route_id, message_tick, watch);        // as a release with a watch arrives
//   w.see(clock_tick, every_robots_cell);          // every tick, before the robot steps
//   if (auto open = w.opened()) robot.release(open->route_id, open->release);
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/mapf/release_watch.hpp"

namespace swarm::member {

class WatchedReleases {
 public:
  // Every robot's cell at `tick` (by agent id, as the clock has them), once per tick in order.
  void see(std::uint32_t tick, std::vector<planner::Cell> cells);
  // A watch on route `route_id` made at `tick` (watched robots by agent id). It replaces the watch
  // held unless that one is on a newer route or was made later (a newer one overtaken on the way).
  void watch(std::uint32_t route_id, std::uint32_t tick, planner::mapf::Watch watch);

  struct Open {
    std::uint32_t route_id = 0;
    std::uint32_t release = 0;
  };
  // A release a gate has opened since the last call, if any.
  [[nodiscard]] std::optional<Open> opened();
  [[nodiscard]] std::uint64_t releases_opened() const { return releases_opened_; }

  static constexpr std::size_t kTicksKept = 64;

 private:
  void follow_up();  // the held watch sees every kept tick from its next one on

  std::deque<std::pair<std::uint32_t, std::vector<planner::Cell>>> ticks_;
  struct Held {
    std::uint32_t route_id = 0;
    std::uint32_t made_at = 0;
    std::uint32_t next_tick = 0;
    std::vector<int> robots;
    planner::mapf::ReleaseWatch watch;
    std::uint32_t told = 0;  // the release last handed out
  };
  std::optional<Held> held_;
  std::uint64_t releases_opened_ = 0;
};

}  // namespace swarm::member
