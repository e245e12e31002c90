// The GCS's rendezvous task: every living robot gathers around a point, or back at the run's
// start (gather.hpp says which cells). The GCS picks the cells on the map it knows and assigns
// them (Hungarian), then drives the robots there exactly as a mapf phase drives its goals
// (tasks/mapf/mapf_gcs.hpp: one conflict-free plan for every robot, executed by its timing or its
// action-dependency graph; the leaders run the mapf leader part).
//
// A robot lost on the way: the plan is held, and the cells are picked and assigned again for the
// living robots, with the lost one standing where it stopped. Complete when every planned robot
// stands on its cell; the lost robots are listed in the phase's numbers (robots_lost).
#pragma once

#include <cstdint>
#include <set>

#include "swarm/gcs/gcs_task.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"

namespace swarm::gcs {

// Where a rendezvous gathers the robots: its point's cell on `map` (config checks the point lies
// on the map), or `start`, the run's start, for home.
[[nodiscard]] planner::Cell rendezvous_target(const swarm::scenario::Rendezvous& config, planner::Cell start,
                                              const planner::OccupancyGrid& map);

class RendezvousGcsTask : public GcsTask {
 public:
  // `paths`: how the plan is made and driven (a mapf phase's settings, without goals).
  RendezvousGcsTask(const swarm::scenario::Rendezvous& config, const swarm::scenario::Mapf& paths, std::uint32_t phase,
                    bool map_given);
  void start(GcsContext& ctx) override { drive_.start(ctx); }
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return drive_.complete(); }
  [[nodiscard]] std::string given_up() const override { return drive_.given_up(); }
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  void on_report(const task::Report& r, GcsContext& ctx) override { drive_.on_report(r, ctx); }
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  // The goal of every robot id: the gathering of `robots` on `map` (MapfGcsTask::GoalPicker).
  std::vector<planner::Cell> pick(const GcsContext& ctx, const planner::OccupancyGrid& map,
                                  const std::vector<int>& robots);

  swarm::scenario::Rendezvous config_;
  MapfGcsTask drive_;
  planner::Cell centre_{-1, -1};
  std::size_t cells_ = 0;
  double path_sum_ = 0;
  std::vector<int> unreachable_;  // robot ids that cannot reach the centre (last pick)
  std::set<int> lost_;            // robot ids not alive in the phase (lost before it or on the way)
};

}  // namespace swarm::gcs
