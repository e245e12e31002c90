// Group-k: clean the simple areas first, the cluttered corners last.
//
// Jeon, Jo & Noh, "Practical Intelligent Cleaning Robot Algorithm Based on Grouping in Complex
// Layout Space", 2006 (seeds/003_70d40d5a77c60547.txt; digest docs/papers.md section 5).
//
// Obstacles: the 8-connected components of blocked (not Free) cells that do not touch the map's
// border (what touches the border is the room's wall, the paper's dark grey). The gap between two
// obstacles is the smallest Euclidean distance between their cells' centres.
//   Basic_Group    every obstacle links to its nearest other obstacle (ties: the lower number);
//                  linked obstacles form groups (connected components).
//   C(g)           over the group's area, the bounding box of its obstacles' cells (the digest's
//                  decision), cut out of the map like an image:
//                    C = ((1 - H_mean / 255) + A_obstacle / A_sum) / 2
//                  with blocked cells black (0) and Free cells white (255), so the first term is
//                  the blocked fraction of the box; A_obstacle counts the corners of the blocked
//                  cells' outlines inside the box (lattice points where 1 or 3 of the 4 cells
//                  around are blocked, or 2 diagonal ones; cells outside the box count as free)
//                  and A_sum the lattice points of the box, (w + 1)(h + 1): 1 = every point a
//                  corner (a checkerboard), 0 = no obstacle.
//   Release_Group  while C(g) < k, drop the group's longest link (ties: at random, planner::Rng);
//                  each part that still has a link is a group again and is checked the same way;
//                  a part with no link (one obstacle) is no group any more.
//   Merge_Group    one pass over the groups in order: join each with its nearest group (smallest
//                  gap between their obstacles; ties: the lower number) when the joined group has
//                  C >= k.
//   Order          the area outside every group first, then the groups by increasing C (ties:
//                  the one nearest the previous group's box), moving between them by shortest
//                  path; plowing (plow.hpp) inside each. A Free cell in several groups' boxes is
//                  cleaned with the first of them.
// Parameters: k = 0.5 (the paper). Groups are numbered in their lowest obstacle's order.
//
//   const Grouping g = group_obstacles(map);                     // Basic, Release, Merge
//   for (const ObstacleGroup& grp : g.groups) print(grp.complexity);
//   GroupKCoverage c = group_k(map, free_cells(map), start);      // the whole room
//   GroupKCoverage mine = group_k(map, g, my_region, my_cell);    // one robot's region
//
// Deterministic per seed. Cost: O(B^2) for B obstacle border cells, one BFS per plowing dead end.
// Thread-safe.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/planner/coverage/coverage.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/coverage/plow.hpp"

namespace swarm::planner {

struct Obstacle {
  std::vector<Cell> cells;
  Cell lo, hi;  // bounding box, inclusive
};

// The obstacles of `map`, numbered in row-major order of their first cell.
[[nodiscard]] std::vector<Obstacle> find_obstacles(const OccupancyGrid& map);

struct ObstacleLink {
  int a = 0;
  int b = 0;                  // a < b
  std::int64_t gap_sq = 0;    // squared gap, in cells^2 (exact: ties are real ties)
  friend bool operator==(const ObstacleLink&, const ObstacleLink&) = default;
};

struct ComplexityParts {
  double blocked_fraction = 0;  // 1 - H_mean / 255
  int vertices = 0;             // A_obstacle
  int possible_vertices = 0;    // A_sum
  double complexity = 0;        // C(g)
};

// C(g) of the box [lo, hi] (inclusive) of `map`.
[[nodiscard]] ComplexityParts box_complexity(const OccupancyGrid& map, Cell lo, Cell hi);

struct ObstacleGroup {
  std::vector<int> obstacles;  // ascending
  std::vector<ObstacleLink> links;
  Cell lo, hi;                 // the obstacles' bounding box
  ComplexityParts parts;
  [[nodiscard]] double complexity() const { return parts.complexity; }
};

struct GroupKConfig {
  double k = 0.5;
  std::uint64_t seed = 1;  // Release_Group's random tie-break
  PlowOptions plow;
  // Not in the paper: the cells a group postpones are its box widened by this many cells on every
  // side (the floor next to the obstacles). 0 = the box itself, as the digest decided.
  int area_margin = 0;
};

struct Grouping {
  std::vector<Obstacle> obstacles;
  std::vector<ObstacleGroup> basic;     // after Basic_Group
  std::vector<ObstacleGroup> released;  // after Release_Group
  std::vector<ObstacleGroup> groups;    // after Merge_Group: the final groups
  std::vector<int> order;               // indices into `groups`, in cleaning order
  int area_margin = 0;                  // GroupKConfig::area_margin it was made with
};

[[nodiscard]] Grouping group_obstacles(const OccupancyGrid& map, const GroupKConfig& config = {});

struct GroupKCoverage {
  CoveragePath path;
  Grouping grouping;
  // Where each part starts in path.cells: the outside area first (group -1), then the groups in
  // cleaning order (index into grouping.groups). A part with nothing left to clean still has an
  // entry (it starts and ends at the same index).
  struct Part {
    int group = -1;
    std::size_t first_cell = 0;
  };
  std::vector<Part> parts;
};

// Group-k coverage of `region` (a subset of the Free cells) from `start`.
[[nodiscard]] GroupKCoverage group_k(const OccupancyGrid& map, const CellMask& region, Cell start,
                                     const GroupKConfig& config = {});
// The same with a grouping made before (e.g. once per map for several robots' regions).
[[nodiscard]] GroupKCoverage group_k(const OccupancyGrid& map, const Grouping& grouping,
                                     const CellMask& region, Cell start,
                                     const PlowOptions& plow = {});

// The cells each part of Group-k cleans, for `region`: [0] the outside area, then one mask per
// group in cleaning order (its box, widened by grouping.area_margin).
[[nodiscard]] std::vector<CellMask> group_k_parts(const OccupancyGrid& map, const Grouping& grouping,
                                                  const CellMask& region);

}  // namespace swarm::planner
