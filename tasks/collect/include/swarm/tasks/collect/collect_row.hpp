// Collecting objects on tours (docs/papers.md section 4): its registry row (tasks/task_row.hpp).
#pragma once

#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

[[nodiscard]] TaskRow collect_row();

}  // namespace swarm::tasks
