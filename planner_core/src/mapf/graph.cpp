#include "swarm/planner/mapf/graph.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace swarm::planner::mapf {
namespace {

std::uint64_t pair_key(int u, int v) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(u, v))) << 32) |
         static_cast<std::uint32_t>(std::max(u, v));
}

// Why edge e cannot be in the adjacency ("" = it can); `first_of` remembers the first index of
// every valid pair, so a repeat names it.
std::string edge_problem(int vertices, const std::vector<Edge>& edges, std::size_t e,
                         std::unordered_map<std::uint64_t, std::size_t>& first_of) {
  const Edge& x = edges[e];
  const std::string name = "edge " + std::to_string(e) + " (" + std::to_string(x.u) + " -- " + std::to_string(x.v) + ")";
  for (int w : {x.u, x.v}) {
    if (w < 0 || w >= vertices) {
      return name + ": vertex " + std::to_string(w) + " is not in the graph (vertices 0.." + std::to_string(vertices - 1) + ")";
    }
  }
  if (x.u == x.v) return name + " is a self loop";
  if (const auto [it, fresh] = first_of.emplace(pair_key(x.u, x.v), e); !fresh) {
    return name + " repeats edge " + std::to_string(it->second);
  }
  return "";
}

}  // namespace

Graph::Graph(int vertices, std::vector<Edge> edges, std::vector<Position> positions)
    : vertices_(std::max(vertices, 0)), edges_(std::move(edges)), positions_(std::move(positions)) {
  std::vector<char> valid(edges_.size(), 0);
  std::unordered_map<std::uint64_t, std::size_t> first_of;
  first_.assign(static_cast<std::size_t>(vertices_) + 1, 0);
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    if (!edge_problem(vertices_, edges_, e, first_of).empty()) continue;
    valid[e] = 1;
    ++first_[static_cast<std::size_t>(edges_[e].u) + 1];
    ++first_[static_cast<std::size_t>(edges_[e].v) + 1];
  }
  for (std::size_t v = 0; v < static_cast<std::size_t>(vertices_); ++v) first_[v + 1] += first_[v];
  neighbours_.resize(static_cast<std::size_t>(first_.back()));
  std::vector<int> fill(first_.begin(), first_.end() - 1);
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    if (!valid[e]) continue;
    const Edge& x = edges_[e];
    neighbours_[static_cast<std::size_t>(fill[static_cast<std::size_t>(x.u)]++)] = x.v;
    neighbours_[static_cast<std::size_t>(fill[static_cast<std::size_t>(x.v)]++)] = x.u;
  }
}

Graph Graph::from_adjacency(std::vector<int> first, std::vector<int> neighbours, std::vector<Position> positions) {
  Graph g;
  g.vertices_ = static_cast<int>(first.size()) - 1;
  g.first_ = std::move(first);
  g.neighbours_ = std::move(neighbours);
  g.positions_ = std::move(positions);
  for (int u = 0; u < g.vertices_; ++u) {
    for (int v : g.neighbours(u)) {
      if (u < v) g.edges_.push_back({u, v});
    }
  }
  return g;
}

std::vector<std::string> check_graph(const Graph& graph) {
  constexpr std::size_t kListed = 10;
  std::vector<std::string> out;
  const int n = graph.vertices();
  std::unordered_map<std::uint64_t, std::size_t> first_of;
  std::size_t bad = 0;
  for (std::size_t e = 0; e < graph.edges().size(); ++e) {
    std::string why = edge_problem(n, graph.edges(), e, first_of);
    if (why.empty()) continue;
    if (++bad <= kListed) out.push_back(std::move(why));
  }
  // A graph made from adjacency lists: every move must go both ways.
  for (int u = 0; u < n; ++u) {
    for (int v : graph.neighbours(u)) {
      std::string why;
      if (!graph.has_vertex(v)) {
        why = "is not in the graph";
      } else if (v == u) {
        why = "is a self loop";
      } else if (graph.arc(v, u) < 0) {
        why = "has no way back (a graph's edges are undirected)";
      }
      if (!why.empty() && ++bad <= kListed) {
        out.push_back("the move " + std::to_string(u) + " -> " + std::to_string(v) + " " + why);
      }
    }
  }
  if (bad > kListed) out.push_back("... and " + std::to_string(bad - kListed) + " more edge problems");
  if (!graph.positions().empty() && static_cast<int>(graph.positions().size()) != n) {
    out.push_back(std::to_string(graph.positions().size()) + " positions for " + std::to_string(n) +
                  " vertices (give one per vertex, or none)");
  }
  return out;
}

}  // namespace swarm::planner::mapf
