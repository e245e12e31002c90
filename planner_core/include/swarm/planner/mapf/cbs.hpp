// Conflict-based search and its bounded-suboptimal variant: the options (solver.hpp runs them).
//
// CBS: Sharon, Stern, Felner & Sturtevant, "Conflict-based search for optimal multi-agent
// pathfinding", Artificial Intelligence 219, 2015. A constraint tree (CT): each node holds one
// path per agent, planned alone under the node's constraints; the best node's first conflict
// splits it into two children, each forbidding one of the two agents that cell (or move) at that
// time. Optimal in the sum of costs. With the improvements of ICBS (Boyarski et al., IJCAI 2015):
//   - prioritising conflicts: cardinal conflicts (both agents' costs must rise, read off their MDDs:
//     the set of all their optimal paths) are split first, then semi-cardinal, then the rest;
//   - bypassing: a child whose new path costs the same and has fewer conflicts replaces the
//     parent's path instead of splitting;
//   - a low-level space-time A* that breaks ties towards fewer conflicts with the other agents'
//     paths (a conflict-avoidance table) and folds time past the last constraint, so it always ends.
//
// ECBS: Barer, Sharon, Stern & Felner, SoCS 2014. Both levels use focal search with weight w: the
// low level returns a path within w of the agent's optimum that has few conflicts; the high level
// expands, among the CT nodes whose cost is within w of the best lower bound, the one with the
// fewest conflicts. The solution costs at most w times the optimum. Bypassing as in EECBS (Li,
// Ruml & Koenig, AAAI 2021): a child path within the bound with fewer conflicts is adopted.
//
// Reserved paths (instance.hpp) are hard constraints of the low level. Under the paper's rules
// the low level searches the paper's action model (stops only in passage middles or at the start,
// 2 steps each) and agents vanish at their goals.
//
// Run them through solve() (solver.hpp); the configs are plain values, safe to copy across threads:
//   SolverConfig c;  c.kind = SolverKind::Ecbs;  c.ecbs.w = 1.2;
//   const Result r = solve(instance, c, StopCondition::after(10.0));
#pragma once

#include <cstdint>

namespace swarm::planner::mapf {

// Which plan a search that ran out of time returns.
enum class TimeoutPlan {
  FewestConflicts,  // the CT node with the fewest conflicts seen (ties: lower cost)
  LastExpanded,     // the paper's rule: the last CT node explored
};

struct CbsConfig {
  bool prioritize_conflicts = true;  // cardinal > semi-cardinal > other (MDDs)
  bool bypass = true;
  TimeoutPlan timeout_plan = TimeoutPlan::FewestConflicts;
};

struct EcbsConfig {
  double w = 1.2;  // suboptimality bound, >= 1
  bool bypass = true;
  TimeoutPlan timeout_plan = TimeoutPlan::FewestConflicts;
};

}  // namespace swarm::planner::mapf
