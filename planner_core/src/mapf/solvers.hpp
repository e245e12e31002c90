// The solvers behind solve() (solver.hpp). Each returns its status, its plan (paths of cells) and
// its search statistics; solve() checks the instance before and validates the plan after.
#pragma once

#include "swarm/planner/mapf/solver.hpp"

namespace swarm::planner::mapf::detail {

// w == 1 with cbs options: CBS; w > 1: ECBS.
[[nodiscard]] Result run_conflict_search(const Instance& in, double w, bool prioritize, bool bypass,
                                         TimeoutPlan timeout_plan, const StopCondition& stop);
[[nodiscard]] Result run_lacam(const Instance& in, const LacamConfig& config, const StopCondition& stop);
[[nodiscard]] Result run_ga(const Instance& in, const GaConfig& config, bool two_stage, const StopCondition& stop);

}  // namespace swarm::planner::mapf::detail
