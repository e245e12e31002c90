// The task registry: every task's row (task_row.hpp says what a row holds and how to add a task).
// The roles' processes hand its parts to their nodes:
//   gcs::GcsNode node(agent, setup, run_dir, progress, tasks::gcs_task);
//   app::CandidateNode node(agent, setup, group, index, tasks::group_task);
//   sim::SimNode node(clock, setup, tasks::sim_part);
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "swarm/sim/sim_node.hpp"
#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

// Every task, in the order of Phase's oneof.
[[nodiscard]] const std::vector<TaskRow>& task_rows();
// The row of the phase's task; throws config::ConfigError for a phase that names no known task.
[[nodiscard]] const TaskRow& task_row(const Phase& phase);

// The parts of phase `index` of the mission (the row's factories).
[[nodiscard]] std::unique_ptr<gcs::GcsTask> gcs_task(const Phase& phase, const app::RoleSetup& setup,
                                                     std::uint32_t index);
[[nodiscard]] std::unique_ptr<leader::GroupTask> group_task(const Phase& phase, const app::RoleSetup& setup,
                                                            int group, std::uint32_t index);
[[nodiscard]] sim::PhaseSim sim_part(const Phase& phase, const app::RoleSetup& setup, std::uint32_t index);

}  // namespace swarm::tasks
