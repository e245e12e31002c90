// What the run's settings allow every task: whether a phase is given the map, and whether message
// delivery is bounded in ticks. (A task's own settings become planner inputs in its folder,
// tasks/<name>/.)
#pragma once

#include <cstdint>

#include "swarm/proto/scenario.pb.h"

namespace swarm::config {

// Are the robots given the map (the map file's cells) for phase `index` of mission_phases(s)? Yes
// when no phase that learns the map (idl/scenario.proto `learns_map`: exploration) comes at or
// before it (DARP, MAPF and the tour planners assume a known map). The one rule the GCS, the leaders and the role set-up follow.
[[nodiscard]] bool map_given(const swarm::scenario::Scenario& s, std::size_t index);
// Does any phase give the robots the map? Only then may a role other than the simulator hold it.
[[nodiscard]] bool any_map_given(const swarm::scenario::Scenario& s);

// Does every message of the run arrive within a number of ticks known in advance (its link's
// delay + jitter)? Not with loss (a re-sent message comes later), a bandwidth cap (it queues) or
// in real time. A plan driven by its own timing (MAPF_EXECUTE_TIMED) needs this: its start tick
// allows for the delays, and a route that came later would set off behind the others.
[[nodiscard]] bool delivery_ticks_bounded(const swarm::scenario::Scenario& s);

}  // namespace swarm::config
