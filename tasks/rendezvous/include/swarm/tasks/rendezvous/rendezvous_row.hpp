// Rendezvous: every living robot gathers around a point, or back at the run's start, packed as
// tightly as the free cells allow (gather.hpp). Its registry row (tasks/task_row.hpp).
#pragma once

#include "swarm/tasks/task_row.hpp"

namespace swarm::tasks {

[[nodiscard]] TaskRow rendezvous_row();

// How a rendezvous makes and drives its plan: a mapf phase's settings without goals.
[[nodiscard]] swarm::scenario::Mapf rendezvous_paths(const swarm::scenario::Rendezvous& rendezvous,
                                                     const swarm::scenario::Scenario& scenario);

}  // namespace swarm::tasks
