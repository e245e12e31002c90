// Mission control at the GCS, free of DDS (paper sections 2 and 3): fuse the groups' map changes
// into the global map, run the planning rounds, and say when exploration is complete.
//
// Rounds: all groups plan at the same moment. Round 1 starts once every group's first scans have
// reached the GCS; round r ends when every group reported its waypoints done, or after
// replan_threshold ticks. Delay model (Fig. 2): the global map fused at the start of round r is
// distributed for planning at round r + global_map_delay_rounds (1 in the paper, 0 = ideal).
// Complete: round 1 has started and the fused map has no frontier reachable from the robots'
// start cells or their current cells.
//
//   Mission m(w, h, res, {.groups = 3, .replan_threshold = 20, .map_delay_rounds = 1});
//   m.fuse(group, changes); m.group_arrived(group, round);
//   Mission::Decision d = m.tick(k, robot_cells);  // d.start_round -> send d.map to every leader
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::gcs {

struct MissionConfig {
  int groups = 3;
  // Where the robots started: every explored region connects to these cells, so completion is
  // judged from them too (under leader<->GCS delay the robots' current cells may still be
  // unknown in the fused map, and a search from there alone would find no frontier at all).
  std::vector<planner::Cell> start_cells;
  std::uint32_t replan_threshold = 20;
  std::uint32_t map_delay_rounds = 1;
};

class Mission {
 public:
  Mission(int width, int height, double resolution, MissionConfig config);

  void fuse(int group, const std::vector<planner::CellChange>& changes);
  void group_arrived(int group, std::uint32_t round);

  struct Decision {
    std::optional<std::uint32_t> start_round;
    const planner::OccupancyGrid* map = nullptr;  // to distribute with the new round
    std::uint32_t map_tick = 0;                   // when that map was fused
    bool complete = false;
  };
  Decision tick(std::uint32_t k, const std::vector<planner::Cell>& robots);

  std::uint32_t round() const { return round_; }
  const planner::OccupancyGrid& fused() const { return fused_; }
  std::size_t frontier_cells() const { return frontier_cells_; }
  double mapped_fraction() const;  // known cells over the map's bounding box
  const std::vector<std::uint32_t>& round_ticks() const { return round_ticks_; }  // start tick per round

 private:
  MissionConfig config_;
  planner::OccupancyGrid fused_;
  std::size_t known_ = 0;
  std::vector<bool> seen_group_;
  std::vector<bool> arrived_;
  std::uint32_t round_ = 0;
  std::uint32_t round_start_ = 0;
  std::map<std::uint32_t, std::pair<std::uint32_t, planner::OccupancyGrid>> snapshots_;  // round -> (tick, map)
  std::vector<std::uint32_t> round_ticks_;
  std::size_t frontier_cells_ = 0;
};

}  // namespace swarm::gcs
