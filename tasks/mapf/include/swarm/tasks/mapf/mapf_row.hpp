// Multi-agent path finding (docs/papers.md section 3): its registry row (tasks/task_row.hpp).
#pragma once

#include <string>

#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

[[nodiscard]] TaskRow mapf_row();

// The checks of how a plan is made and driven (solver bound `w`, `time_limit_s`, `execution`),
// for any task that drives its robots with this one's parts; `field` names the settings message.
void check_mapf_paths(const swarm::scenario::Mapf& mapf, const swarm::scenario::Scenario& scenario,
                      const std::string& field, config::Problems& problems);

}  // namespace swarm::tasks
