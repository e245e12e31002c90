// One task, one place: a task is a folder tasks/<name>/ and one row of the registry
// (tasks/registry.hpp). The row says everything the rest of the system needs to know of it:
//   name        its field in idl/scenario.proto's Phase `task` oneof, which is also its name in
//               --mission, metrics.json and the logs (the registry test checks they agree)
//   phase_case  that field's case
//   motion      how its robots move in the simulator (the model its planner assumes)
//   gcs         its GCS part (gcs/gcs_task.hpp: the contract), one per phase
//   leader      its leader part (leader/group_task.hpp), one per phase and group
//   judge       its ground-truth judge in the simulator (sim/phase_judge.hpp), one per phase
//   check       its settings' checks at load (optional): each impossible value one line of
//               `problems`, named from `field` ("mission.phase[2].mapf"); the run does not start
//   resolve     what its settings fix in advance from the scenario and the map (optional: goals,
//               objects), made once at load, where the map file is read, into World::phase_data
//               (its parts read it there); throws config::ConfigError naming `field`
//
// Adding a task:
//   1. its settings message and a field in Phase's oneof, in idl/scenario.proto (marked
//      `[(learns_map) = true]` if the task starts without the map, as exploration does);
//   2. tasks/<name>/: its planner calls, the three parts, and `TaskRow <name>_row()`. The parts
//      exchange plain messages (app/task_messages.hpp: Order, Report, Route); what their
//      `values` mean is the task's own contract, written in its folder;
//   3. that row in tasks/src/registry.cpp and the folder in tasks/CMakeLists.txt.
// tasks/rendezvous/ is the smallest example: settings, a GCS part that picks goals and drives
// them with mapf's parts, a judge and a row (its commit touched 15 files, tests included).
// The lockstep protocol, link emulation, faults, traffic accounting, the CLI's --mission and the
// phase machine do not change. Settings are checked and resolved at load by the row's `check`
// and `resolve` (tasks::resolve_mission: in the launcher before any process starts, and in every
// role's process).
#pragma once

#include <any>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "swarm/app/role.hpp"
#include "swarm/config/problems.hpp"
#include "swarm/gcs/gcs_task.hpp"
#include "swarm/leader/group_task.hpp"
#include "swarm/planner/grid/motion.hpp"
#include "swarm/sim/phase_judge.hpp"

namespace swarm::tasks {

using swarm::scenario::Phase;

struct TaskRow {
  std::string name;
  Phase::TaskCase phase_case = Phase::TASK_NOT_SET;
  planner::MotionModel motion = planner::MotionModel::eight();
  std::function<std::unique_ptr<gcs::GcsTask>(const Phase&, const app::RoleSetup&, std::uint32_t index)> gcs;
  std::function<std::unique_ptr<leader::GroupTask>(const Phase&, const app::RoleSetup&, int group,
                                                   std::uint32_t index)>
      leader;
  std::function<std::unique_ptr<sim::PhaseJudge>(const Phase&, const app::RoleSetup&, std::uint32_t index)> judge;
  std::function<void(const Phase&, const config::World&, const std::string& field, config::Problems& problems)> check;
  std::function<std::any(const Phase&, const config::World&, const std::string& field)> resolve;
};

}  // namespace swarm::tasks
