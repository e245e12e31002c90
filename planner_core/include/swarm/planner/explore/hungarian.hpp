// Minimum-cost assignment of rows to columns (the Hungarian / Kuhn-Munkres problem).
//
// Used by the group-frontier explorer (docs/papers.md section 1) twice: leaders to frontier segments
// (case B, every leader solves the same matrix and keeps its own row) and robots to waypoints
// inside a group.
//
// Algorithm: shortest augmenting paths with dual potentials (Kuhn 1955, Munkres 1957, in the
// O(n^2 m) form of Jonker & Volgenant 1987): rows are added one at a time and each is routed to
// a free column along a Dijkstra-like shortest path in the reduced costs.
//
// Rectangular matrices are fine. With n rows and m columns every row gets at most one column and
// every column at most one row; min(n, m) pairs are made, so when n > m exactly n - m rows get -1.
// Costs may be negative but must be finite (forbid a pair with a large finite cost, not infinity).
//
// Deterministic: the same matrix always gives the same assignment (ties are broken by the fixed
// scan order, lowest column index first), on every machine: only additions, subtractions and
// comparisons touch the costs. Thread-safe: no shared state.
//
//   Eigen::MatrixXd c(2, 3);
//   c << 4, 1, 6,
//        2, 0, 5;
//   swarm::planner::Assignment a = swarm::planner::hungarian(c);
//   // a.row_to_col == {1, 0}, a.total_cost == 3
#pragma once

#include <Eigen/Core>
#include <vector>

namespace swarm::planner {

struct Assignment {
  std::vector<int> row_to_col;  // size = rows; column index, or -1 if the row is unassigned
  double total_cost = 0;        // sum of cost(r, row_to_col[r]) over assigned rows
};

// O(min(n,m)^2 * max(n,m)) time, O(n + m) extra memory besides a transposed copy when n > m.
[[nodiscard]] Assignment hungarian(const Eigen::MatrixXd& cost);

}  // namespace swarm::planner
