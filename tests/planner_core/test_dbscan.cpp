#include "swarm/planner/explore/dbscan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {
namespace {

// A hand-drawn point set: every character other than '.' is a point, read row by row (row r has
// y = r, column c has x = c). A letter names the cluster the point must end up in; '*' is noise.
// Expected labels number the letters in order of first appearance, as dbscan numbers clusters.
struct Drawing {
  std::vector<Cell> points;
  std::vector<int> expected;
};

Drawing draw(const std::vector<std::string>& rows) {
  Drawing d;
  std::map<char, int> id;
  for (int y = 0; y < static_cast<int>(rows.size()); ++y) {
    for (int x = 0; x < static_cast<int>(rows[y].size()); ++x) {
      const char ch = rows[y][x];
      if (ch == '.') continue;
      d.points.push_back({x, y});
      if (ch == '*') {
        d.expected.push_back(-1);
      } else {
        auto it = id.find(ch);
        if (it == id.end()) it = id.emplace(ch, static_cast<int>(id.size())).first;
        d.expected.push_back(it->second);
      }
    }
  }
  return d;
}

// O(N^2) textbook DBSCAN with the same conventions, as a reference.
std::vector<int> naive_dbscan(const std::vector<Cell>& p, double eps, int min_points) {
  const int n = static_cast<int>(p.size());
  auto nbrs = [&](int i) {
    std::vector<int> out;
    for (int j = 0; j < n; ++j) {
      const double dx = p[j].x - p[i].x, dy = p[j].y - p[i].y;
      if (dx * dx + dy * dy <= eps * eps) out.push_back(j);
    }
    return out;
  };
  std::vector<int> label(n, -2);
  int k = 0;
  for (int i = 0; i < n; ++i) {
    if (label[i] != -2) continue;
    std::vector<int> q = nbrs(i);
    if (static_cast<int>(q.size()) < min_points) {
      label[i] = -1;
      continue;
    }
    label[i] = k;
    for (std::size_t h = 0; h < q.size(); ++h) {
      const int j = q[h];
      if (label[j] == -1) label[j] = k;
      if (label[j] != -2) continue;
      label[j] = k;
      std::vector<int> more = nbrs(j);
      if (static_cast<int>(more.size()) >= min_points) q.insert(q.end(), more.begin(), more.end());
    }
    ++k;
  }
  std::vector<int> remap(k, -1);
  int next = 0;
  for (int& l : label) {
    if (l < 0) continue;
    if (remap[l] < 0) remap[l] = next++;
    l = remap[l];
  }
  return label;
}

TEST(Dbscan, FourSeparateFrontierPieces) {
  // eps 1.5 links 8-neighbours (diagonals included), min_points 1: no noise.
  const Drawing d = draw({
      "aa....b",
      "a.....b",
      ".......",
      "cc...dd",
      "..c.d..",
  });
  EXPECT_EQ(dbscan(d.points, 1.5, 1), d.expected);
}

TEST(Dbscan, FourNeighbourhoodSplitsDiagonalTouch) {
  // With eps 1.0 only orthogonal neighbours link, so the diagonal step splits 'a' from 'b'.
  const Drawing d = draw({
      "aa..",
      "..b.",
      "..bb",
  });
  EXPECT_EQ(dbscan(d.points, 1.0, 1), d.expected);
  // With eps 1.5 the same points are one cluster.
  EXPECT_EQ(dbscan(d.points, 1.5, 1), (std::vector<int>{0, 0, 0, 0, 0}));
}

TEST(Dbscan, IsolatedPointsAreNoiseWithMinPointsThree) {
  // min_points counts the point itself: each 'b' sees 3 points ((6,2), (5,3), (6,3) are mutually
  // within 1.5). The two '*' see only themselves.
  const Drawing d = draw({
      "aaa...*",
      "aa.....",
      "......b",
      ".....bb",
      "*......",
  });
  EXPECT_EQ(dbscan(d.points, 1.5, 3), d.expected);
}

TEST(Dbscan, BorderPointsJoinButDoNotExpand) {
  // eps 1, min_points 3: in "aaaa" the ends have 2 neighbours (border), the middle ones are core.
  // The lone point 2 cells right of the line is noise: it touches only itself.
  const Drawing d = draw({"aaaa.*"});
  EXPECT_EQ(dbscan(d.points, 1.0, 3), d.expected);
}

TEST(Dbscan, ContestedBorderPointGoesToTheFirstCluster) {
  // min_points 4, eps 1. Cores: (0,1) and (2,1) (4 neighbours each, self included). (1,1) has 3
  // (itself, (0,1), (2,1)): a border point of both clusters. It must not merge them, and it goes
  // to the cluster that reaches it first (the left one, whose points come first).
  const std::vector<Cell> p = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {2, 0}, {2, 1}, {2, 2}};
  EXPECT_EQ(dbscan(p, 1.0, 4), (std::vector<int>{0, 0, 0, 0, 1, 1, 1}));
}

TEST(Dbscan, ClustersAreNumberedByTheirFirstPointEvenIfItIsABorderPoint) {
  // eps 1, min_points 3. Input order: (0,0) is a border point of the left cluster whose only core
  // (1,0) comes late; the right cluster's core (11,0) comes before it. The left cluster still gets
  // label 0 because its first point is the first point of the input.
  const std::vector<Cell> p = {{0, 0}, {10, 0}, {11, 0}, {12, 0}, {1, 0}, {2, 0}};
  EXPECT_EQ(dbscan(p, 1.0, 3), (std::vector<int>{0, 1, 1, 1, 0, 0}));
}

TEST(Dbscan, EpsIsInclusive) {
  const std::vector<Cell> p = {{0, 0}, {3, 4}};  // exactly 5 apart
  EXPECT_EQ(dbscan(p, 5.0, 1), (std::vector<int>{0, 0}));
  EXPECT_EQ(dbscan(p, 4.999, 1), (std::vector<int>{0, 1}));
  const std::vector<Cell> diag = {{0, 0}, {1, 1}};  // sqrt(2) apart
  EXPECT_EQ(dbscan(diag, std::sqrt(2.0), 1), (std::vector<int>{0, 0}));
  EXPECT_EQ(dbscan(diag, 1.41, 1), (std::vector<int>{0, 1}));
  // eps 0: only duplicates link.
  const std::vector<Cell> dup = {{2, 2}, {3, 2}, {2, 2}};
  EXPECT_EQ(dbscan(dup, 0.0, 2), (std::vector<int>{0, -1, 0}));
}

TEST(Dbscan, NegativeCoordinatesAndBucketEdges) {
  // Points straddle bucket borders (eps 2.5 -> 3-cell buckets) and the origin.
  const std::vector<Cell> p = {{-1, 0}, {1, 0}, {-4, -4}, {2, 2}, {-3, -2}};
  // (-1,0)-(1,0): 2; (1,0)-(2,2): sqrt5 = 2.24; (-1,0)-(-3,-2): 2.83 > 2.5; (-3,-2)-(-4,-4): 2.24.
  EXPECT_EQ(dbscan(p, 2.5, 1), (std::vector<int>{0, 0, 1, 0, 1}));
}

TEST(Dbscan, EmptyInput) { EXPECT_TRUE(dbscan({}, 1.5, 1).empty()); }

TEST(Dbscan, ClustersOfGroupsInInputOrderAndDropsNoise) {
  const std::vector<Cell> p = {{0, 0}, {5, 5}, {1, 0}, {9, 9}};
  const std::vector<int> l = {0, 1, 0, -1};
  const auto c = clusters_of(p, l);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0], (std::vector<Cell>{{0, 0}, {1, 0}}));
  EXPECT_EQ(c[1], (std::vector<Cell>{{5, 5}}));
}

TEST(Dbscan, MatchesTextbookReferenceOnRandomFrontierLikeSets) {
  Rng rng(99);
  for (int rep = 0; rep < 20; ++rep) {
    std::vector<Cell> p;
    const int n = 300 + rep * 10;
    for (int i = 0; i < n; ++i) p.push_back({rng.uniform_int(-20, 40), rng.uniform_int(0, 40)});
    for (double eps : {1.0, 1.5, 2.5}) {
      for (int mp : {1, 3, 5}) {
        SCOPED_TRACE(testing::Message() << "rep " << rep << " eps " << eps << " min " << mp);
        EXPECT_EQ(dbscan(p, eps, mp), naive_dbscan(p, eps, mp));
      }
    }
  }
}

TEST(Dbscan, ThousandsOfFrontierCellsClusterAsTheNaiveSearchDoes) {
  // Every cell on the border of 40 rooms of a 100 x 100 map: ~ 6000 frontier-like cells.
  std::vector<Cell> p;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x)
      if (x % 10 == 0 || y % 5 == 0 || (x + y) % 17 == 0) p.push_back({x, y});
  ASSERT_GT(p.size(), 3000u);
  const std::vector<int> l = dbscan(p, 1.5, 1);
  EXPECT_EQ(l.size(), p.size());
  EXPECT_EQ(l, naive_dbscan(p, 1.5, 1));
}

}  // namespace
}  // namespace swarm::planner
