#include "swarm/planner/explore/explore.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Core>

#include "swarm/planner/explore/dbscan.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/explore/hungarian.hpp"
#include "swarm/planner/explore/kmeans.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {
namespace {

using Segments = std::vector<std::vector<Cell>>;

// Integer squared distance: exact, so distance comparisons never depend on rounding.
std::int64_t sq_dist(Cell a, Cell b) {
  const std::int64_t dx = static_cast<std::int64_t>(a.x) - b.x;
  const std::int64_t dy = static_cast<std::int64_t>(a.y) - b.y;
  return dx * dx + dy * dy;
}

// Euclidean distance in cells from `from` to the nearest of `cells` (non-empty).
double nearest_distance(Cell from, const std::vector<Cell>& cells) {
  std::int64_t best = std::numeric_limits<std::int64_t>::max();
  for (const Cell& c : cells) best = std::min(best, sq_dist(from, c));
  return std::sqrt(static_cast<double>(best));
}

// The paper's D: at least 1 so a segment touching the leader gets a finite, comparable cost.
double segment_distance(Cell leader, const std::vector<Cell>& segment) {
  return std::max(1.0, nearest_distance(leader, segment));
}

// C = D / W: distance paid per frontier cell gained (the inverse of information per cost).
double segment_cost(Cell leader, const std::vector<Cell>& segment) {
  return segment_distance(leader, segment) / static_cast<double>(segment.size());
}

Segments segment_frontiers(const std::vector<Cell>& frontiers, const ExploreConfig& config) {
  const std::vector<int> labels = dbscan(frontiers, config.dbscan_eps_cells, config.dbscan_min_points);
  Segments segs = clusters_of(frontiers, labels);
  // DBSCAN calls a sparse frontier cell noise, but it is still unexplored space the GCS waits
  // for: dropped, it was never visited and missions with dbscan_min_points > 1 never completed.
  // So each noise cell is a segment of its own (W = 1: the costliest per cell, visited last).
  for (std::size_t i = 0; i < frontiers.size(); ++i) {
    if (labels[i] < 0) segs.push_back({frontiers[i]});
  }
  return segs;
}

// Up to k waypoints on `cells` (non-empty): K-Means centres snapped to the nearest cell (ties:
// the first such cell). Fewer than k when the cells have fewer distinct positions.
std::vector<Cell> segment_waypoints(const std::vector<Cell>& cells, int k, std::uint64_t seed,
                                    const ExploreConfig& config) {
  std::vector<Eigen::Vector2d> pts;
  pts.reserve(cells.size());
  for (const Cell& c : cells) pts.emplace_back(c.x, c.y);
  KMeansConfig kc;
  kc.k = k;
  kc.max_iterations = config.kmeans_max_iterations;
  kc.seed = seed;
  const KMeansResult km = kmeans(pts, kc);
  std::vector<Cell> out;
  out.reserve(km.centres.size());
  for (const Eigen::Vector2d& centre : km.centres) {
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double d = (pts[i] - centre).squaredNorm();
      if (d < best_d) {
        best_d = d;
        best = i;
      }
    }
    out.push_back(cells[best]);
  }
  return out;
}

// Gives every robot one of `waypoints` (non-empty), minimising the summed Euclidean distance.
// With fewer waypoints than robots each waypoint is offered ceil(robots / waypoints) times, so
// robots share waypoints as evenly as possible.
std::vector<Cell> assign_waypoints(const std::vector<Cell>& robots,
                                   const std::vector<Cell>& waypoints) {
  const int r = static_cast<int>(robots.size());
  const int w = static_cast<int>(waypoints.size());
  const int copies = (r + w - 1) / w;
  Eigen::MatrixXd cost(r, w * copies);
  for (int i = 0; i < r; ++i) {
    for (int j = 0; j < w * copies; ++j) {
      cost(i, j) = euclidean_distance(robots[i], waypoints[j % w]);
    }
  }
  const Assignment a = hungarian(cost);
  std::vector<Cell> out(r);
  for (int i = 0; i < r; ++i) {
    assert(a.row_to_col[i] >= 0);  // columns >= rows, so every row is assigned
    out[i] = waypoints[a.row_to_col[i] % w];
  }
  return out;
}

// Sends the members listed in `who` (indices into member_positions) to `segment_cells`.
void plan_segment(const ExploreInput& in, const std::vector<int>& who,
                  const std::vector<Cell>& segment_cells, int segment_index, std::uint64_t seed,
                  const ExploreConfig& config, ExplorePlan& plan) {
  if (who.empty()) return;
  std::vector<Cell> robots;
  robots.reserve(who.size());
  for (int m : who) robots.push_back(in.member_positions[m]);
  const std::vector<Cell> wps =
      segment_waypoints(segment_cells, static_cast<int>(who.size()), seed, config);
  const std::vector<Cell> goal = assign_waypoints(robots, wps);
  for (std::size_t i = 0; i < who.size(); ++i) {
    plan.waypoints[who[i]] = goal[i];
    plan.member_segment[who[i]] = segment_index;
  }
}

// Case A (paper 3.3.1): the group's own new frontiers.
void plan_case_a(const ExploreInput& in, const ExploreConfig& config, std::uint64_t seed,
                 ExplorePlan& plan) {
  plan.plan_case = PlanCase::GroupFrontier;
  const Segments& segs = plan.group_segments;
  const Cell leader = in.member_positions[0];
  const int s = static_cast<int>(segs.size());

  std::vector<double> dist(s);
  int chosen = 0;
  double chosen_cost = std::numeric_limits<double>::infinity();
  for (int j = 0; j < s; ++j) {
    dist[j] = segment_distance(leader, segs[j]);
    const double c = dist[j] / static_cast<double>(segs[j].size());
    if (c < chosen_cost) {  // strict: ties keep the lowest index
      chosen_cost = c;
      chosen = j;
    }
  }
  plan.chosen_segment = chosen;

  // Small-segment rule: small segments near the leader (typically room corners) get one
  // non-leader member each now, nearest first, so the swarm need not come back for them.
  const int members = static_cast<int>(in.member_positions.size());
  std::vector<int> small;
  for (int j = 0; j < s; ++j) {
    if (j != chosen && static_cast<int>(segs[j].size()) <= config.small_segment_max_cells &&
        dist[j] <= config.small_segment_radius_cells) {
      small.push_back(j);
    }
  }
  std::stable_sort(small.begin(), small.end(), [&](int a, int b) { return dist[a] < dist[b]; });
  if (static_cast<int>(small.size()) > members - 1) small.resize(std::max(0, members - 1));

  std::vector<int> main_group = {0};  // the leader always stays with the main segment
  if (!small.empty()) {
    // Rows: members 1..n-1; columns: small segments. Rows >= columns, so every small segment
    // gets exactly one member; cost = distance from the member to the segment's nearest cell.
    Eigen::MatrixXd cost(members - 1, static_cast<int>(small.size()));
    for (int i = 1; i < members; ++i) {
      for (int c = 0; c < static_cast<int>(small.size()); ++c) {
        cost(i - 1, c) = nearest_distance(in.member_positions[i], segs[small[c]]);
      }
    }
    const Assignment a = hungarian(cost);
    for (int i = 1; i < members; ++i) {
      const int c = a.row_to_col[i - 1];
      if (c < 0) {
        main_group.push_back(i);
      } else {
        plan_segment(in, {i}, segs[small[c]], small[c], seed, config, plan);
      }
    }
  } else {
    for (int i = 1; i < members; ++i) main_group.push_back(i);
  }
  plan_segment(in, main_group, segs[chosen], chosen, seed, config, plan);
}

// Case B, when the shared assignment's segment has no open cell left for this group: among the
// segments with open cells (open[j] = segment j's cells still frontiers in the group map), the
// least D'/W' from `leader` (W' = open cells, D' = distance to the nearest of them), preferring
// segments the shared assignment gives no other group: every other leader goes where the shared
// assignment sends it, so this keeps the paper's implicit cooperation. -1 if no segment is open.
int reselect_open_segment(Cell leader, const Segments& open,
                          const std::vector<int>& group_to_segment, int group) {
  std::vector<std::uint8_t> taken(open.size(), 0);
  for (std::size_t g = 0; g < group_to_segment.size(); ++g) {
    const int j = group_to_segment[g];
    if (static_cast<int>(g) != group && j >= 0) taken[j] = 1;
  }
  for (const bool allow_taken : {false, true}) {
    int best = -1;
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < open.size(); ++j) {
      if (open[j].empty() || (taken[j] && !allow_taken)) continue;
      const double c = segment_cost(leader, open[j]);
      if (c < best_cost) {  // strict: ties keep the lowest index
        best_cost = c;
        best = static_cast<int>(j);
      }
    }
    if (best >= 0) return best;
  }
  return -1;
}

// Case B (paper 3.3.2): every leader solves the same leaders-to-segments assignment from the
// shared stale global map and leader positions, and keeps its own row.
void plan_case_b(const ExploreInput& in, const ExploreConfig& config, std::uint64_t seed,
                 const std::vector<Cell>& global_frontiers,
                 const std::vector<std::uint8_t>& local_frontier_mask, ExplorePlan& plan) {
  plan.global_segments = segment_frontiers(global_frontiers, config);
  const Segments& segs = plan.global_segments;
  if (segs.empty()) return;  // no global frontier at all: NoFrontier
  plan.plan_case = PlanCase::GlobalAssignment;

  const int g = static_cast<int>(in.leader_positions.size());
  const int s = static_cast<int>(segs.size());
  Eigen::MatrixXd cost(g, s);
  for (int i = 0; i < g; ++i) {
    for (int j = 0; j < s; ++j) cost(i, j) = segment_cost(in.leader_positions[i], segs[j]);
  }
  const Assignment a = hungarian(cost);
  plan.group_to_segment = a.row_to_col;

  const bool own_row = in.group >= 0 && in.group < g;
  assert(own_row && "ExploreInput::group must index leader_positions");
  int chosen = own_row ? a.row_to_col[in.group] : -1;
  if (chosen < 0) {
    // More groups than segments and this group lost: take its cheapest segment anyway (shared).
    const Cell leader = own_row ? in.leader_positions[in.group] : in.member_positions[0];
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < s; ++j) {
      const double c = segment_cost(leader, segs[j]);
      if (c < best) {
        best = c;
        chosen = j;
      }
    }
  }

  // The global map is a round old, but this leader also holds its group map (the same global map
  // plus everything its group saw since). Only the segment cells that are still (reachable)
  // frontiers there are worth visiting: the others the group has explored itself since the fusion.
  std::vector<std::vector<Cell>> open(s);
  for (int j = 0; j < s; ++j) {
    for (const Cell& c : segs[j]) {
      if (in.group_map->in_bounds(c) && local_frontier_mask[in.group_map->index(c)]) {
        open[j].push_back(c);
      }
    }
  }
  if (open[chosen].empty()) {
    // The shared assignment sent this group to a segment it has explored since the fusion (a
    // dead end: had it found anything new, it would be in case A). The other leaders cannot know
    // that, so their rows of the assignment stand; this leader re-chooses for its own row only.
    // Issue 3's diagnosis before this rule: 36-44 % of case-B targets were such segments, and
    // their robots idled until the replan cap.
    chosen = reselect_open_segment(in.member_positions[0], open, plan.group_to_segment, in.group);
    if (chosen < 0) {
      // Nothing this group can reach is unexplored: no waypoints until the next global map.
      plan.plan_case = PlanCase::NoFrontier;
      return;
    }
  }
  plan.chosen_segment = chosen;
  const std::vector<Cell>& cells = open[chosen];

  std::vector<int> everyone(in.member_positions.size());
  for (std::size_t i = 0; i < everyone.size(); ++i) everyone[i] = static_cast<int>(i);
  plan_segment(in, everyone, cells, chosen, seed, config, plan);
}

}  // namespace

ExplorePlan plan_group_exploration(const ExploreInput& in, const ExploreConfig& config) {
  ExplorePlan plan;
  plan.waypoints.assign(in.member_positions.size(), std::nullopt);
  plan.member_segment.assign(in.member_positions.size(), -1);
  assert(in.global_map && in.group_map && "ExploreInput needs both maps");
  assert(!in.member_positions.empty() && "ExploreInput::member_positions[0] is the leader");
  if (!in.global_map || !in.group_map || in.member_positions.empty()) return plan;
  const OccupancyGrid& global = *in.global_map;
  const OccupancyGrid& local = *in.group_map;

  // Global frontiers: from the leaders that stand on known free space of the global map.
  std::vector<Cell> seeds;
  for (const Cell& c : in.leader_positions) {
    if (global.is_free(c)) seeds.push_back(c);
  }
  const std::vector<Cell> global_frontiers = reachable_frontiers(global, seeds);
  std::vector<std::uint8_t> is_global(global.size(), 0);
  for (const Cell& c : global_frontiers) is_global[global.index(c)] = 1;

  // Local frontiers: the group's up-to-date map, from its own robots.
  const std::vector<Cell> local_frontiers = reachable_frontiers(local, in.member_positions);
  std::vector<std::uint8_t> is_local(local.size(), 0);
  for (const Cell& c : local_frontiers) is_local[local.index(c)] = 1;

  const std::uint64_t seed = mix_seed(config.seed, in.round, in.group);

  if (config.use_group_frontiers) {
    for (const Cell& c : local_frontiers) {
      if (!(global.in_bounds(c) && is_global[global.index(c)])) plan.group_frontiers.push_back(c);
    }
    if (!plan.group_frontiers.empty()) {
      plan.group_segments = segment_frontiers(plan.group_frontiers, config);
      if (!plan.group_segments.empty()) {
        plan_case_a(in, config, seed, plan);
        return plan;
      }
    }
  }
  if (global_frontiers.empty()) return plan;  // NoFrontier
  plan_case_b(in, config, seed, global_frontiers, is_local, plan);
  return plan;
}

}  // namespace swarm::planner
