#include "swarm/planner/mapf/solver.hpp"

#include <array>

#include "solvers.hpp"
#include "swarm/planner/mapf/validate.hpp"

namespace swarm::planner::mapf {
namespace {

constexpr std::array<std::pair<SolverKind, const char*>, 5> kSolvers = {{
    {SolverKind::Cbs, "cbs"},
    {SolverKind::Ecbs, "ecbs"},
    {SolverKind::Lacam, "lacam"},
    {SolverKind::Ga, "ga"},
    {SolverKind::Ga1, "ga1"},
}};

}  // namespace

const char* to_string(Status status) {
  switch (status) {
    case Status::Solved: return "solved";
    case Status::Timeout: return "timeout";
    case Status::Infeasible: return "infeasible";
    case Status::Failed: return "failed";
    case Status::Unsupported: return "unsupported";
    case Status::InvalidInstance: return "invalid-instance";
  }
  return "?";
}

const char* to_string(SolverKind kind) {
  for (const auto& [k, name] : kSolvers) {
    if (k == kind) return name;
  }
  return "?";
}

bool parse_solver(const std::string& name, SolverKind& out) {
  for (const auto& [k, n] : kSolvers) {
    if (name == n) {
      out = k;
      return true;
    }
  }
  return false;
}

std::vector<std::string> solver_names() {
  std::vector<std::string> out;
  for (const auto& [k, n] : kSolvers) out.emplace_back(n);
  return out;
}

Result solve(const Instance& in, const SolverConfig& config, const StopCondition& stop) {
  const auto t0 = std::chrono::steady_clock::now();
  Result r;
  if (const auto problems = check_instance(in); !problems.empty()) {
    r.status = Status::InvalidInstance;
    for (const std::string& p : problems) r.message += (r.message.empty() ? "" : "; ") + p;
  } else if (const std::string why = feasibility_problem(in); !why.empty()) {
    r.status = Status::Infeasible;
    r.message = why;
    r.lower_bound = lower_bound(in);
  } else {
    switch (config.kind) {
      case SolverKind::Cbs:
        r = detail::run_conflict_search(in, 1.0, config.cbs.prioritize_conflicts, config.cbs.bypass,
                                        config.cbs.timeout_plan, stop);
        break;
      case SolverKind::Ecbs:
        r = detail::run_conflict_search(in, std::max(1.0, config.ecbs.w), false, config.ecbs.bypass,
                                        config.ecbs.timeout_plan, stop);
        break;
      case SolverKind::Lacam: r = detail::run_lacam(in, config.lacam, stop); break;
      case SolverKind::Ga: r = detail::run_ga(in, config.ga, true, stop); break;
      case SolverKind::Ga1: r = detail::run_ga(in, config.ga, false, stop); break;
    }
    r.lower_bound = lower_bound(in);
    if (!r.paths.empty()) {
      const ValidationReport v = validate(in, r.paths);
      r.conflicts = static_cast<int>(v.conflicts.size());
      r.soc = sum_of_costs(in, r.paths);
      r.makespan = makespan(in, r.paths);
      if (!v.problems.empty()) {
        // A solver bug: never report an illegal plan as a plan.
        r.status = Status::Failed;
        r.message = "the solver's plan breaks the rules: " + v.summary();
      } else if (r.status == Status::Solved && !v.ok()) {
        r.status = Status::Failed;
        r.message = "the solver's plan has conflicts: " + v.summary();
      }
    } else if (r.status == Status::Solved) {
      r.status = Status::Failed;
      r.message = "the solver returned no plan";
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace swarm::planner::mapf
