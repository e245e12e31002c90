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

void resolve_mission(config::World& world, const std::string& source) {
  config::Problems problems(source);
  const auto phases = config::mission_phases(world.scenario);
  std::vector<const TaskRow*> rows;
  std::vector<std::string> fields;  // "mission.phase[i].TASK"
  for (std::size_t i = 0; i < phases.size(); ++i) {
    rows.push_back(&task_row(phases[i]));
    fields.push_back("mission.phase[" + std::to_string(i) + "]." + rows.back()->name);
    if (rows.back()->check) rows.back()->check(phases[i], world, fields.back(), problems);
  }
  problems.throw_if_any();
  world.phase_data.assign(phases.size(), {});
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (rows[i]->resolve) world.phase_data[i] = rows[i]->resolve(phases[i], world, source + ": " + fields[i]);
  }
}

app::RoleSetup load_role(const app::RoleOptions& options, app::RoleKind kind) {
  return app::load_role(options, kind, [&](config::World& world) { resolve_mission(world, options.scenario_path); });
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
