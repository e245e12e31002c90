// Multi-agent path finding (docs/papers.md section 3): its registry row (tasks/task_row.hpp).
#pragma once

#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

[[nodiscard]] TaskRow mapf_row();

}  // namespace swarm::tasks
