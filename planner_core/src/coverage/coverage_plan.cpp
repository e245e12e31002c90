#include "swarm/planner/coverage/coverage_plan.hpp"

#include <algorithm>
#include <memory>

#include "swarm/planner/coverage/region_graph.hpp"

namespace swarm::planner {

std::vector<Cell> CoveragePlan::path() const {
  if (!reachable) return {};
  std::vector<Cell> out = approach;
  if (!out.empty()) out.pop_back();  // coverage starts on that cell
  out.insert(out.end(), coverage.cells.begin(), coverage.cells.end());
  return out;
}

OccupancyGrid region_of(const OccupancyGrid& map, const std::vector<int>& assignment, int robot) {
  OccupancyGrid out(map.width(), map.height(), map.resolution(), map.origin_x(), map.origin_y(),
                    CellState::Occupied);
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (assignment[i] == robot) out.set(i, CellState::Free);
  }
  return out;
}

namespace {

// The 4-connected piece of `region`'s Free cells that holds `at`, as a region of its own.
OccupancyGrid piece_of(const OccupancyGrid& region, Cell at) {
  OccupancyGrid out(region.width(), region.height(), region.resolution(), region.origin_x(), region.origin_y(),
                    CellState::Occupied);
  const RegionGraph g = RegionGraph::build(region);
  std::vector<int> order;
  static_cast<void>(bfs_steps(g, {g.index_of(at)}, &order));
  for (int c : order) out.set(g.cells[c], CellState::Free);
  return out;
}

}  // namespace

std::vector<CoveragePlan> plan_coverage(const OccupancyGrid& map, const DarpResult& division,
                                        const std::vector<Cell>& robots, const StcConfig& config) {
  std::vector<CoveragePlan> out(robots.size());
  std::unique_ptr<RegionGraph> free_cells;  // built only if some robot stands outside its region
  for (std::size_t r = 0; r < robots.size(); ++r) {
    OccupancyGrid region = region_of(map, division.assignment, static_cast<int>(r));
    Cell from = robots[r];
    if (!region.is_free(from)) {
      // Drive to the piece of the region its start is in: other pieces (cells given on after the
      // division) may be nearer, but are only a part of it.
      if (r < division.starts.size() && region.is_free(division.starts[r])) region = piece_of(region, division.starts[r]);
      if (!free_cells) free_cells = std::make_unique<RegionGraph>(RegionGraph::build(map));
      const RegionGraph& g = *free_cells;
      // BFS from the robot to the first cell of its region; parents give the way back.
      std::vector<int> order;
      const int s = g.index_of(from);
      std::vector<int> parent(g.size(), -1);
      int goal = -1;
      if (s >= 0) {
        parent[s] = s;
        order.push_back(s);
        for (std::size_t head = 0; head < order.size() && goal < 0; ++head) {
          for (int nb : g.next[order[head]]) {
            if (nb < 0 || parent[nb] >= 0) continue;
            parent[nb] = order[head];
            if (region.is_free(g.cells[nb])) {
              goal = nb;
              break;
            }
            order.push_back(nb);
          }
        }
      }
      if (goal < 0) {
        out[r].reachable = false;
        continue;
      }
      for (int c = goal;; c = parent[c]) {
        out[r].approach.push_back(g.cells[c]);
        if (c == s) break;
      }
      std::reverse(out[r].approach.begin(), out[r].approach.end());
      from = g.cells[goal];
    }
    out[r].coverage = spanning_tree_coverage(region, from, config);
  }
  return out;
}

}  // namespace swarm::planner
