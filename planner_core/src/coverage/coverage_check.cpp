#include "swarm/planner/coverage/coverage_check.hpp"

#include <cmath>
#include <deque>
#include <set>

#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {
namespace {

std::string at(Cell c) { return to_string(c); }

// Cells reachable from `from` by 4-connected steps through cells where inside(cell) holds.
template <class Inside>
std::vector<char> flood(const OccupancyGrid& map, const std::vector<Cell>& from, Inside inside) {
  std::vector<char> seen(map.size(), 0);
  std::deque<Cell> todo;
  for (const Cell& c : from) {
    if (!map.in_bounds(c) || !inside(c) || seen[map.index(c)]) continue;
    seen[map.index(c)] = 1;
    todo.push_back(c);
  }
  while (!todo.empty()) {
    const Cell c = todo.front();
    todo.pop_front();
    for (const Cell n : {Cell{c.x + 1, c.y}, Cell{c.x - 1, c.y}, Cell{c.x, c.y + 1}, Cell{c.x, c.y - 1}}) {
      if (!map.in_bounds(n) || seen[map.index(n)] || !inside(n)) continue;
      seen[map.index(n)] = 1;
      todo.push_back(n);
    }
  }
  return seen;
}

}  // namespace

std::vector<std::string> check_division(const OccupancyGrid& map, const DarpRequest& request,
                                        const DarpResult& result, bool given_starts, double tolerance_cells) {
  std::vector<std::string> problems;
  const int n = static_cast<int>(request.robots.size());
  if (result.status == DarpStatus::BadInput) return {"status is bad-input: " + result.message};
  if (result.assignment.size() != map.size()) return {"assignment does not cover the map"};
  if (static_cast<int>(result.cells.size()) != n || static_cast<int>(result.starts.size()) != n ||
      static_cast<int>(result.shares.size()) != n) {
    return {"cells, starts or shares do not have one entry per robot"};
  }
  auto in_region = [&](Cell c) {
    return map.is_free(c) && (request.region.empty() || request.region[map.index(c)] != 0);
  };
  const std::vector<char> reachable = flood(map, request.robots, in_region);
  std::vector<int> cells(n, 0);
  int unreachable = 0, divided = 0;
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    const Cell c = map.cell_of(i);
    const int a = result.assignment[i];
    if (!in_region(c)) {
      if (a != kOutsideRegion) problems.push_back("cell " + at(c) + " is outside the region but marked " + std::to_string(a));
    } else if (!reachable[i]) {
      ++unreachable;
      if (a != kUnreachable) problems.push_back("cell " + at(c) + " is unreachable but marked " + std::to_string(a));
    } else if (a < 0 || a >= n) {
      problems.push_back("reachable cell " + at(c) + " has no robot (" + std::to_string(a) + ")");
    } else {
      ++cells[a];
      ++divided;
    }
  }
  if (unreachable != result.unreachable_cells) {
    problems.push_back("unreachable_cells is " + std::to_string(result.unreachable_cells) + ", counted " +
                       std::to_string(unreachable));
  }
  double share_sum = 0;
  int split = 0;
  for (int r = 0; r < n; ++r) {
    const std::string who = "robot " + std::to_string(r);
    if (cells[r] != result.cells[r]) {
      problems.push_back(who + ": cells says " + std::to_string(result.cells[r]) + ", counted " + std::to_string(cells[r]));
    }
    const Cell s = result.starts[r];
    if (!map.in_bounds(s) || result.assignment[map.index(s)] != r) problems.push_back(who + ": start " + at(s) + " is not its own");
    if (given_starts && s != request.robots[r]) problems.push_back(who + ": start " + at(s) + " is not the robot's cell");
    const std::vector<char> piece =
        flood(map, {s}, [&](Cell c) { return result.assignment[map.index(c)] == r; });
    int in_piece = 0;
    for (char v : piece) in_piece += v;
    if (in_piece != cells[r]) ++split;
    if (result.status == DarpStatus::Converged || result.status == DarpStatus::Impossible) {
      if (in_piece != cells[r]) problems.push_back(who + ": region is not 4-connected");
    }
    if (result.status == DarpStatus::Converged) {
      if (std::abs(cells[r] - result.shares[r]) > tolerance_cells + 1e-9) {
        problems.push_back(who + ": " + std::to_string(cells[r]) + " cells, share " + std::to_string(result.shares[r]));
      }
    }
    share_sum += result.shares[r];
  }
  if (split != result.split_regions) {
    problems.push_back("split_regions is " + std::to_string(result.split_regions) + ", counted " + std::to_string(split));
  }
  if (std::abs(share_sum - divided) > 1e-6 * (1 + divided)) {
    problems.push_back("shares add up to " + std::to_string(share_sum) + ", cells divided " + std::to_string(divided));
  }
  return problems;
}

std::vector<std::string> check_coverage_path(const OccupancyGrid& region, Cell start, const std::vector<Cell>& path) {
  std::vector<std::string> problems;
  if (path.empty()) return {"empty path"};
  if (path.front() != start) problems.push_back("path starts at " + at(path.front()) + ", not " + at(start));
  const MotionModel four = MotionModel::four();
  std::vector<char> visited(region.size(), 0);
  if (region.is_free(path.front())) visited[region.index(path.front())] = 1;
  else problems.push_back("start " + at(path.front()) + " is not in the region");
  for (std::size_t k = 1; k < path.size(); ++k) {
    const MoveCheck m = four.check(region, path[k - 1], path[k]);
    if (m != MoveCheck::Ok) {
      problems.push_back("step " + std::to_string(k) + " " + at(path[k - 1]) + " -> " + at(path[k]) + ": " + to_string(m));
      if (problems.size() > 10) return problems;
      continue;
    }
    visited[region.index(path[k])] = 1;
  }
  const std::vector<char> piece = flood(region, {start}, [&](Cell c) { return region.is_free(c); });
  int missed = 0;
  Cell first{};
  for (int i = 0; i < static_cast<int>(region.size()); ++i) {
    if (piece[i] && !visited[i]) {
      if (missed++ == 0) first = region.cell_of(i);
    }
  }
  if (missed > 0) problems.push_back(std::to_string(missed) + " cells never visited, e.g. " + at(first));
  return problems;
}

std::vector<std::string> check_cover_routes(const OccupancyGrid& map, const std::vector<std::uint8_t>& cells,
                                            const std::vector<Cell>& robots,
                                            const std::vector<std::vector<Cell>>& routes) {
  if (routes.size() != robots.size()) {
    return {std::to_string(routes.size()) + " routes for " + std::to_string(robots.size()) + " robots"};
  }
  std::vector<std::string> problems;
  const MotionModel four = MotionModel::four();
  std::vector<char> visited(map.size(), 0);
  for (std::size_t r = 0; r < routes.size(); ++r) {
    const std::string who = "robot " + std::to_string(r);
    const std::vector<Cell>& route = routes[r];
    if (route.empty() || route.front() != robots[r]) {
      problems.push_back(who + ": the route does not start at its cell " + at(robots[r]));
      continue;
    }
    if (map.is_free(route.front())) visited[map.index(route.front())] = 1;
    for (std::size_t k = 1; k < route.size(); ++k) {
      const MoveCheck m = four.check(map, route[k - 1], route[k]);
      if (m != MoveCheck::Ok) {
        problems.push_back(who + ": step " + std::to_string(k) + " " + at(route[k - 1]) + " -> " + at(route[k]) + ": " +
                           to_string(m));
        break;
      }
      visited[map.index(route[k])] = 1;
    }
  }
  const std::vector<char> reachable = flood(map, robots, [&](Cell c) { return map.is_free(c); });
  int missed = 0;
  Cell first{};
  for (int i = 0; i < static_cast<int>(map.size()) && i < static_cast<int>(cells.size()); ++i) {
    if (cells[static_cast<std::size_t>(i)] && reachable[i] && !visited[i] && missed++ == 0) first = map.cell_of(i);
  }
  if (missed > 0) problems.push_back(std::to_string(missed) + " cells of the set never visited, e.g. " + at(first));
  return problems;
}

}  // namespace swarm::planner
