// DBSCAN clustering of grid cells: turns frontier cells into frontier segments.
//
// The group-frontier explorer (docs/papers.md section 1, paper section 3.2) segments frontier cells with
// DBSCAN so that frontiers separated by obstacles become separate segments, each segment's size W
// being its cell count. Algorithm: Ester, Kriegel, Sander & Xu, "A density-based algorithm for
// discovering clusters in large spatial databases with noise", KDD 1996.
//
// Conventions (the paper is silent; these are the usual ones, e.g. scikit-learn's):
// - Neighbours of a point: every point (itself included) at Euclidean distance <= eps, in cells.
//   eps = 1.5 links the 8-neighbourhood; eps = 1.0 links only the 4-neighbourhood.
// - A core point has at least min_points neighbours (itself included); min_points <= 1 makes
//   every point a core point, so there is no noise and clusters are 8-/4-connected components.
// - Border points reachable from two clusters go to the one that reaches them first.
// - Labels are 0..k-1, numbered in the order of each cluster's first point in the input; -1 is
//   noise. Duplicate cells are separate points (at distance 0 of each other).
//
// Speed: points are bucketed in a hash grid of ceil(eps)-sized squares, so a query scans 3x3
// buckets: about O(N * density) instead of O(N^2); thousands of frontier cells take well under a
// millisecond. Deterministic: the result depends only on the input order, never on hashing.
// Thread-safe: no shared state.
//
//   std::vector<Cell> frontier = find_frontiers(map);
//   std::vector<int> label = swarm::planner::dbscan(frontier, 1.5, 1);
//   // label[i] is the segment of frontier[i]
#pragma once

#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

// eps in cells (>= 0); the distance test is dx^2 + dy^2 <= eps^2, evaluated in double.
[[nodiscard]] std::vector<int> dbscan(const std::vector<Cell>& points, double eps, int min_points);

// Groups points by label: result[c] holds the points of cluster c in input order; noise is
// dropped. `labels` must be dbscan's output for `points`.
[[nodiscard]] std::vector<std::vector<Cell>> clusters_of(const std::vector<Cell>& points,
                                                         const std::vector<int>& labels);

}  // namespace swarm::planner
