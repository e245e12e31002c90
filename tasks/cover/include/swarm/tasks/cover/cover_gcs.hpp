// The GCS's coverage task (issue 8; docs/papers.md section 2 for DARP): cover every reachable free cell
// of the known map (the fused map the exploration left, or the map file when the mission starts
// with cover: then the robots are given it, as DARP assumes).
//
// The robots drive their routes through the traffic layer (docs/traffic.md): once every robot
// stands still the GCS divides the cells (hierarchical, the default: among the living groups by
// DARP with the leaders as agents, portions by living group size, then each group's share among
// its robots, or, when it is cheaper to drive, among all living robots at once, or, when few cells
// are left, as tours; flat: only the latter two), gives every robot a route over its part, and
// the mapf task's lifelong engine drives the routes as goal sequences in conflict-free windows
// (tasks/mapf/mapf_gcs.hpp; the leaders run mapf's part). The GCS follows coverage from the
// robots' cells in the clock (with the footprint radius) and judges the phase complete when every
// target cell is covered. A lost robot's cells are divided again among the living; when every
// route is done with cells still uncovered, those are divided again.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "swarm/gcs/gcs_task.hpp"
#include "swarm/planner/coverage/coverage_tracker.hpp"
#include "swarm/planner/coverage/cover_routes.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"

namespace swarm::gcs {

class CoverGcsTask : public GcsTask {
 public:
  // `paths`: how the traffic layer's windows are driven.
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
  // Divides `cells` among `robots` (the living robots the layer drives); returns every robot id's
  // route.
  std::vector<std::vector<planner::Cell>> divide(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                                                 const char* why, const std::vector<int>& robots);
  std::vector<int> living_groups(const GcsContext& ctx) const;
  // One division of `cells`: every robot id's route (empty: none) and region size, and what
  // metrics.json keeps of it.
  struct Division {
    std::vector<std::vector<planner::Cell>> routes;
    std::vector<int> region_cells;
    std::vector<int> group_of_cell;  // per grid cell: the group whose part it is (-1: none)
    nlohmann::json json;
    std::string summary;  // for the log
    // Fills json and summary from the division's plan; `agents`: "leaders" or "robots".
    void describe(const planner::CoverRoutes& plan, const char* agents);
  };
  // Among the living groups (DARP with the leaders as agents, portions by living group size), then
  // each group's share among its robots in `robots`.
  Division divide_among_groups(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                               const std::vector<int>& robots, const std::function<bool()>& stop) const;
  // Among `robots` at once.
  Division divide_among_robots(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                               const std::vector<int>& robots, const std::function<bool()>& stop) const;
  // Per robot id: the ticks after the leaders' own robots that its route reaches it, with the
  // link's mean jitter, or (latest) its whole jitter: the last of several members' routes to
  // arrive comes near the latest, and a member's short tour then still ends in time.
  [[nodiscard]] static std::vector<int> route_arrivals(const GcsContext& ctx, bool latest);
  // Per robot id, in each of kArrivalDraws draws of the links' jitter and loss: the tick its route
  // reaches it, counted from the tick the leaders' own robots get theirs over exact links. One
  // draw where no link has jitter or loss: the arrivals are known.
  static constexpr int kArrivalDraws = 16;
  [[nodiscard]] std::vector<std::vector<int>> arrival_draws(const GcsContext& ctx) const;

 public:
  // A rehearsal's estimate of a drive: the mean of its ticks over the draws of arrivals, the
  // fewest and the most, and the steps the traffic layer plans.
  struct Rehearsed {
    double mean_ticks = 0;
    int fastest = 0, slowest = 0;
    int planned = 0;
  };

 private:
  // For `routes` (every robot id's) driven by `robots`: the ticks the drive is estimated to take
  // by the plan's dependencies (over the draws of arrival_draws), and the steps the layer plans.
  [[nodiscard]] Rehearsed rehearsed_ticks(const GcsContext& ctx, const std::vector<std::vector<planner::Cell>>& routes,
                                          const std::vector<int>& robots) const;
  // Among `robots` as tours (cover_tours.hpp), solved from the `variant`th seed; json is null when
  // there are more cells than config_.tour_candidate_cells.
  Division divide_by_tours(const GcsContext& ctx, const std::vector<std::uint8_t>& cells,
                           const std::vector<int>& robots, const std::function<bool()>& stop, std::uint32_t variant) const;

  swarm::scenario::Cover config_;
  std::uint32_t phase_;
  bool map_given_;
  bool started_ = false;
  planner::OccupancyGrid known_;
  planner::CoverageTracker tracker_;
  std::uint32_t seq_ = 0;
  nlohmann::json divisions_ = nlohmann::json::array();
  std::unique_ptr<MapfGcsTask> drive_;  // the traffic layer
  bool nothing_to_drive_ = false;       // a division left cells uncovered that no route reaches
};

}  // namespace swarm::gcs
