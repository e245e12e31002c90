#include "swarm/tasks/registry.hpp"

#include "swarm/config/scenario.hpp"
#include "swarm/tasks/collect/collect_row.hpp"
#include "swarm/tasks/cover/cover_row.hpp"
#include "swarm/tasks/explore/explore_row.hpp"
#include "swarm/tasks/mapf/mapf_row.hpp"
#include "swarm/tasks/rendezvous/rendezvous_row.hpp"

namespace swarm::tasks {

const std::vector<TaskRow>& task_rows() {
  static const std::vector<TaskRow> rows = {explore_row(), cover_row(), mapf_row(), collect_row(), rendezvous_row()};
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

void check_mission(const config::World& world, const std::string& source) {
  config::Problems problems(source);
  const auto phases = config::mission_phases(world.scenario);
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const TaskRow& row = task_row(phases[i]);
    if (row.check) row.check(phases[i], world, "mission.phase[" + std::to_string(i) + "]." + row.name, problems);
  }
  problems.throw_if_any();
}

app::RoleSetup load_role(const app::RoleOptions& options, app::RoleKind kind) {
  app::RoleSetup setup = app::load_role(options, kind);
  check_mission(setup.world, options.scenario_path);
  return setup;
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
