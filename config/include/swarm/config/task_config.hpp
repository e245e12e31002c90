// From a phase's settings in the scenario (idl/scenario.proto: Cover, Mapf, Collect) to the plain
// config structs of the planners in planner_core: the one translation both the GCS's and the
// leaders' side of a task use.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarm/planner/coverage/cover_routes.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm/planner/tours/tour.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::config {

// DARP and the coverage order for a cover phase; `seed` is the run's (mixed with `salt` so the
// GCS's and each leader's divisions draw different numbers).
[[nodiscard]] planner::CoverRoutesConfig cover_routes_config(const swarm::scenario::Cover& cover, std::uint64_t seed,
                                                             std::uint64_t salt);

// Are the robots given the map (the map file's cells) for phase `index` of mission_phases(s)? Yes
// when no explore phase comes before it (DARP, MAPF and the tour planners assume a known map);
// never for an explore phase. The one rule the GCS, the leaders and the role set-up follow.
[[nodiscard]] bool map_given(const swarm::scenario::Scenario& s, std::size_t index);
// Does any phase give the robots the map? Only then may a role other than the simulator hold it.
[[nodiscard]] bool any_map_given(const swarm::scenario::Scenario& s);

// Does every message of the run arrive within a number of ticks known in advance (its link's
// delay + jitter)? Not with loss (a re-sent message comes later), a bandwidth cap (it queues) or
// in real time. A plan driven by its own timing (MAPF_EXECUTE_TIMED) needs this: its start tick
// allows for the delays, and a route that came later would set off behind the others.
[[nodiscard]] bool delivery_ticks_bounded(const swarm::scenario::Scenario& s);

// A mapf phase's settings with `execution: MAPF_EXECUTE_AUTO` made concrete for this scenario:
// MAPF_EXECUTE_TIMED when every link class has no delay, jitter, loss or bandwidth cap, the scenario schedules no
// fault (kill, cut or freeze) and the run is in lockstep (the plan's own timing is then exactly executable, so the executed
// makespan equals the planned one); MAPF_EXECUTE_ADG otherwise (a wait costs a message round
// trip, but no delay can cause a conflict). The GCS and every leader resolve it alike.
[[nodiscard]] swarm::scenario::Mapf resolved_mapf(const swarm::scenario::Mapf& mapf,
                                                  const swarm::scenario::Scenario& scenario);

// The MAPF solver of a mapf phase (ECBS with its w by default).
[[nodiscard]] planner::mapf::SolverConfig mapf_solver_config(const swarm::scenario::Mapf& mapf, std::uint64_t seed);

}  // namespace swarm::config
