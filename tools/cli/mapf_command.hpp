// `swarm mapf`: multi-agent path finding on one instance, from the command line.
//
//   swarm mapf --map random-32-32-20.map --scen random-32-32-20-random-1.scen --agents 20 \
//              --solver cbs --time-limit 10 --out runs/mapf
//   swarm mapf --map warehouse-5x8 --random 20 --seed 3 --solver ga
//   swarm mapf --graph ring.graph --solver lacam
//
// The map: a MovingAI `.map`, a ROS map_server YAML, a built-in map name (open, maze1, ...), or
// the paper's warehouse world `warehouse-RxC` (R x C intersections; `warehouse-5x8` is the
// paper's; its rules are the paper's unless --standard-rules). Agents: the first K rows of a
// MovingAI `.scen` (--scen F --agents K), or K random ones (--random K --seed S: distinct random
// free cells; on a warehouse, random intersections). Solvers: cbs, ecbs (--w), lacam, ga, ga1.
// Or, instead of --map and its agents, --graph FILE: a graph and its agents in the text format of
// planner/mapf/graph_file.hpp (`vertices N`, `edge U V`, `agent START GOAL` lines; standard rules;
// every solver but the GA).
//
// Writes into --out DIR (default runs/mapf-<time>): result.json (status, soc, makespan,
// lower_bound, seconds, collisions, paths per agent as [x, y] per time step in the map file's own
// coordinates: MovingAI and warehouse maps x = column, y = row from the top; map_server maps x, y
// = cell column and row from the bottom), paths.png (every path on the map), animation.html (a
// self-contained player: open it in a browser) and instance.scen + map.map (the instance as
// MovingAI files, to run again or elsewhere). With --graph, result.json's starts, goals and paths
// are the file's vertex ids (a path: one id per time step), the pictures draw the graph (the
// file's positions, or the vertices on a circle when it gives none) and instance.graph is the
// instance again.
//
// Exit 0 solved, 1 not solved (timeout, infeasible, failed: the result is still written), 2 bad
// input (a missing or malformed file, a start or goal outside the map or blocked, two agents on
// one start or goal, a scenario for another map, K larger than the scenario, an unknown solver,
// --graph with --map, the GA on a graph), with one message naming the file and line or the flag.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

namespace swarm::tools {

struct MapfOptions {
  std::string map;
  std::string graph;              // a graph instance file instead of map + agents
  std::string scen;
  std::optional<int> agents;      // with scen
  std::optional<int> random;      // K random agents
  std::uint64_t seed = 1;         // random instance and solver seed
  std::string solver = "cbs";
  double w = 1.2;                 // ecbs
  double time_limit_s = 10;
  std::string out_dir;            // "" = runs/mapf-<YYYYmmdd-HHMMSS>
  bool standard_rules = false;    // warehouse maps: MovingAI rules instead of the paper's
  bool last_node_on_timeout = false;  // cbs/ecbs: return the last CT node (the paper's rule)
  bool refine = false;            // lacam: LaCAM* refinement until the time limit
  // GA parameters the paper leaves open (ga.hpp); unset = GaConfig's defaults.
  std::optional<int> ga_population, ga_generations1, ga_generations2, ga_elite, ga_initial_idle;
  std::optional<double> ga_crossover, ga_mutation;
  int scale = 0;                  // pixels per cell in pictures; 0 = fit about 900 pixels
  bool quiet = false;             // no progress lines
};

int mapf_command(const MapfOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
