// The GCS's coverage task (issue 8; docs/papers.md section 2 for DARP): cover every reachable free cell
// of the known map (the fused map the exploration left, or the map file when the mission starts
// with cover: then the robots are given it, as DARP assumes).
//
// Hierarchical (default): DARP divides the cells among the groups, the living leaders as agents,
// portions by living group size; each group gets its share (Order: the known map, the share
// as a cell set) and its leader divides it among its members (tasks/cover/cover_leader.hpp). Flat: DARP
// divides among all living robots here, and each group gets its robots' routes.
// The GCS follows coverage from the robots' cells in the clock (with the footprint radius) and
// judges the phase complete when every target cell is covered. It divides what is left again
// among the living groups when a group with uncovered cells loses its leader, or when every group
// has reported its share done while cells are still uncovered.
// Through the traffic layer (cover.traffic, docs/traffic.md): the division is flat, made once
// every robot stands still, and the routes are goal sequences that the mapf task's lifelong
// engine drives in conflict-free windows (tasks/mapf/mapf_gcs.hpp; the leaders run mapf's part).
// A lost robot's cells are divided again among the living; when every route is done with cells
// still uncovered, those are divided again.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "swarm/gcs/gcs_task.hpp"
#include "swarm/planner/coverage/coverage_tracker.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"

namespace swarm::gcs {

class CoverGcsTask : public GcsTask {
 public:
  // `paths`: how the traffic layer's windows are driven (with cover.traffic).
  CoverGcsTask(const swarm::scenario::Cover& config, const swarm::scenario::Mapf& paths, std::uint32_t phase,
               bool map_given);
  void start(GcsContext& ctx) override;
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return started_ && tracker_.complete(); }
  [[nodiscard]] std::string given_up() const override;
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  void on_report(const task::Report& r, GcsContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  // Divides `cells`; sends each living group its share (and, flat, its robots' routes), or with
  // the traffic layer returns every robot id's route (agents: `robots`).
  std::vector<std::vector<planner::Cell>> divide(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                 const char* why, const std::vector<int>* robots = nullptr);
  std::vector<int> living_groups(const GcsContext& ctx) const;

  swarm::scenario::Cover config_;
  std::uint32_t phase_;
  bool map_given_;
  bool started_ = false;
  planner::OccupancyGrid known_;
  planner::CoverageTracker tracker_;
  std::vector<int> group_of_cell_;          // the group whose share a cell is in (-1: none)
  std::vector<bool> group_alive_;           // as last divided
  std::vector<bool> group_done_;
  std::uint32_t seq_ = 0;
  std::uint32_t last_division_tick_ = 0;
  nlohmann::json divisions_ = nlohmann::json::array();
  std::unique_ptr<MapfGcsTask> drive_;  // cover.traffic: the traffic layer
  bool nothing_to_drive_ = false;       // a division left cells uncovered that no route reaches
};

}  // namespace swarm::gcs
