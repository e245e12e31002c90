// One interface to every MAPF solver: an instance (a grid or a graph, instance.hpp) and a stop
// condition in, a status and a plan out.
//
//   SolverConfig cfg;                                   // CBS by default
//   cfg.kind = SolverKind::Ecbs;  cfg.ecbs.w = 1.2;
//   const Result r = solve(instance, cfg, StopCondition::after(10.0));
//   switch (r.status) {
//     case Status::Solved: drive(r.paths); break;       // conflict-free, validated
//     case Status::Timeout: ...                         // r.paths = best plan so far (r.conflicts > 0)
//     case Status::Infeasible: ...                      // proven: r.message says why
//     ...
//   }
//
// Every solver polls the stop condition often (at least every few milliseconds) and returns
// within a few milliseconds of it; none can hang (CBS and ECBS search for ever on unsolvable
// instances, cf. libMultiRobotPlanning issues #44 and #46: here the deadline ends them). The
// returned paths are checked by validate() (validate.hpp) before the result is returned: a plan
// that fails the check is never reported as Solved. Deterministic: the same instance and config
// give the same result (the seeds are config fields). Each call is independent and thread-safe.
//
// Solvers (see each header for its paper and options):
//   cbs.hpp   CBS, optimal sum of costs, with cardinal-conflict priority and bypassing (ICBS);
//             its timeout plan is the CT node with the fewest conflicts, or (the paper's rule)
//             the last one expanded.
//   cbs.hpp   ECBS: bounded-suboptimal, sum of costs <= w * optimum.
//   lacam.hpp LaCAM* with PIBT (swap variant): hundreds to thousands of agents, complete; the
//             first solution by default, refined for the rest of the time on request.
//   ga.hpp    the paper's direction-ordering GA, two-stage and single-stage, paper world only
//             (Unsupported on any other grid and on a graph).
// CBS, ECBS and LaCAM* run on grid and graph instances alike.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "swarm/planner/mapf/cbs.hpp"
#include "swarm/planner/mapf/ga.hpp"
#include "swarm/planner/mapf/instance.hpp"
#include "swarm/planner/mapf/lacam.hpp"
#include "swarm/planner/mapf/result.hpp"

namespace swarm::planner::mapf {

enum class SolverKind { Cbs, Ecbs, Lacam, Ga, Ga1 };

// "cbs", "ecbs", "lacam", "ga", "ga1".
[[nodiscard]] const char* to_string(SolverKind kind);
// The kind named `name` (as to_string writes it); false if there is none.
[[nodiscard]] bool parse_solver(const std::string& name, SolverKind& out);
// Every solver name, in the order above.
[[nodiscard]] std::vector<std::string> solver_names();

struct SolverConfig {
  SolverKind kind = SolverKind::Cbs;
  CbsConfig cbs;       // used by Cbs
  EcbsConfig ecbs;     // used by Ecbs
  LacamConfig lacam;   // used by Lacam
  GaConfig ga;         // used by Ga (two_stage forced true) and Ga1 (forced false)
};

// Checks the instance (check_instance: bad input gives Status::InvalidInstance with the problems in
// message), looks for a cheap proof of infeasibility (feasibility_problem), runs the solver and
// validates its plan (conflicts, soc, makespan, lower_bound and seconds filled in).
[[nodiscard]] Result solve(const Instance& in, const SolverConfig& config, const StopCondition& stop);

}  // namespace swarm::planner::mapf
