// Exploration through the traffic layer (docs/traffic.md): a leader plans its round's waypoints
// and sends them to the GCS, which drives every robot to its waypoint in the layer's
// conflict-free windows. The report:
//   Report.values = [kWaypointsReport, round, robot, robot, ...]   (agent ids)
//   Report.cells  = the waypoint of each robot listed, in order
// A robot not listed has no waypoint this round. The round is the one on the wire (the GCS's
// run-wide count).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/app/task_messages.hpp"

namespace swarm::tasks {

inline constexpr std::int32_t kWaypointsReport = -1;

struct RoundWaypoints {
  std::uint32_t round = 0;
  std::vector<int> robots;  // agent ids
  std::vector<planner::Cell> cells;
};

[[nodiscard]] inline task::Report waypoints_report(const RoundWaypoints& w) {
  task::Report r;
  r.values = {kWaypointsReport, static_cast<std::int32_t>(w.round)};
  r.values.insert(r.values.end(), w.robots.begin(), w.robots.end());
  r.cells = w.cells;
  return r;
}

// The waypoints a report carries; none if it is not a waypoints report or is malformed.
[[nodiscard]] inline std::optional<RoundWaypoints> read_waypoints_report(const task::Report& r) {
  if (r.values.size() < 2 || r.values[0] != kWaypointsReport || r.values[1] < 0) return std::nullopt;
  if (r.values.size() - 2 != r.cells.size()) return std::nullopt;
  RoundWaypoints w;
  w.round = static_cast<std::uint32_t>(r.values[1]);
  w.robots.assign(r.values.begin() + 2, r.values.end());
  w.cells = r.cells;
  return w;
}

}  // namespace swarm::tasks
