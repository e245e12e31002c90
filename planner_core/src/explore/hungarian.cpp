#include "swarm/planner/explore/hungarian.hpp"

#include <algorithm>
#include <cassert>
#include <limits>

namespace swarm::planner {
namespace {

// Solves the case rows <= cols; returns the row matched to each column (-1 = free column).
// Potentials u (rows) and v (cols) keep every reduced cost a(i,j) - u(i) - v(j) >= 0; each new
// row is connected by a shortest path in reduced costs from a virtual column 0, then the path is
// flipped. Index 0 of p/way is that virtual column, so rows and columns are 1-based below.
std::vector<int> solve_wide(const Eigen::MatrixXd& a) {
  const int n = static_cast<int>(a.rows());
  const int m = static_cast<int>(a.cols());
  assert(n <= m);
  constexpr double kInf = std::numeric_limits<double>::infinity();

  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0), minv(m + 1);
  std::vector<int> p(m + 1, 0), way(m + 1, 0);
  std::vector<char> used(m + 1);

  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::fill(minv.begin(), minv.end(), kInf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[j0] = 1;
      const int i0 = p[j0];
      double delta = kInf;
      int j1 = -1;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = a(i0 - 1, j - 1) - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        // Strict '<': on ties the lowest column wins, which makes the result reproducible.
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      // j1 == -1 only if costs are NaN/inf, which the contract forbids.
      assert(j1 != -1);
      if (j1 == -1) break;
      for (int j = 0; j <= m; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    // Flip the augmenting path back to the virtual column.
    do {
      const int j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }

  std::vector<int> col_to_row(m, -1);
  for (int j = 1; j <= m; ++j) {
    if (p[j] != 0) col_to_row[j - 1] = p[j] - 1;
  }
  return col_to_row;
}

}  // namespace

Assignment hungarian(const Eigen::MatrixXd& cost) {
  assert(cost.allFinite() && "hungarian: costs must be finite; use a large value to forbid");
  const int n = static_cast<int>(cost.rows());
  const int m = static_cast<int>(cost.cols());
  Assignment out;
  out.row_to_col.assign(n, -1);
  if (n == 0 || m == 0) return out;

  if (n <= m) {
    const std::vector<int> col_to_row = solve_wide(cost);
    for (int j = 0; j < m; ++j) {
      if (col_to_row[j] >= 0) out.row_to_col[col_to_row[j]] = j;
    }
  } else {
    // More rows than columns: assign columns to rows on the transpose; the rows no column
    // picked stay -1 (exactly n - m of them).
    const Eigen::MatrixXd t = cost.transpose();
    const std::vector<int> row_of_col = solve_wide(t);  // indexed by original row
    for (int r = 0; r < n; ++r) {
      if (row_of_col[r] >= 0) out.row_to_col[r] = row_of_col[r];
    }
  }
  // Sum the original entries (not the dual objective) so the total is exact and row-ordered.
  for (int r = 0; r < n; ++r) {
    if (out.row_to_col[r] >= 0) out.total_cost += cost(r, out.row_to_col[r]);
  }
  return out;
}

}  // namespace swarm::planner
