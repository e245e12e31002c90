// Group-frontier exploration planner: one planning round of one group leader.
//
//   ExploreInput in;
//   in.global_map = &global;  in.group_map = &mine;
//   in.leader_positions = {l0, l1, l2};  in.group = 1;
//   in.member_positions = {l1, m1, m2};  in.round = r;
//   ExplorePlan plan = plan_group_exploration(in, ExploreConfig{});
//   for (size_t i = 0; i < plan.waypoints.size(); ++i)
//     if (plan.waypoints[i]) send_goal(i, *plan.waypoints[i]);
//
// Paper: the hierarchical group-frontier exploration paper under constrained (delayed) global
// information, seeds/004_4c4ef858aa95613f.txt section 3 (Korean); English digest: docs/papers.md
// section 1. DBSCAN, K-Means and Hungarian: see dbscan.hpp, kmeans.hpp, hungarian.hpp.
//
// A GCS fuses the groups' maps once per round, so at round r every leader holds the global map
// of round r-1 (identical at every leader) plus its own group's observations since.
//
// What one call does:
//  1. Global frontiers: frontiers of the stale global map reachable from the leaders.
//     Local frontiers: frontiers of the group's map reachable from its members.
//     Group frontiers: local frontiers that are not global frontiers, i.e. what this group has
//     discovered since the last fusion (paper 3.1).
//  2. Case A, group frontiers exist (paper 3.3.1): DBSCAN them into segments (paper 3.2); take
//     the segment with the least D/W (W = cells, D = leader-to-segment distance); small segments
//     near the leader (room corners) each get one non-leader member now, so nobody has to come
//     back for them later.
//  3. Case B, no group frontiers, or the baseline (paper 3.3.2): DBSCAN the global frontiers;
//     Hungarian assignment of ALL leaders to segments with C_ij = D_ij / W_j; this group keeps
//     its own row. The assignment reads only the global map and the leader positions, which
//     every leader shares, so all leaders compute the same one and cooperate without messages.
//     If the group has explored its row's segment since the fusion, it re-chooses (see below).
//  4. Within the group: K-Means (k = members on the segment) on the segment's open cells; each
//     waypoint is the segment cell nearest a centre; Hungarian on Euclidean distance gives every
//     member one waypoint.
//
// Decisions where the paper is silent (the C_ij = D_ij / W_j formula is docs/papers.md's; the rest
// are this file's):
// - D is the Euclidean distance in cells from the leader to the segment's nearest cell, at least 1
//   (a segment touching the leader must not divide by zero or swamp W). Case A and case B use the
//   same D / W. Ties go to the lowest segment index; segments are numbered by their first cell in
//   row-major order (dbscan.hpp).
// - Small segments (case A): W <= small_segment_max_cells and D <= small_segment_radius_cells,
//   nearest first, at most members - 1 of them; the member for each comes from a Hungarian
//   assignment on the member-to-segment distance (nearest cell); its waypoint is the segment cell
//   nearest the segment's centroid (K-Means with k = 1).
// - Case B, more groups than segments: a group whose row the Hungarian leaves out takes the
//   cheapest segment of its row and shares it.
// - Case B uses the leader's own group map as well, for its own row only: the chosen segment's
//   waypoints come from its cells that are still reachable frontiers in the group map ("open";
//   the global map is a round old). If the shared assignment's segment has no open cell, the
//   group explored it itself since the fusion (a dead end, or it would be in case A); it then
//   takes the open segment of least D'/W' (W' = open cells, D' = distance to the nearest one)
//   among those the shared assignment gives no other group, else among all open segments;
//   none open = NoFrontier. Why it stays within the method: the leader holds its group map in
//   the paper too, and the other leaders' rows, which model what they will do, are untouched.
//   The baseline does this too: it differs from the full planner only in never using group
//   frontiers.
// - Fewer distinct cells than members: each waypoint is offered ceil(members / waypoints) times
//   to the Hungarian assignment, so members share waypoints as evenly as possible.
// - All group frontiers DBSCAN noise (only possible with dbscan_min_points > 1): case B.
// - Baseline with no global frontier: NoFrontier, even if the group's own map has frontiers
//   (the baseline plans on stale global information only).
// - NoFrontier: every waypoint is std::nullopt (waypoints stays parallel to member_positions).
//
// Deterministic (same input and config => identical plan on every machine) and fast: a few
// milliseconds on a 100 x 100 grid with thousands of frontier cells. Thread-safe: no shared state.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

struct ExploreConfig {
  bool use_group_frontiers = true;  // false = the paper's baseline: always case B
  double dbscan_eps_cells = 1.5;    // 1.5 links 8-neighbours: one segment per connected frontier
  int dbscan_min_points = 1;        // 1 = no noise: every frontier cell belongs to a segment
  int small_segment_max_cells = 6;  // case A: a segment this small (W <= ...) is "small"
  double small_segment_radius_cells = 15;  // ... and gets a member only if D <= this (15 = 3 m)
  int kmeans_max_iterations = 50;
  std::uint64_t seed = 1;  // K-Means seed = mix_seed(seed, round, group)
};

struct ExploreInput {
  const OccupancyGrid* global_map = nullptr;  // stale global map from the GCS: same at every leader
  const OccupancyGrid* group_map = nullptr;   // global map + this group's observations since;
                                              // same size as global_map
  std::vector<Cell> leader_positions;         // every group's leader, index = group id
  int group = 0;                              // this group, index into leader_positions
  std::vector<Cell> member_positions;         // this group's robots, [0] is the leader
  int round = 0;
};

enum class PlanCase {
  NoFrontier,        // nothing reachable left to explore: no waypoints
  GroupFrontier,     // case A: this group's own new frontiers
  GlobalAssignment,  // case B: Hungarian over the stale global frontiers
};

struct ExplorePlan {
  PlanCase plan_case = PlanCase::NoFrontier;
  // Parallel to member_positions; std::nullopt = no goal (only in NoFrontier).
  std::vector<std::optional<Cell>> waypoints;

  // For pictures and tests.
  std::vector<Cell> group_frontiers;                 // row-major; empty for the baseline
  std::vector<std::vector<Cell>> group_segments;     // case A: DBSCAN of group_frontiers
  std::vector<std::vector<Cell>> global_segments;    // case B: DBSCAN of the global frontiers
  // Case A: index into group_segments; case B: into global_segments. In case B it differs from
  // group_to_segment[group] when this group had already explored that segment (explore.hpp top).
  int chosen_segment = -1;
  // Parallel to member_positions: the segment each member was sent to (same indexing as
  // chosen_segment), -1 in NoFrontier. In case A, members != chosen_segment went to small segments.
  std::vector<int> member_segment;
  // Case B only: the leaders-to-segments assignment every leader computes (index = group id,
  // -1 = left out because there are more groups than segments).
  std::vector<int> group_to_segment;
};

[[nodiscard]] ExplorePlan plan_group_exploration(const ExploreInput& input,
                                                 const ExploreConfig& config);

}  // namespace swarm::planner
