// The GCS's exploration task (docs/papers.md section 1): planning rounds on the fused map with the
// paper's one-round delay (planning_rounds.hpp), each round's map to the leaders, completion when
// no reachable frontier is left.
// The leaders send their rounds' waypoints here (waypoint_report.hpp) and the GCS drives every
// robot to its waypoint through the traffic layer (docs/traffic.md), in conflict-free windows
// planned on the fused map as it grows (the mapf task's lifelong mode); a new round's waypoints
// go into the next window. A group has arrived when every robot it gave a waypoint has reached
// it, or it was skipped as unreachable.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "swarm/gcs/gcs_task.hpp"
#include "swarm/tasks/explore/planning_rounds.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"

namespace swarm::gcs {

class ExploreGcsTask : public GcsTask {
 public:
  // `drive`: the traffic layer's settings and window length.
  struct Drive {
    swarm::scenario::Mapf paths;
    int window = 16;
  };
  ExploreGcsTask(std::uint32_t phase, tasks::PlanningRoundsConfig config, const Drive& drive);
  void start(GcsContext& ctx) override;
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return complete_; }
  [[nodiscard]] std::string given_up() const override { return drive_->given_up(); }
  void on_report(const task::Report& r, GcsContext& ctx) override;
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  std::uint32_t phase_;
  tasks::PlanningRoundsConfig config_;
  tasks::PlanningRounds rounds_;
  // The run-wide number of this phase's round 1 on the wire; this phase's round r went out as
  // first_round_ + r - 1.
  std::optional<std::uint32_t> first_round_;
  bool complete_ = false;

  // The sequences the drive takes: every robot's waypoint, as a cell it can stand on.
  std::vector<std::vector<MapfGcsTask::Stop>> targets(const GcsContext& ctx, const planner::OccupancyGrid& map,
                                                       const std::vector<int>& robots);
  void target_done(int robot, const MapfGcsTask::Stop& stop, bool reached);
  // Round `round`'s arrival for every group whose robots have no waypoint left.
  void note_arrivals();
  std::unique_ptr<MapfGcsTask> drive_;
  bool driving_ = false;      // the drive has started (with the first round's waypoints)
  bool new_targets_ = false;  // waypoints came in this tick
  std::vector<std::optional<planner::Cell>> target_;   // per robot id: where it is driven
  std::vector<std::uint32_t> group_round_;             // per group: the wire round of its waypoints
  std::vector<bool> group_arrived_;                    // per group: its round's arrival noted
  std::uint64_t targets_reached_ = 0, targets_skipped_ = 0, targets_moved_ = 0;
};

}  // namespace swarm::gcs
