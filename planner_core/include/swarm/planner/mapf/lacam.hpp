// LaCAM*: the scalable solver (hundreds to thousands of agents) — its options.
//
// Okumura, "LaCAM: Search-Based Algorithm for Quick Multi-Agent Pathfinding", AAAI 2023, and
// "Improving LaCAM for Scalable Eventually Optimal Multi-Agent Pathfinding", IJCAI 2023 (LaCAM*).
// A depth-first search over CONFIGURATIONS (one cell per agent): each search node generates its
// successor configuration lazily with PIBT (Okumura et al., "Priority inheritance with
// backtracking for iterative multi-agent path finding", AIJ 2022), guided by a tree of low-level
// constraints ("agent i goes to cell v") that is widened one agent at a time whenever the node is
// revisited, so every successor configuration is eventually tried. It is complete: it returns a
// solution if one exists and, on a finite graph, proves that none exists when the search space is
// exhausted (Status::Infeasible). PIBT here uses the swap technique of LaCAM* (two agents that must
// pass each other in a corridor trade places). With `refine`, LaCAM* keeps searching after the
// first solution and rewires the search tree towards lower sums of costs until the stop
// condition (it is eventually optimal); by default it returns the first solution.
//
// Solutions are far from optimal (their sum of costs is often several times the lower bound);
// they come in milliseconds where CBS-style searches give up. Reserved paths are not supported
// (the search is over configurations, not time): such instances get Status::Unsupported. Under
// the paper's rules (warehouse.hpp) it searches the paper's action model and agents vanish at
// their goals; the swap technique is then off (a stop lasts 2 steps).
//
// Run it through solve() (solver.hpp):
//   SolverConfig c;  c.kind = SolverKind::Lacam;  c.lacam.refine = true;   // LaCAM* until the limit
//   const Result r = solve(instance, c, StopCondition::after(10.0));
#pragma once

#include <cstdint>

namespace swarm::planner::mapf {

struct LacamConfig {
  std::uint64_t seed = 0;     // tie-breaking and restarts (through rng.hpp)
  bool refine = false;        // LaCAM*: improve the sum of costs until the stop condition
  bool swap = true;           // PIBT's swap technique (standard rules only)
  double restart_rate = 0.001;  // probability of restarting the DFS from the root on a revisit
};

}  // namespace swarm::planner::mapf
