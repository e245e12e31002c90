// MAPF graph instance files: a graph and its agents as text, in and out.
//
// The MovingAI benchmark has formats for grids only (.map, .scen: movingai_scen.hpp) and the MAPF
// literature has no common one for general graphs, so this is ours, one statement a line:
//
//   # a ring of 6 with the chord 0 -- 3     ('#' starts a comment; blank lines are skipped)
//   vertices 6           # first: the number of vertices, numbered 0 .. N-1
//   position 0 1.0 0.0   # optional, for pictures only: vertex x y (every vertex or none)
//   edge 0 1             # an undirected edge of unit length; each pair once, no self loops
//   edge 1 2
//   ...
//   agent 0 3            # an agent: start vertex, goal vertex (agents are numbered in file order)
//   agent 3 0
//
// Words are separated by spaces or tabs; after the `vertices` line the other lines may come in
// any order. The instance has the standard rules (instance.hpp: agents stay on their goals, wait
// anywhere) and no reserved paths; its vertex v is the cell vertex_cell(v) = (v, 0).
//
// Errors are process-edge failures: MapFileError (map_io.hpp) naming the file, the line and what
// was expected, e.g. "ring.graph:7: edge 2 9: vertex 9 is not in the graph (vertices 0..5)". A
// file that loads is a valid instance (check_instance finds nothing); it may still be unsolvable.
//
//   const Instance in = load_graph_instance("ring.graph");
//   const Result r = solve(in, SolverConfig{}, StopCondition::after(10));
//   save_graph_instance("/tmp/copy.graph", in);
//
// Thread-safe (no shared state).
#pragma once

#include <string>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf {

// The most vertices a file may declare (the graph is held in memory).
inline constexpr int kMaxGraphFileVertices = 10'000'000;

// Reads a graph instance file. Throws MapFileError.
[[nodiscard]] Instance load_graph_instance(const std::string& path);

// Writes the instance in the format above: a graph instance as it is, a grid instance as its
// graph (graph_instance: one vertex per free cell, positions = cells; read back, its vertices list
// their neighbours in edge order, not the grid's, so ties between equally good plans may go the
// other way). Rules and reserved paths are not written. Throws MapFileError when the file cannot
// be written.
void save_graph_instance(const std::string& path, const Instance& in);

}  // namespace swarm::planner::mapf
