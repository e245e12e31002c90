// The independent check of a MAPF plan: every solver's output and every test goes through it.
//
// It knows nothing of how plans are made. For each agent it checks the path itself: it starts on
// the agent's start, ends on its goal, and every step is a legal action (step_problem,
// instance.hpp: on a grid the motion model's, motion.hpp: a wait, or a move to an adjacent free
// cell; on a graph a wait on a vertex or a move along an edge); under the paper's rules
// (WaitRule::PassageMiddles) also that waits happen only in passage middles or at the start before
// the first move, in blocks of 2 steps, and that no agent turns back inside a passage. Then it
// counts conflicts over time: at every time step, one VERTEX conflict per pair of agents on one
// cell, and one SWAP conflict per pair that exchanged cells during the step (the paper's
// "collision": one count per colliding pair per step). Agents stay on their goals after their
// paths end (GoalRule::Stay) or leave the check once they arrive (Vanish: an agent is still
// checked at its arrival step). Reserved robots (Instance::reserved) follow their paths and then
// stay for ever; a conflict with one names it as agent -1 - r. Past the longest path nothing
// moves, so a lasting overlap there is counted once, at the last time step. On a graph instance
// cells are vertex_cell(v): a conflict "at (3, 0)" is on vertex 3 (path problems say "vertex 3").
//
// Thread-safe (pure function).
//
//   const ValidationReport r = validate(instance, paths);
//   if (!r.ok()) std::cerr << r.summary() << "\n";   // "2 conflicts (first: vertex ...)"
#pragma once

#include <string>
#include <vector>

#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf {

enum class ConflictKind { Vertex, Swap };

struct Conflict {
  ConflictKind kind = ConflictKind::Vertex;
  int a = 0;      // agent index; a < b for two planned agents
  int b = 0;      // agent index, or -1 - r for reserved path r
  Cell cell;      // Vertex: the shared cell; Swap: a's cell before the step (b's after)
  Cell other;     // Swap: a's cell after the step; Vertex: == cell
  int time = 0;   // the time step of the overlap (Swap: the step's end)
};

// A path that breaks the rules on its own (not a conflict with others).
struct PathProblem {
  int agent = 0;
  int time = 0;        // the time step where it happens (0 for start/empty problems)
  std::string what;    // e.g. "step (3, 4) -> (5, 4): not adjacent", "step vertex 2 -> vertex 5: not adjacent"
};

struct ValidationReport {
  std::vector<PathProblem> problems;
  std::vector<Conflict> conflicts;

  [[nodiscard]] bool ok() const { return problems.empty() && conflicts.empty(); }
  // One line: "valid" or "<n> conflicts, <m> path problems (first: ...)".
  [[nodiscard]] std::string summary() const;
};

[[nodiscard]] ValidationReport validate(const Instance& in, const std::vector<Path>& paths);

// "vertex conflict of agents 1 and 4 at (3, 5), time 7" and the like.
[[nodiscard]] std::string describe(const Conflict& c);

}  // namespace swarm::planner::mapf
