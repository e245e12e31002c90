// The GCS's collection task (issue 10; docs/papers.md section 4): every object carried to its type's
// destination. The objects and destinations come from the scenario (tasks::collect_world, the
// same for the simulator, the GCS and the leaders, so an object is known by its number).
//
// The GCS plans every robot's tour itself and drives them through the traffic layer
// (docs/traffic.md) as cover does: each robot's tour stops (pick-ups and drops) go to a lifelong
// MapfGcsTask, whose conflict-free windows the leaders drive as mapf plans
// (tasks/mapf/mapf_leader.hpp), each pick-up and drop at the step the robot stands on its cell.
// The objects go to the living robots of led groups (each to the nearest with room left); what a
// robot carries stays with it. The GCS follows each object from the stops behind the robots
// (a pick-up takes every object lying on the cell, a drop leaves all the robot carries there:
// the simulator's rule), and when a robot is lost, what it carried lies beside it
// (planner::put_down_cell, as the simulator puts it) and goes to the others with a new tour each.
// Tours done and objects left (a stop skipped): new tours, as long as the last ones delivered;
// otherwise the phase is given up, saying how many objects no tour reaches.
// A pick-up on a tour's first cell counts only once the robot made it (tasks/mapf/mapf_gcs.hpp).
// A robot lost without a word of it may have made it in its last tick: the object lies under the
// robot or, picked up, beside it, where the simulator put it down. The GCS sends a robot to pick
// it up beside, and that robot's gripper says which (Report kPickResults); the phase is complete
// only once every such object is found.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/tasks/collect/collect_world.hpp"
#include "swarm/gcs/gcs_task.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"

namespace swarm::gcs {

class CollectGcsTask : public GcsTask {
 public:
  // `paths`: how the leaders drive the traffic layer's windows.
  CollectGcsTask(const swarm::scenario::Collect& config, const swarm::scenario::Mapf& paths, std::uint32_t phase,
                 bool map_given);
  void start(GcsContext& ctx) override;
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return complete_; }
  [[nodiscard]] std::string given_up() const override;
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  void on_report(const task::Report& r, GcsContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  std::uint32_t phase_;
  tasks::CollectWorld world_;
  std::vector<std::array<std::int32_t, 3>> known_;  // per object: what, a, b, as the stops behind the robots say
  bool complete_ = false;
  [[nodiscard]] int delivered_known() const;
  // The robots' tours as stops, from where they stand (MapfGcsTask's RoutePicker); and what a stop
  // behind a robot did to the objects (its StopDone).
  std::vector<std::vector<MapfGcsTask::Stop>> tours(const GcsContext& ctx, const planner::OccupancyGrid& map,
                                                    const std::vector<int>& robots);
  void stop_done(int robot, const MapfGcsTask::Stop& stop, bool reached);
  // The gripper's word (MapfGcsTask::Lifelong::picked): `robot` holds `objects` after its
  // pick-up at `at`; it settles the doubts on that pick-up.
  void picked(int robot, planner::Cell at, const std::vector<std::uint32_t>& objects);
  // Per robot: the cell of the pick-up its tour starts with where it stands, until it is counted
  // made ({-1, -1}: none).
  std::vector<planner::Cell> first_pick_;
  // Per object, a lost robot's pick-up not known made: the cell it lies on if not (under that
  // robot), and the one it is believed put down on, beside it, until the gripper of the robot
  // whose tour picks up there (`by`, -1: none yet) tells. Only that word settles it: a leader sends
  // its robots' last words again now and then, and an older one may name the same cell.
  struct Doubt {
    planner::Cell under, beside;
    int by = -1;
  };
  std::vector<std::optional<Doubt>> doubt_;
  std::uint64_t doubted_ = 0;  // objects so doubted, in all
  [[nodiscard]] bool any_doubt() const;
  std::unique_ptr<MapfGcsTask> drive_;
  int delivered_at_tours_ = 0;  // delivered when the current tours were planned
  std::uint64_t tour_plans_ = 0;
  std::string gave_up_;
};

}  // namespace swarm::gcs
