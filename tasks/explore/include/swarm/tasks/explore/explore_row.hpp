// Exploration (docs/papers.md section 1): its registry row (tasks/task_row.hpp).
#pragma once

#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

[[nodiscard]] TaskRow explore_row();

}  // namespace swarm::tasks
