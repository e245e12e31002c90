#include "swarm/planner/explore/hungarian.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {
namespace {

// Checks the structural contract: every row at most one column, every column at most one row,
// exactly min(n, m) pairs, and total_cost equals the sum of the chosen entries.
void expect_valid(const Eigen::MatrixXd& c, const Assignment& a) {
  const int n = static_cast<int>(c.rows());
  const int m = static_cast<int>(c.cols());
  ASSERT_EQ(static_cast<int>(a.row_to_col.size()), n);
  std::vector<int> used(m, 0);
  int pairs = 0;
  double sum = 0;
  for (int r = 0; r < n; ++r) {
    const int col = a.row_to_col[r];
    if (col < 0) {
      EXPECT_EQ(col, -1);
      continue;
    }
    ASSERT_LT(col, m);
    EXPECT_EQ(used[col]++, 0) << "column " << col << " used twice";
    ++pairs;
    sum += c(r, col);
  }
  EXPECT_EQ(pairs, std::min(n, m));
  EXPECT_DOUBLE_EQ(a.total_cost, sum);
}

// Minimum over every injective map of the smaller side into the larger one.
double brute_force(const Eigen::MatrixXd& c) {
  const int n = static_cast<int>(c.rows());
  const int m = static_cast<int>(c.cols());
  const bool wide = n <= m;
  const int small = wide ? n : m;
  const int large = wide ? m : n;
  std::vector<int> perm(large);
  std::iota(perm.begin(), perm.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  // Permutations of the large side; the first `small` entries are the partners.
  do {
    double s = 0;
    for (int i = 0; i < small; ++i) s += wide ? c(i, perm[i]) : c(perm[i], i);
    best = std::min(best, s);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

TEST(Hungarian, HeaderExample) {
  Eigen::MatrixXd c(2, 3);
  c << 4, 1, 6,
       2, 0, 5;
  const Assignment a = hungarian(c);
  EXPECT_EQ(a.row_to_col, (std::vector<int>{1, 0}));
  EXPECT_DOUBLE_EQ(a.total_cost, 3.0);
}

TEST(Hungarian, ClassicThreeByThree) {
  // Hand-solved over all 6 permutations (column of row 0, 1, 2):
  //   (0,1,2) 4+3+2=9  (0,2,1) 4+5+2=11  (1,0,2) 1+2+2=5
  //   (1,2,0) 1+5+3=9  (2,0,1) 3+2+2=7   (2,1,0) 3+3+3=9   -> unique minimum 5 at (1,0,2).
  Eigen::MatrixXd c(3, 3);
  c << 4, 1, 3,
       2, 3, 5,
       3, 2, 2;
  const Assignment a = hungarian(c);
  EXPECT_EQ(a.row_to_col, (std::vector<int>{1, 0, 2}));
  EXPECT_DOUBLE_EQ(a.total_cost, 5.0);
}

TEST(Hungarian, GreedyIsWrongHere) {
  // Greedy would give row 0 its cheapest column 0 (1) and leave row 1 with 100: 101.
  // The optimum swaps: 2 + 3 = 5.
  Eigen::MatrixXd c(2, 2);
  c << 1, 2,
       3, 100;
  const Assignment a = hungarian(c);
  EXPECT_EQ(a.row_to_col, (std::vector<int>{1, 0}));
  EXPECT_DOUBLE_EQ(a.total_cost, 5.0);
}

TEST(Hungarian, MoreRowsThanColumnsLeavesExactlyTheExtraRowsUnassigned) {
  // Three leaders, one segment: the cheapest row (1) takes it; rows 0 and 2 get -1.
  Eigen::MatrixXd c(3, 1);
  c << 5, 2, 7;
  const Assignment a = hungarian(c);
  EXPECT_EQ(a.row_to_col, (std::vector<int>{-1, 0, -1}));
  EXPECT_DOUBLE_EQ(a.total_cost, 2.0);

  // 4 x 2: best pair is rows 2 and 3 (1 + 1 = 2).
  Eigen::MatrixXd d(4, 2);
  d << 9, 9,
       8, 7,
       1, 6,
       6, 1;
  const Assignment b = hungarian(d);
  EXPECT_EQ(b.row_to_col, (std::vector<int>{-1, -1, 0, 1}));
  EXPECT_DOUBLE_EQ(b.total_cost, 2.0);
}

TEST(Hungarian, MoreColumnsThanRows) {
  Eigen::MatrixXd c(1, 4);
  c << 3, 1, 4, 1;
  const Assignment a = hungarian(c);
  EXPECT_EQ(a.row_to_col, (std::vector<int>{1}));  // tie 1 vs 1: lowest column
  EXPECT_DOUBLE_EQ(a.total_cost, 1.0);
}

TEST(Hungarian, NegativeCostsAreFine) {
  Eigen::MatrixXd c(2, 2);
  c << -5, 0,
        0, -5;
  const Assignment a = hungarian(c);
  EXPECT_EQ(a.row_to_col, (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(a.total_cost, -10.0);
}

TEST(Hungarian, EmptyMatrices) {
  EXPECT_TRUE(hungarian(Eigen::MatrixXd(0, 0)).row_to_col.empty());
  EXPECT_TRUE(hungarian(Eigen::MatrixXd(0, 3)).row_to_col.empty());
  const Assignment a = hungarian(Eigen::MatrixXd(3, 0));
  EXPECT_EQ(a.row_to_col, (std::vector<int>{-1, -1, -1}));
  EXPECT_EQ(a.total_cost, 0.0);
}

TEST(Hungarian, AllEqualCostsStillAPerfectMatchingAndReproducible) {
  const Eigen::MatrixXd c = Eigen::MatrixXd::Constant(4, 4, 2.5);
  const Assignment a = hungarian(c);
  expect_valid(c, a);
  EXPECT_DOUBLE_EQ(a.total_cost, 10.0);
  EXPECT_EQ(hungarian(c).row_to_col, a.row_to_col);
}

TEST(Hungarian, MatchesBruteForceOnRandomMatrices) {
  Rng rng(20240601);
  int checked = 0;
  // Every shape from 1x1 to 6x6 (3x5 and 5x3 included), 8 matrices each = 288 matrices.
  for (int n = 1; n <= 6; ++n) {
    for (int m = 1; m <= 6; ++m) {
      for (int rep = 0; rep < 8; ++rep) {
        Eigen::MatrixXd c(n, m);
        for (int i = 0; i < n; ++i) {
          for (int j = 0; j < m; ++j) {
            // Half the matrices use small integers so ties are common; half use reals.
            c(i, j) = rep % 2 == 0 ? static_cast<double>(rng.uniform_int(0, 4))
                                   : rng.uniform(-10.0, 10.0);
          }
        }
        const Assignment a = hungarian(c);
        SCOPED_TRACE(testing::Message() << n << "x" << m << " rep " << rep << "\n" << c);
        expect_valid(c, a);
        EXPECT_NEAR(a.total_cost, brute_force(c), 1e-9);
        EXPECT_EQ(hungarian(c).row_to_col, a.row_to_col);  // deterministic
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 200);
}

TEST(Hungarian, ThreeByFiveAndFiveByThreeAgreeOnCost) {
  Rng rng(7);
  for (int rep = 0; rep < 20; ++rep) {
    Eigen::MatrixXd c(3, 5);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 5; ++j) c(i, j) = rng.uniform(0.0, 1.0);
    const Assignment wide = hungarian(c);
    const Eigen::MatrixXd t = c.transpose();
    const Assignment tall = hungarian(t);
    expect_valid(c, wide);
    expect_valid(t, tall);
    EXPECT_NEAR(wide.total_cost, tall.total_cost, 1e-12);
    EXPECT_NEAR(wide.total_cost, brute_force(c), 1e-12);
  }
}

}  // namespace
}  // namespace swarm::planner
