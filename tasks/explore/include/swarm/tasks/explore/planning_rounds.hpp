// Exploration's planning rounds at the GCS, free of DDS (docs/papers.md sections 2 and 3): when
// the groups plan, which fused map they plan on, and when exploration is complete.
//
// All groups plan at the same moment. Round 1 starts once every group's first scans have reached
// the GCS; round r ends when every group reported its waypoints done, or after replan_threshold
// ticks. Delay model (Fig. 2): the global map fused at the start of round r is distributed for
// planning at round r + map_delay_rounds (1 in the paper, 0 = ideal). Complete: round 1 has
// started and the fused map has no frontier reachable from the robots' start cells or their
// current cells.
//
// Rounds are numbered from 1 within one explore phase; the GCS numbers them across the run on the
// wire (gcs/gcs_task.hpp, GcsOutlets::round).
//
//   PlanningRounds r({.groups = 3, .replan_threshold = 20, .map_delay_rounds = 1});
//   r.group_arrived(group, round);
//   PlanningRounds::Decision d = r.tick(k, fused, robot_cells);  // d.start_round -> send *d.map
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "swarm/gcs/fused_map.hpp"
#include "swarm/planner/grid/grid.hpp"

namespace swarm::tasks {

struct PlanningRoundsConfig {
  int groups = 3;
  // Where the robots started: every explored region connects to these cells, so completion is
  // judged from them too (under leader<->GCS delay the robots' current cells may still be
  // unknown in the fused map, and a search from there alone would find no frontier at all).
  std::vector<planner::Cell> start_cells;
  std::uint32_t replan_threshold = 20;
  std::uint32_t map_delay_rounds = 1;
};

class PlanningRounds {
 public:
  explicit PlanningRounds(PlanningRoundsConfig config);

  // Group `group` is done with round `round`'s waypoints; a report for another round is ignored.
  void group_arrived(int group, std::uint32_t round);

  struct Decision {
    std::optional<std::uint32_t> start_round;
    const planner::OccupancyGrid* map = nullptr;  // to distribute with the new round
    std::uint32_t map_tick = 0;                   // when that map was fused
    bool complete = false;
  };
  Decision tick(std::uint32_t k, const gcs::FusedMap& fused, const std::vector<planner::Cell>& robots);

  [[nodiscard]] std::uint32_t round() const { return round_; }
  [[nodiscard]] std::size_t frontier_cells() const { return frontier_cells_; }
  [[nodiscard]] const std::vector<std::uint32_t>& round_ticks() const { return round_ticks_; }  // start tick per round

 private:
  PlanningRoundsConfig config_;
  std::vector<bool> arrived_;
  std::uint32_t round_ = 0;
  std::uint32_t round_start_ = 0;
  std::map<std::uint32_t, std::pair<std::uint32_t, planner::OccupancyGrid>> snapshots_;  // round -> (tick, map)
  std::vector<std::uint32_t> round_ticks_;
  std::size_t frontier_cells_ = 0;
};

}  // namespace swarm::tasks
