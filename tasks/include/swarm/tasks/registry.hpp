// The task registry: every task's row (task_row.hpp says what a row holds and how to add a task).
// The roles' processes hand its parts to their nodes:
//   gcs::GcsNode node(agent, setup, run_dir, progress, tasks::gcs_task);
//   app::CandidateNode node(agent, setup, group, index, tasks::group_task);
//   sim::SimNode node(clock, setup, tasks::sim_part);
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "swarm/sim/sim_node.hpp"
#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

// Every task, in the order of Phase's oneof.
[[nodiscard]] const std::vector<TaskRow>& task_rows();
// The row of the phase's task; throws config::ConfigError for a phase that names no known task.
[[nodiscard]] const TaskRow& task_row(const Phase& phase);

// Checks every phase's settings with its row's `check` against the world it will run in (the map,
// the start cells): throws config::ConfigError with every problem, one per line, each
// "SOURCE: field mission.phase[i].TASK...: must ... (got ...)". Then resolves what they fix in
// advance with its row's `resolve` into world.phase_data (one entry per phase; a ConfigError
// names the field of a bad goal or object). The launcher calls it before it starts a process, and
// every role's process when it loads its scenario (load_role), before it drops the map file.
void resolve_mission(config::World& world, const std::string& source);

// A role's set-up (app::load_role) with its mission resolved (resolve_mission): what every role's
// process loads.
[[nodiscard]] app::RoleSetup load_role(const app::RoleOptions& options, app::RoleKind kind);

// The parts of phase `index` of the mission (the row's factories).
[[nodiscard]] std::unique_ptr<gcs::GcsTask> gcs_task(const Phase& phase, const app::RoleSetup& setup,
                                                     std::uint32_t index);
[[nodiscard]] std::unique_ptr<leader::GroupTask> group_task(const Phase& phase, const app::RoleSetup& setup,
                                                            int group, std::uint32_t index);
[[nodiscard]] sim::PhaseSim sim_part(const Phase& phase, const app::RoleSetup& setup, std::uint32_t index);

}  // namespace swarm::tasks
