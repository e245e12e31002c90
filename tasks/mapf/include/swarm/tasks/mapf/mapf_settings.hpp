// A mapf phase's settings (idl/scenario.proto Mapf) made concrete for the run, and as the MAPF
// solver's inputs: the one translation the GCS's and the leaders' parts (and rendezvous) use.
#pragma once

#include <cstdint>

#include "swarm/planner/mapf/solver.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::tasks {

// A mapf phase's settings with `execution: MAPF_EXECUTE_AUTO` made concrete for this scenario:
// MAPF_EXECUTE_TIMED when every link class has no delay, jitter, loss or bandwidth cap, the scenario schedules no
// fault (kill, cut or freeze) and the run is in lockstep (the plan's own timing is then exactly executable, so the executed
// makespan equals the planned one); MAPF_EXECUTE_ADG otherwise (a wait costs a message round
// trip, but no delay can cause a conflict). The GCS and every leader resolve it alike.
[[nodiscard]] swarm::scenario::Mapf resolved_mapf(const swarm::scenario::Mapf& mapf,
                                                  const swarm::scenario::Scenario& scenario);

// How the leaders drive the traffic layer's windows (explore, cover and collect): always by
// each window's action-dependency graph. A robot lost without warning then only makes the others
// wait (timed driving would send them into its cell), and in lockstep without delay it costs
// next to nothing: explore,cover,mapf,collect on small, maze1 and open, 3 x 3 robots, took
// 252 / 1,258 / 1,292 cover ticks by the graph against 233 / 1,252 / 1,286 timed, and collect
// 100 / 284 / 278 against 108 / 288 / 288.
[[nodiscard]] swarm::scenario::Mapf traffic_driving();

// What an explore, cover or collect phase's `traffic: false` is told: the classic drives are gone.
inline constexpr const char* kOnlyTheLayer =
    "be true: the classic drive (each robot or leader finding its own way, with detours and back-offs) is gone, "
    "and every explore, cover and collect phase drives through the traffic layer (docs/traffic.md)";

// The MAPF solver of a mapf phase (ECBS with its w by default).
[[nodiscard]] planner::mapf::SolverConfig mapf_solver_config(const swarm::scenario::Mapf& mapf, std::uint64_t seed);

}  // namespace swarm::tasks
