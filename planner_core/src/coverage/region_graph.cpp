#include "swarm/planner/coverage/region_graph.hpp"

#include <algorithm>
#include <cassert>

namespace swarm::planner {

RegionGraph RegionGraph::build(const OccupancyGrid& region) {
  RegionGraph g;
  g.width = region.width();
  g.height = region.height();
  g.compact.assign(region.size(), -1);
  for (int i = 0; i < static_cast<int>(region.size()); ++i) {
    if (region.at(i) != CellState::Free) continue;
    g.compact[i] = static_cast<int>(g.cells.size());
    g.cells.push_back(region.cell_of(i));
  }
  const MotionModel four = MotionModel::four();
  g.next.assign(g.cells.size(), {-1, -1, -1, -1});
  for (std::size_t i = 0; i < g.cells.size(); ++i) {
    const Cell c = g.cells[i];
    for (int k = 0; k < 4; ++k) {
      const Cell n{c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]};
      if (four.check(region, c, n) == MoveCheck::Ok) g.next[i][k] = g.compact[region.index(n)];
    }
  }
  return g;
}

std::vector<int> bfs_steps(const RegionGraph& graph, const std::vector<int>& sources,
                           std::vector<int>* order) {
  std::vector<int> dist(graph.cells.size(), -1);
  std::vector<int> local;
  std::vector<int>& queue = order != nullptr ? *order : local;
  queue.clear();
  queue.reserve(graph.cells.size());
  for (int s : sources) {
    assert(s >= 0 && s < graph.size());
    if (dist[s] >= 0) continue;
    dist[s] = 0;
    queue.push_back(s);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int c = queue[head];
    for (int n : graph.next[c]) {
      if (n < 0 || dist[n] >= 0) continue;
      dist[n] = dist[c] + 1;
      queue.push_back(n);
    }
  }
  return dist;
}

std::vector<int> components(const RegionGraph& graph, int& count) {
  std::vector<int> label(graph.cells.size(), -1);
  std::vector<int> queue;
  count = 0;
  for (int start = 0; start < graph.size(); ++start) {
    if (label[start] >= 0) continue;
    label[start] = count;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      for (int n : graph.next[queue[head]]) {
        if (n < 0 || label[n] >= 0) continue;
        label[n] = count;
        queue.push_back(n);
      }
    }
    ++count;
  }
  return label;
}

bool simple_point(const RegionGraph& graph, const std::vector<int>& owner, int c, int r) {
  // r's 4-neighbours of c, in order around it (+x, +y, -x, -y); two consecutive ones are joined
  // when the corner cell between them is r's too. Removing c keeps r's cells around it together
  // exactly when that leaves one group.
  const auto& nb = graph.next[c];  // RegionGraph order: +x, -x, +y, -y
  const int ring[4] = {nb[0], nb[2], nb[1], nb[3]};
  constexpr int kTowardsNext[4] = {2, 1, 3, 0};  // the direction of ring[k + 1] as seen from c
  auto mine = [&](int cell) { return cell >= 0 && owner[cell] == r; };
  int present = 0, joined = 0;
  for (int k = 0; k < 4; ++k) {
    if (!mine(ring[k])) continue;
    ++present;
    if (mine(ring[(k + 1) % 4]) && mine(graph.next[ring[k]][kTowardsNext[k]])) ++joined;
  }
  return present > 0 && (joined == 4 || present - joined == 1);
}

std::vector<std::uint8_t> join_pieces(const OccupancyGrid& map, std::vector<std::uint8_t> mask, int* pieces) {
  assert(mask.size() == map.size());
  const RegionGraph set = RegionGraph::build(region_grid(map, mask));
  int count = 0;
  const std::vector<int> piece_of_set_cell = components(set, count);
  if (pieces) *pieces = count;
  if (count < 2) return mask;
  const RegionGraph free = RegionGraph::build(region_grid(map, {}));
  std::vector<int> piece(static_cast<std::size_t>(free.size()), -1);  // per Free cell, -1: not in the set
  std::vector<int> size(static_cast<std::size_t>(count), 0);
  for (int i = 0; i < set.size(); ++i) {
    piece[static_cast<std::size_t>(free.index_of(set.cells[static_cast<std::size_t>(i)]))] = piece_of_set_cell[i];
    ++size[static_cast<std::size_t>(piece_of_set_cell[i])];
  }
  const int largest = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
  std::vector<std::uint8_t> in_whole(static_cast<std::size_t>(free.size()), 0);  // the joined pieces and paths
  for (int c = 0; c < free.size(); ++c) in_whole[c] = piece[c] == largest;
  std::vector<int> parent(static_cast<std::size_t>(free.size()));
  std::vector<int> queue;
  for (int left = count - 1; left > 0; --left) {
    // Breadth-first from the whole so far, to the first cell of a piece not joined yet.
    std::fill(parent.begin(), parent.end(), -2);
    queue.clear();
    for (int c = 0; c < free.size(); ++c) {
      if (!in_whole[c]) continue;
      parent[c] = -1;
      queue.push_back(c);
    }
    int reached = -1;
    for (std::size_t head = 0; head < queue.size() && reached < 0; ++head) {
      for (const int n : free.next[static_cast<std::size_t>(queue[head])]) {
        if (n < 0 || parent[n] != -2) continue;
        parent[n] = queue[head];
        if (piece[n] >= 0) {
          reached = n;
          break;
        }
        queue.push_back(n);
      }
    }
    if (reached < 0) break;  // the rest no Free path reaches
    const int p = piece[reached];
    for (int c = 0; c < free.size(); ++c) in_whole[c] = in_whole[c] || piece[c] == p;
    for (int c = parent[reached]; c >= 0 && !in_whole[c]; c = parent[c]) {
      in_whole[c] = 1;
      mask[static_cast<std::size_t>(map.index(free.cells[static_cast<std::size_t>(c)]))] = 1;
    }
  }
  return mask;
}

OccupancyGrid region_grid(const OccupancyGrid& map, const std::vector<std::uint8_t>& mask) {
  assert(mask.empty() || mask.size() == map.size());
  OccupancyGrid out(map.width(), map.height(), map.resolution(), map.origin_x(), map.origin_y(),
                    CellState::Occupied);
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (map.at(i) == CellState::Free && (mask.empty() || mask[i] != 0)) out.set(i, CellState::Free);
  }
  return out;
}

}  // namespace swarm::planner
