// What every MAPF solver returns, and how it is told to stop (solver.hpp has the one interface).
// Plain values; StopCondition::reached() is thread-safe if its predicate is.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "swarm/planner/grid/deadline.hpp"
#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf {

enum class Status {
  Solved,           // a conflict-free plan (validated)
  Timeout,          // the stop condition fired first; paths = the best plan found (may be empty)
  Infeasible,       // proven that no plan exists (message: why)
  Failed,           // the method ended without a conflict-free plan and without a proof (the GA
                    // after its generations; a search that ran out of options it can try)
  Unsupported,      // the solver cannot take this instance (e.g. reserved paths, paper-only GA)
  InvalidInstance,  // bad input (message: check_instance's problems)
};

// "solved", "timeout", "infeasible", "failed", "unsupported", "invalid-instance".
[[nodiscard]] const char* to_string(Status status);

struct SearchStats {
  long long high_level_expanded = 0;   // CT nodes (CBS, ECBS), configurations (LaCAM), generations (GA)
  long long high_level_generated = 0;
  long long low_level_expanded = 0;    // space-time search nodes
};

struct Result {
  Status status = Status::Failed;
  std::vector<Path> paths;   // one per agent, path[t] = cell at time t; empty when there is none
  int conflicts = 0;         // validate()'s conflict count of `paths` (0 when Solved)
  long long soc = kNoCost;   // sum_of_costs(paths), kNoCost without paths
  int makespan = kNoCost;
  long long lower_bound = kNoCost;  // sum of individual shortest paths
  double seconds = 0;        // wall time of the call
  std::string message;       // why, for Infeasible / Unsupported / InvalidInstance / Failed
  SearchStats stats;
};

// When to stop: at a deadline, when a predicate says so, or both (whichever comes first).
struct StopCondition {
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  std::function<bool()> predicate;  // may be empty

  static StopCondition after(double seconds) {
    StopCondition s;
    s.deadline = deadline_after(seconds);
    return s;
  }
  static StopCondition never() { return {}; }
  [[nodiscard]] bool reached() const {
    return std::chrono::steady_clock::now() >= deadline || (predicate && predicate());
  }
};

}  // namespace swarm::planner::mapf
