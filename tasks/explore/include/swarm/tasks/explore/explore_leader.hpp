// The leader's exploration task (docs/papers.md section 1): at every planning round the GCS starts, it
// plans the group's waypoints on the stale global map and the group map (planner/explore/explore.hpp)
// and sends them to the GCS (waypoint_report.hpp), which drives every robot there through the
// traffic layer (docs/traffic.md) and judges the round's arrivals itself; the leader drives the
// GCS's windows as a mapf plan (tasks/mapf/mapf_leader.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "swarm/leader/group_task.hpp"
#include "swarm/planner/explore/explore.hpp"
#include "swarm/tasks/mapf/mapf_leader.hpp"

namespace swarm::leader {

class ExploreGroupTask : public GroupTask {
 public:
  // `drive`: the traffic layer's driving settings.
  ExploreGroupTask(const swarm::scenario::Explore& config, std::uint64_t seed, int group,
                   const swarm::scenario::Mapf& drive);
  void start(GroupContext& ctx) override;
  void on_order(const task::Order& order, GroupContext& ctx) override;
  void on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) override;
  void took_over(GroupContext& ctx) override;
  void step(GroupContext& ctx) override;
  void gcs_back(GroupContext& ctx) override;
  void on_round(std::uint32_t round, GroupContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;
  [[nodiscard]] bool numbers_at_top_level() const override { return true; }

 private:
  void plan(std::uint32_t round, GroupContext& ctx);

  planner::ExploreConfig explore_;
  MapfGroupTask drive_;          // the traffic layer's windows
  task::Report sent_waypoints_;  // the round's, as sent to the GCS
  std::optional<std::uint32_t> pending_round_;
  std::uint32_t round_ = 0;
  // Numbers for the run's metrics (wall-clock planning time is not part of the deterministic record).
  std::uint64_t rounds_planned_ = 0;
  std::uint64_t case_a_ = 0;
  std::uint64_t case_b_ = 0;
  double planning_seconds_ = 0;
};

// The explore planner's settings from the scenario's.
[[nodiscard]] planner::ExploreConfig explore_config(const swarm::scenario::Explore& e, std::uint64_t seed);

}  // namespace swarm::leader
