#include "swarm/tasks/registry.hpp"

#include "swarm/config/scenario.hpp"
#include "swarm/tasks/collect/collect_row.hpp"
#include "swarm/tasks/cover/cover_row.hpp"
#include "swarm/tasks/explore/explore_row.hpp"
#include "swarm/tasks/mapf/mapf_row.hpp"

namespace swarm::tasks {

const std::vector<TaskRow>& task_rows() {
  static const std::vector<TaskRow> rows = {explore_row(), cover_row(), mapf_row(), collect_row()};
  return rows;
}

const TaskRow& task_row(const Phase& phase) {
  // By name: config::task_name already says which task a phase that names none runs.
  const std::string name = config::task_name(phase);
  for (const TaskRow& row : task_rows()) {
    if (row.name == name) return row;
  }
  throw config::ConfigError("task '" + name + "' is not in this build's task registry");
}

std::unique_ptr<gcs::GcsTask> gcs_task(const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
  return task_row(phase).gcs(phase, setup, index);
}

std::unique_ptr<leader::GroupTask> group_task(const Phase& phase, const app::RoleSetup& setup, int group,
                                              std::uint32_t index) {
  return task_row(phase).leader(phase, setup, group, index);
}

sim::PhaseSim sim_part(const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
  const TaskRow& row = task_row(phase);
  return {row.motion, row.judge(phase, setup, index)};
}

}  // namespace swarm::tasks
