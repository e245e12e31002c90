// An undirected graph for multi-agent path finding on something other than a grid: V vertices
// numbered 0..V-1, unit-length edges, and optionally a position per vertex (for pictures only:
// no solver reads it). Adjacency is stored in CSR form (one array of every vertex's neighbours,
// and where each vertex's part starts), so a vertex may have any number of neighbours.
//
// Vertex u's neighbours are listed in the order of the edges that name u. That order is the order
// in which the solvers try moves, so it decides ties between equally good plans (deterministic).
// Edges are kept as given: an edge naming a vertex outside 0..V-1, a self loop or a repeated
// edge is left out of the adjacency and reported by check_graph (and so by check_instance).
//
// A grid is one way to make a graph (instance.hpp: InstanceGraph, one vertex per free cell).
// graph_file.hpp reads and writes graph instances as text. Thread-safe: a Graph is a value.
//
//   const Graph ring(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {0, 3}});  // + a chord
//   for (int n : ring.neighbours(0)) ...          // 1, 5, 3
//   ring.adjacent(0, 3);                          // true
//   if (const auto problems = check_graph(ring); !problems.empty()) ...
#pragma once

#include <span>
#include <string>
#include <vector>

namespace swarm::planner::mapf {

struct Edge {
  int u = 0;
  int v = 0;
  friend bool operator==(const Edge&, const Edge&) = default;
};

// Where a vertex is drawn (any unit: pictures scale to fit).
struct Position {
  double x = 0;
  double y = 0;
  friend bool operator==(const Position&, const Position&) = default;
};

class Graph {
 public:
  Graph() = default;
  // `positions`: empty, or one per vertex. A negative vertex count makes an empty graph.
  Graph(int vertices, std::vector<Edge> edges, std::vector<Position> positions = {});
  // From adjacency in CSR form, which must be symmetric (a grid's moves, instance.cpp): vertex
  // v's neighbours are neighbours[first[v] .. first[v + 1]). edges() lists each edge once (u < v).
  static Graph from_adjacency(std::vector<int> first, std::vector<int> neighbours, std::vector<Position> positions = {});

  [[nodiscard]] int vertices() const { return vertices_; }
  [[nodiscard]] bool has_vertex(int v) const { return v >= 0 && v < vertices_; }
  // The edges as given, valid or not.
  [[nodiscard]] const std::vector<Edge>& edges() const { return edges_; }
  [[nodiscard]] const std::vector<Position>& positions() const { return positions_; }

  [[nodiscard]] std::span<const int> neighbours(int v) const {
    const auto begin = static_cast<std::size_t>(first_[static_cast<std::size_t>(v)]);
    const auto end = static_cast<std::size_t>(first_[static_cast<std::size_t>(v) + 1]);
    return {neighbours_.data() + begin, end - begin};
  }
  [[nodiscard]] int degree(int v) const {
    return first_[static_cast<std::size_t>(v) + 1] - first_[static_cast<std::size_t>(v)];
  }
  // The index of the move u -> v among all moves (0 .. 2E - 1), or -1 if u and v are not adjacent:
  // a key for per-move data (the solvers' edge constraints).
  [[nodiscard]] int arc(int u, int v) const {
    for (int k = first_[static_cast<std::size_t>(u)]; k < first_[static_cast<std::size_t>(u) + 1]; ++k) {
      if (neighbours_[static_cast<std::size_t>(k)] == v) return k;
    }
    return -1;
  }
  [[nodiscard]] bool adjacent(int u, int v) const { return has_vertex(u) && has_vertex(v) && arc(u, v) >= 0; }

  friend bool operator==(const Graph& a, const Graph& b) {
    return a.vertices_ == b.vertices_ && a.first_ == b.first_ && a.neighbours_ == b.neighbours_ &&
           a.positions_ == b.positions_;
  }

 private:
  int vertices_ = 0;
  std::vector<Edge> edges_;
  std::vector<int> first_ = {0};  // vertices_ + 1 entries
  std::vector<int> neighbours_;
  std::vector<Position> positions_;
};

// What is wrong with a graph (empty = fine): an edge naming a vertex that does not exist, a self
// loop, an edge given twice (either way round), a move without its way back (from_adjacency),
// positions for some vertices but not all. At most 10 edge problems are listed, then how many more.
[[nodiscard]] std::vector<std::string> check_graph(const Graph& graph);

}  // namespace swarm::planner::mapf
