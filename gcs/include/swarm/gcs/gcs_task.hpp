// The GCS's side of the task seam (docs/design.md "Missions, phases and tasks"; the leader's side is
// leader/group_task.hpp, which says what a task is).
//
// The GCS runs the phase machine: phase 0 starts at tick 0; each tick the current phase's GcsTask
// steps and says whether the phase is complete, judged from what the GCS knows (the fused map, the
// robots' cells and living flags in the clock, the leaders' reports; never the ground truth); then
// the GCS announces the next phase (PhaseStart, to the leaders and the simulator) and starts its
// task, until the last phase completes the mission.
//   start(ctx)   the phase begins: split the work among the groups (task orders), ...
//   step(ctx)    every tick of the phase
//   complete()   the phase is done
//   given_up()   why the phase can never be done (empty while it can): e.g. mapf's plan proven
//                infeasible. The GCS then ends the phase and the mission there, incomplete,
//                instead of running on to max_ticks
//   progress()   what the progress display shows
//   on_report    the leaders' reports of the current phase
//   numbers()    the task's own numbers: metrics.json phases[i].task
// What a task sends and receives is plain C++ (app/task_messages.hpp); the node puts it on the
// wire.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarm/app/role.hpp"
#include "swarm/app/task_messages.hpp"
#include "swarm/gcs/fused_map.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/record/record.hpp"

namespace swarm::gcs {

struct GcsOutlets {
  std::function<void(const task::Order&)> order;  // to every leader (the order names its group)
  // A planning round: to every leader, with the fused map of fused_tick (each adopts it as its
  // global map; leader/group_map.hpp). Returns the round's number, which the GCS counts across the
  // run (metrics.json's planning_rounds and rounds); the leaders' waypoints name it.
  std::function<std::uint32_t(std::uint32_t fused_tick, const planner::OccupancyGrid& map)> round;
};

struct GcsContext {
  const app::RoleSetup& setup;
  std::uint32_t phase = 0;
  const task::Clock& clock;
  const FusedMap& fused;  // every group's map changes so far
  record::RecordWriter& record;
  GcsOutlets& out;

  std::uint32_t tick() const { return clock.tick; }
  planner::Cell cell_of(int robot) const { return clock.robots[static_cast<std::size_t>(robot)].cell; }
  bool alive(int robot) const { return clock.robots[static_cast<std::size_t>(robot)].alive; }
  // Group g's leader at this tick (comm/leadership.hpp: a standby may have taken over).
  int leader_of(int g) const { return clock.leaders[static_cast<std::size_t>(g)]; }
};

struct ProgressLine {
  std::string label;    // "mapped", "covered", ...
  double fraction = 0;  // 0..1
  std::string detail;   // e.g. "round  12  frontier cells 40"
};

class GcsTask {
 public:
  virtual ~GcsTask() = default;
  virtual void start(GcsContext& ctx) = 0;
  virtual void step(GcsContext& ctx) = 0;
  [[nodiscard]] virtual bool complete() const = 0;
  [[nodiscard]] virtual std::string given_up() const { return {}; }
  [[nodiscard]] virtual ProgressLine progress(const GcsContext& ctx) const = 0;
  virtual void on_report(const task::Report&, GcsContext&) {}
  // Group `group` reached every waypoint of planning round `round` (or could not).
  [[nodiscard]] virtual nlohmann::json numbers() const = 0;
};

// Makes the task of phase `index` of the mission (the phase's settings from
// config::mission_phases): the task registry's tasks::gcs_task (tasks/registry.hpp).
using GcsTaskFactory = std::function<std::unique_ptr<GcsTask>(const swarm::scenario::Phase& phase,
                                                              const app::RoleSetup& setup, std::uint32_t index)>;

}  // namespace swarm::gcs

namespace swarm::gcs {

// A MapVersion frame of the run record: `map` as the GCS had fused it at `tick`.
[[nodiscard]] record::Frame map_frame(std::uint32_t tick, std::uint32_t round, std::uint32_t phase,
                                      const planner::OccupancyGrid& map);
// A RoutePlan frame of the run record: the route the GCS planned for `robot` (region_cells: cover's
// region size, 0 otherwise).
[[nodiscard]] record::Frame route_frame(std::uint32_t tick, std::uint32_t phase, int robot,
                                        const std::vector<planner::Cell>& route, std::uint32_t region_cells = 0);
}  // namespace swarm::gcs
