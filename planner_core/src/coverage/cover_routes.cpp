#include "swarm/planner/coverage/cover_routes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <queue>

#include "swarm/planner/coverage/coverage.hpp"
#include "swarm/planner/coverage/coverage_plan.hpp"
#include "swarm/planner/coverage/group_k.hpp"
#include "swarm/planner/grid/motion.hpp"
#include "swarm/planner/coverage/plow.hpp"

namespace swarm::planner {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Breadth-first search through Free cells (4-connected) not in `blocked` from `sources`: steps
// per grid index (-1 = not reached).
struct Bfs {
  std::vector<int> steps;
};

Bfs bfs(const OccupancyGrid& map, const std::vector<Cell>& sources, const std::vector<std::uint8_t>* blocked = nullptr) {
  Bfs b{std::vector<int>(map.size(), -1)};
  std::vector<int> queue;
  queue.reserve(map.size());
  for (const Cell& s : sources) {
    if (!map.in_bounds(s)) continue;
    const int i = map.index(s);
    if (b.steps[i] >= 0) continue;
    b.steps[i] = 0;
    queue.push_back(i);
  }
  const MotionModel four = MotionModel::four();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int ci = queue[head];
    four.for_each_neighbour(map, map.cell_of(ci), [&](Cell n, double) {
      const int ni = map.index(n);
      if (b.steps[ni] >= 0 || (blocked != nullptr && (*blocked)[ni])) return;
      b.steps[ni] = b.steps[ci] + 1;
      queue.push_back(ni);
    });
  }
  return b;
}

// The pieces of the set (4-connected through Free set cells), each a list of grid indices, in
// the order of their lowest cell.
std::vector<std::vector<int>> pieces_of(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells) {
  std::vector<std::uint8_t> seen(map.size(), 0);
  std::vector<std::vector<int>> pieces;
  const MotionModel four = MotionModel::four();
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (!cells[i] || seen[i] || map.at(static_cast<int>(i)) != CellState::Free) continue;
    std::vector<int> piece{static_cast<int>(i)};
    seen[i] = 1;
    for (std::size_t h = 0; h < piece.size(); ++h) {
      four.for_each_neighbour(map, map.cell_of(piece[h]), [&](Cell c, double) {
        const int j = map.index(c);
        if (!cells[j] || seen[j]) return;
        seen[j] = 1;
        piece.push_back(j);
      });
    }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// The set's cells that lie in a piece of at least `least` cells: a robot that starts in a sliver
// of the set (an orphan piece another division gave its group) would get nothing else.
std::vector<std::uint8_t> in_large_pieces(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                                          std::size_t least) {
  std::vector<std::uint8_t> out(map.size(), 0);
  for (const std::vector<int>& piece : pieces_of(map, cells)) {
    if (piece.size() < least) continue;
    for (int j : piece) out[static_cast<std::size_t>(j)] = 1;
  }
  return out;
}

CoverRoutes divide_once(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                        const std::vector<Cell>& robots, const std::vector<double>& weights,
                        const CoverRoutesConfig& config, const std::function<bool()>& stop) {
  const auto t0 = Clock::now();
  CoverRoutes out;
  const std::size_t n = robots.size();
  out.starts.assign(n, Cell{-1, -1});
  // Each robot's start: its nearest cell of the set that no robot has taken yet, robots in id
  // order (a robot on a set cell keeps it), in a piece of the set of at least half a share when
  // it can reach one.
  const std::size_t total = static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [](std::uint8_t v) { return v != 0; }));
  const std::vector<std::uint8_t> large = in_large_pieces(map, cells, std::max<std::size_t>(1, total / (2 * std::max<std::size_t>(1, n))));
  std::vector<std::uint8_t> taken(map.size(), 0);
  std::vector<std::size_t> placed;
  for (std::size_t r = 0; r < n; ++r) {
    const Bfs b = bfs(map, {robots[r]});
    int best = -1;
    for (const bool anywhere : {false, true}) {
      for (std::size_t i = 0; i < map.size(); ++i) {
        if (!cells[i] || taken[i] || b.steps[i] < 0 || (!anywhere && !large[i])) continue;
        if (best < 0 || b.steps[i] < b.steps[best]) best = static_cast<int>(i);
      }
      if (best >= 0) break;
    }
    if (best < 0) continue;  // it can reach nothing of the set
    taken[best] = 1;
    out.starts[r] = map.cell_of(best);
    placed.push_back(r);
  }
  out.routes.assign(n, {});
  out.region_cells.assign(n, 0);
  out.turns.assign(n, 0);
  for (std::size_t r = 0; r < n; ++r) out.routes[r] = {robots[r]};
  if (placed.empty()) {
    out.seconds_division = since(t0);
    return out;
  }
  DarpRequest req;
  for (std::size_t r : placed) {
    req.robots.push_back(out.starts[r]);
    if (!weights.empty()) req.weights.push_back(weights[r]);
  }
  req.region = cells;
  out.darp = divide_areas(map, req, config.darp, stop);
  if (config.assign_orphans && out.darp.status != DarpStatus::BadInput) {
    // One BFS from every robot at once: each orphan cell goes to the robot that reaches it first.
    std::vector<int> owner(map.size(), -1);
    std::vector<int> queue;
    for (std::size_t k = 0; k < placed.size(); ++k) {
      const int i = map.index(robots[placed[k]]);
      if (owner[i] >= 0) continue;
      owner[i] = static_cast<int>(k);
      queue.push_back(i);
    }
    const MotionModel four = MotionModel::four();
    for (std::size_t h = 0; h < queue.size(); ++h) {
      four.for_each_neighbour(map, map.cell_of(queue[h]), [&](Cell c, double) {
        const int j = map.index(c);
        if (owner[j] >= 0) return;
        owner[j] = owner[queue[h]];
        queue.push_back(j);
      });
    }
    for (std::size_t i = 0; i < map.size(); ++i) {
      if (out.darp.assignment[i] != kUnreachable || owner[i] < 0) continue;
      out.darp.assignment[i] = owner[i];
      ++out.darp.cells[static_cast<std::size_t>(owner[i])];
    }
  }
  out.seconds_division = since(t0);
  if (!config.routes || out.darp.status == DarpStatus::BadInput) return out;

  const auto t1 = Clock::now();
  std::vector<Cell> current;
  for (std::size_t r : placed) current.push_back(robots[r]);
  const std::vector<CoveragePlan> stc = config.order == CoverOrder::Stc
                                            ? plan_coverage(map, out.darp, current, config.stc)
                                            : std::vector<CoveragePlan>{};
  for (std::size_t k = 0; k < placed.size(); ++k) {
    const std::size_t r = placed[k];
    out.region_cells[r] = out.darp.cells[k];
    std::vector<Cell> route;
    if (config.order == CoverOrder::Stc) {
      route = stc[k].path();
    } else {
      std::vector<std::uint8_t> region(map.size(), 0);
      for (std::size_t i = 0; i < map.size(); ++i) region[i] = out.darp.assignment[i] == static_cast<int>(k);
      route = config.order == CoverOrder::Plow ? plow(map, region, robots[r]).cells
                                               : group_k(map, region, robots[r]).path.cells;
    }
    if (route.empty()) route = {robots[r]};
    out.turns[r] = count_turns(route).quarter_turns();
    out.routes[r] = std::move(route);
  }
  out.seconds_routes = since(t1);
  return out;
}

std::size_t longest_route(const CoverRoutes& r) {
  std::size_t most = 0;
  for (const std::vector<Cell>& route : r.routes) most = std::max(most, route.size());
  return most;
}

// Cells of the set the routes stand on, together.
std::size_t cells_covered(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells, const CoverRoutes& r) {
  std::vector<std::uint8_t> seen(map.size(), 0);
  std::size_t n = 0;
  for (const std::vector<Cell>& route : r.routes) {
    for (const Cell c : route) {
      const auto i = static_cast<std::size_t>(map.index(c));
      if (cells[i] && !seen[i]) seen[i] = 1, ++n;
    }
  }
  return n;
}

// Candidate k's configuration: the configured start first, K-Means once, then other random factors.
CoverRoutesConfig candidate_config(const CoverRoutesConfig& config, int k) {
  CoverRoutesConfig other = config;
  if (k == 0) return other;
  if (k == 1 && config.darp.init != DarpInit::KMeans) other.darp.init = DarpInit::KMeans;
  other.darp.seed = config.darp.seed + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(k);
  return other;
}

// Portions for the next balancing round: each robot with a region gets more when its route is
// shorter than the mean and less when longer. The square root damps the step: a region's moves per
// cell change with its shape, so a full step overshoots and the rounds swing (measured: over 16
// rounds the kept longest route was 3 % shorter with the square root on warehouse-10-20-10-2-1).
void rebalance(std::vector<double>& portions, const CoverRoutes& r) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < portions.size(); ++i) {
    if (r.region_cells[i] == 0) continue;
    sum += static_cast<double>(r.routes[i].size());
    ++n;
  }
  if (n == 0) return;
  const double mean = sum / n;
  for (std::size_t i = 0; i < portions.size(); ++i) {
    if (r.region_cells[i] == 0) continue;
    portions[i] *= std::sqrt(mean / static_cast<double>(std::max<std::size_t>(1, r.routes[i].size())));
  }
}

}  // namespace

CoverRoutes divide_and_route(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                             const std::vector<Cell>& robots, const std::vector<double>& weights,
                             const CoverRoutesConfig& config, const std::function<bool()>& stop) {
  CoverRoutes best = divide_once(map, cells, robots, weights, config, stop);
  if (!config.routes || best.darp.status == DarpStatus::BadInput) return best;
  std::size_t best_covered = cells_covered(map, cells, best);
  double division = best.seconds_division, routes = best.seconds_routes;
  // Only a division as good as the best (converged, or as balanced; covering as much) with a
  // shorter longest route replaces it.
  const auto consider = [&](const CoverRoutes& r, int index) {
    division += r.seconds_division;
    routes += r.seconds_routes;
    const std::size_t covered = cells_covered(map, cells, r);
    const bool as_good = (r.darp.status == DarpStatus::Converged || best.darp.status != DarpStatus::Converged) &&
                         covered >= best_covered;
    if (!as_good || longest_route(r) >= longest_route(best)) return;
    best = r;
    best.chosen = index;
    best_covered = covered;
  };
  int tried = 1;
  for (int k = 1; k < config.candidates && !(stop && stop()); ++k) {
    CoverRoutes r = divide_once(map, cells, robots, weights, candidate_config(config, k), stop);
    ++tried;
    consider(r, k);
  }
  const CoverRoutesConfig start = candidate_config(config, best.chosen);
  std::vector<double> portions = weights.empty() ? std::vector<double>(robots.size(), 1.0) : weights;
  CoverRoutes last = best;
  int rounds = 0;
  for (int k = 0; k < config.balance_rounds && !(stop && stop()); ++k) {
    rebalance(portions, last);
    last = divide_once(map, cells, robots, portions, start, stop);
    ++rounds;
    consider(last, tried + k);
  }
  best.candidates_tried = tried;
  best.balance_rounds = rounds;
  best.seconds_division = division;
  best.seconds_routes = routes;
  return best;
}

}  // namespace swarm::planner
