#include "swarm/planner/explore/kmeans.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <vector>

#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {
namespace {

// --- rng.hpp (used by K-Means; no test file of its own) ---------------------------------------

TEST(Rng, SplitMix64KnownAnswer) {
  // Reference value of splitmix64 from state 0 (Vigna's splitmix64.c).
  std::uint64_t s = 0;
  EXPECT_EQ(splitmix64(s), 0xe220a8397b1dcdafULL);
}

TEST(Rng, StreamIsPinned) {
  // Pinned outputs (xoshiro256** seeded by splitmix64): if these change, every seeded plan in the
  // project changes with them, on every machine.
  Rng a(1);
  EXPECT_EQ(a.next(), 0xb3f2af6d0fc710c5ULL);
  EXPECT_EQ(a.next(), 0x853b559647364ceaULL);
  EXPECT_EQ(a.next(), 0x92f89756082a4514ULL);
  EXPECT_EQ(a.next(), 0x642e1c7bc266a3a7ULL);
  Rng b(42);
  EXPECT_EQ(b.uniform01(), 0.083862971059882163);
  EXPECT_EQ(b.uniform_int(-100, 100), -46);
  EXPECT_EQ(b.below(1000), 9u);
  EXPECT_EQ(mix_seed(1, 0, 0), 0xf7cadd881990cf7eULL);
  EXPECT_NE(Rng(1).next(), Rng(2).next());
}

TEST(Rng, HelpersStayInRange) {
  Rng r(123);
  std::set<int> seen;
  for (int i = 0; i < 10000; ++i) {
    const double u = r.uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    const double v = r.uniform(-2.0, 3.0);
    ASSERT_GE(v, -2.0);
    ASSERT_LT(v, 3.0);
    const int k = r.uniform_int(-3, 3);
    ASSERT_GE(k, -3);
    ASSERT_LE(k, 3);
    seen.insert(k);
    ASSERT_LT(r.below(7), 7u);
  }
  EXPECT_EQ(seen.size(), 7u);  // every value of -3..3 shows up
  EXPECT_EQ(r.uniform_int(5, 5), 5);
  // Extreme span must not overflow.
  const int big = r.uniform_int(std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
  (void)big;
}

TEST(Rng, MixSeedIsOrderSensitiveAndSpreads) {
  EXPECT_NE(mix_seed(1, 2, 3), mix_seed(3, 2, 1));
  EXPECT_NE(mix_seed(1, 7, 0), mix_seed(1, 8, 0));
  EXPECT_EQ(mix_seed(1, 7, 0), mix_seed(1, 7, 0));
  static_assert(mix_seed(1, 2) == mix_seed(1, 2));  // usable at compile time
}

// --- K-Means ----------------------------------------------------------------------------------

// Three tight 3x3 blobs far apart (centres (0,0), (50,0), (20,40)), interleaved in the input so
// the labels cannot simply follow the input order.
struct Blobs {
  std::vector<Eigen::Vector2d> points;
  std::vector<int> blob;
};

Blobs three_blobs() {
  const Eigen::Vector2d centre[3] = {{0, 0}, {50, 0}, {20, 40}};
  Blobs b;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int k = 0; k < 3; ++k) {
        b.points.push_back(centre[k] + Eigen::Vector2d(dx, dy));
        b.blob.push_back(k);
      }
    }
  }
  return b;
}

TEST(KMeans, RecoversWellSeparatedBlobsExactlyForEverySeed) {
  const Blobs b = three_blobs();
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    KMeansConfig cfg;
    cfg.k = 3;
    cfg.seed = seed;
    const KMeansResult r = kmeans(b.points, cfg);
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    ASSERT_EQ(r.centres.size(), 3u);
    ASSERT_EQ(r.labels.size(), b.points.size());
    EXPECT_TRUE(r.converged);
    // Same partition: blob k maps to one label, and different blobs to different labels.
    int label_of_blob[3] = {-1, -1, -1};
    for (std::size_t i = 0; i < b.points.size(); ++i) {
      int& l = label_of_blob[b.blob[i]];
      if (l < 0) l = r.labels[i];
      EXPECT_EQ(r.labels[i], l);
    }
    EXPECT_NE(label_of_blob[0], label_of_blob[1]);
    EXPECT_NE(label_of_blob[0], label_of_blob[2]);
    EXPECT_NE(label_of_blob[1], label_of_blob[2]);
    // Centres are the blob centres (symmetric 3x3 blobs: the mean is exact).
    EXPECT_EQ(r.centres[label_of_blob[0]], Eigen::Vector2d(0, 0));
    EXPECT_EQ(r.centres[label_of_blob[1]], Eigen::Vector2d(50, 0));
    EXPECT_EQ(r.centres[label_of_blob[2]], Eigen::Vector2d(20, 40));
  }
}

std::vector<Eigen::Vector2d> scattered(int n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < n; ++i) p.emplace_back(rng.uniform(0, 100), rng.uniform(0, 100));
  return p;
}

TEST(KMeans, SameSeedGivesBitIdenticalResult) {
  const auto pts = scattered(500, 5);
  KMeansConfig cfg;
  cfg.k = 6;
  cfg.seed = 77;
  const KMeansResult a = kmeans(pts, cfg);
  const KMeansResult b = kmeans(pts, cfg);
  EXPECT_EQ(a.labels, b.labels);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.converged, b.converged);
  ASSERT_EQ(a.centres.size(), b.centres.size());
  for (std::size_t c = 0; c < a.centres.size(); ++c) {
    EXPECT_EQ(a.centres[c].x(), b.centres[c].x());  // exact, not approximately equal
    EXPECT_EQ(a.centres[c].y(), b.centres[c].y());
  }
}

TEST(KMeans, DifferentSeedsMayDiffer) {
  // Uniform scatter has many local optima, so some of ten seeds must land in different ones.
  const auto pts = scattered(300, 9);
  std::set<std::vector<int>> outcomes;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    KMeansConfig cfg;
    cfg.k = 8;
    cfg.seed = seed;
    outcomes.insert(kmeans(pts, cfg).labels);
  }
  EXPECT_GT(outcomes.size(), 1u);
}

TEST(KMeans, LabelsAreNearestCentresAndCentresAreMeans) {
  const auto pts = scattered(200, 3);
  KMeansConfig cfg;
  cfg.k = 4;
  const KMeansResult r = kmeans(pts, cfg);
  ASSERT_TRUE(r.converged);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double own = (pts[i] - r.centres[r.labels[i]]).squaredNorm();
    for (const auto& c : r.centres) EXPECT_LE(own, (pts[i] - c).squaredNorm());
  }
  for (int c = 0; c < 4; ++c) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int n = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (r.labels[i] == c) sum += pts[i], ++n;
    ASSERT_GT(n, 0);
    EXPECT_NEAR((sum / n - r.centres[c]).norm(), 0.0, 1e-12);
  }
}

TEST(KMeans, EmptyInput) {
  const KMeansResult r = kmeans({}, KMeansConfig{});
  EXPECT_TRUE(r.centres.empty());
  EXPECT_TRUE(r.labels.empty());
  EXPECT_TRUE(r.converged);
}

TEST(KMeans, KIsClippedToDistinctPoints) {
  // Five points, two distinct positions, k = 4 -> two clusters.
  const std::vector<Eigen::Vector2d> p = {{1, 1}, {1, 1}, {4, 2}, {1, 1}, {4, 2}};
  KMeansConfig cfg;
  cfg.k = 4;
  const KMeansResult r = kmeans(p, cfg);
  ASSERT_EQ(r.centres.size(), 2u);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.labels[0], r.labels[1]);
  EXPECT_EQ(r.labels[0], r.labels[3]);
  EXPECT_EQ(r.labels[2], r.labels[4]);
  EXPECT_NE(r.labels[0], r.labels[2]);
  EXPECT_EQ(r.centres[r.labels[0]], Eigen::Vector2d(1, 1));
  EXPECT_EQ(r.centres[r.labels[2]], Eigen::Vector2d(4, 2));
}

TEST(KMeans, AllPointsIdentical) {
  const std::vector<Eigen::Vector2d> p(6, Eigen::Vector2d(3, -2));
  KMeansConfig cfg;
  cfg.k = 3;
  const KMeansResult r = kmeans(p, cfg);
  ASSERT_EQ(r.centres.size(), 1u);
  EXPECT_EQ(r.centres[0], Eigen::Vector2d(3, -2));
  EXPECT_EQ(r.labels, std::vector<int>(6, 0));
}

TEST(KMeans, NonPositiveKMeansOneCluster) {
  const std::vector<Eigen::Vector2d> p = {{0, 0}, {2, 0}};
  KMeansConfig cfg;
  cfg.k = 0;
  const KMeansResult r = kmeans(p, cfg);
  ASSERT_EQ(r.centres.size(), 1u);
  EXPECT_EQ(r.centres[0], Eigen::Vector2d(1, 0));
  EXPECT_EQ(r.labels, (std::vector<int>{0, 0}));
}

TEST(KMeans, SinglePoint) {
  const KMeansResult r = kmeans({{7, 8}}, KMeansConfig{});
  ASSERT_EQ(r.centres.size(), 1u);
  EXPECT_EQ(r.centres[0], Eigen::Vector2d(7, 8));
  EXPECT_EQ(r.labels, (std::vector<int>{0}));
}

TEST(KMeans, StopPredicateReturnsBestSoFar) {
  const auto pts = scattered(400, 11);
  KMeansConfig cfg;
  cfg.k = 5;
  // Stop at once: seeding only, but labels are still valid nearest-centre labels.
  const KMeansResult now = kmeans(pts, cfg, [] { return true; });
  EXPECT_EQ(now.iterations, 0);
  EXPECT_FALSE(now.converged);
  ASSERT_EQ(now.centres.size(), 5u);
  ASSERT_EQ(now.labels.size(), pts.size());
  for (int l : now.labels) EXPECT_TRUE(l >= 0 && l < 5);

  // Stop after two iterations: the result equals a run capped at two iterations.
  int calls = 0;
  const KMeansResult two = kmeans(pts, cfg, [&] { return ++calls > 2; });
  KMeansConfig capped = cfg;
  capped.max_iterations = 2;
  const KMeansResult ref = kmeans(pts, capped);
  EXPECT_EQ(two.iterations, 2);
  EXPECT_EQ(two.labels, ref.labels);

  // Within-cluster sum of squares never goes up: the full run is at least as good.
  auto wcss = [&](const KMeansResult& r) {
    double s = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      s += (pts[i] - r.centres[r.labels[i]]).squaredNorm();
    }
    return s;
  };
  const KMeansResult full = kmeans(pts, cfg);
  EXPECT_LE(wcss(full), wcss(two) + 1e-9);
  EXPECT_LE(wcss(two), wcss(now) + 1e-9);
}

TEST(KMeans, ZeroIterationsIsSeedingOnly) {
  const auto pts = scattered(50, 2);
  KMeansConfig cfg;
  cfg.max_iterations = 0;
  const KMeansResult r = kmeans(pts, cfg);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.centres.size(), 3u);
}

}  // namespace
}  // namespace swarm::planner
