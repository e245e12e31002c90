// Coverage (docs/papers.md sections 2 and 5): its registry row (tasks/task_row.hpp).
#pragma once

#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

[[nodiscard]] TaskRow cover_row();

}  // namespace swarm::tasks
