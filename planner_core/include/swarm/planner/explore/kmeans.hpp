// K-Means clustering of 2D points, reproducible per seed and interruptible.
//
// The group-frontier explorer (docs/papers.md section 1) splits a frontier segment into one cluster per
// robot and sends each robot to the frontier cell nearest a cluster centre; DARP's initialisation
// (docs/papers.md section 2) clusters free cells the same way.
//
// Algorithm: k-means++ seeding (Arthur & Vassilvitskii, SODA 2007) then Lloyd iterations
// (Lloyd 1982): assign every point to its nearest centre, move every centre to the mean of its
// points, until no label changes or max_iterations.
//
// Details the references leave open:
// - k is clipped to [1, number of distinct points] (k-means++ seeding only): asking for more clusters than distinct points
//   would only create duplicate centres. Empty input gives empty centres and labels.
// - Distance ties go to the lowest centre index. A centre that loses all its points keeps its
//   position (it cannot happen after k-means++ seeding on distinct points, only later, rarely).
// - should_stop() is polled before every Lloyd iteration; when it returns true the current centres
//   and labels are returned (Lloyd never increases the within-cluster sum of squares, so the
//   latest iterate is the best so far) with converged = false.
// - Randomness comes only from swarm::planner::Rng (rng.hpp), so the same points, config and seed
//   give bit-identical results everywhere.
//
// Units: whatever the points are in (cells or metres). Thread-safe: no shared state.
//
//   std::vector<Eigen::Vector2d> pts = ...;
//   swarm::planner::KMeansConfig cfg;
//   cfg.k = 3;
//   cfg.seed = 42;
//   auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(5);
//   swarm::planner::KMeansResult r = swarm::planner::kmeans(
//       pts, cfg, [&] { return std::chrono::steady_clock::now() > deadline; });
//   // r.centres.size() == min(3, distinct points); r.labels[i] indexes r.centres
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace swarm::planner {

struct KMeansConfig {
  int k = 3;                // wanted clusters; clipped to [1, distinct points]
  int max_iterations = 50;  // Lloyd iterations at most (0 = k-means++ seeding only)
  std::uint64_t seed = 1;   // k-means++ draws; see mix_seed() in rng.hpp to derive per-call seeds
  // Non-empty: Lloyd starts from these centres instead of k-means++ (k = their count, not
  // clipped; centre i stays centre i, so a caller can tell which start each cluster grew from).
  std::vector<Eigen::Vector2d> initial_centres;
};

struct KMeansResult {
  std::vector<Eigen::Vector2d> centres;  // size = effective k
  std::vector<int> labels;               // parallel to the input: index into centres
  int iterations = 0;                    // Lloyd iterations performed
  bool converged = false;                // true when an iteration changed no label
};

[[nodiscard]] KMeansResult kmeans(const std::vector<Eigen::Vector2d>& points,
                                  const KMeansConfig& config,
                                  const std::function<bool()>& should_stop = {});

}  // namespace swarm::planner
