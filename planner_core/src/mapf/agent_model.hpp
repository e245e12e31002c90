// How one agent may act, as the solvers see it: a state (its vertex plus, under the paper's rules,
// a little memory) and the states it can be in one time step later. Built once per instance from
// the instance's graph (InstanceGraph, instance.hpp: a grid's free cells and their 4-neighbours in
// motion.hpp's order, or a graph instance's own graph) and the world rules (instance.hpp).
//
// Standard rules: state = vertex; successors = the wait, then the neighbours in the graph's order.
// Paper rules (WaitRule::PassageMiddles, grids only): state = vertex * 4 + aux, where at an
// intersection aux bit 0 = "has not moved yet" (only then may it stop there) and at a passage
// middle bit 0 = which of its two neighbours it came from (it may not turn back); bit 1 = half-way
// through a 2-step stop (it must wait once more). So an agent enters intersections only at even
// time steps. The graph must outlive the model. Not thread-safe to build; const use is thread-safe.
#pragma once

#include <span>
#include <vector>

#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf::detail {

class AgentModel {
 public:
  AgentModel(const Instance& in, const InstanceGraph& graph)
      : paper_(in.rules.waits == WaitRule::PassageMiddles), graph_(&graph.graph()) {
    if (paper_) {
      middle_.assign(static_cast<std::size_t>(graph_->vertices()), 0);
      for (int v = 0; v < graph_->vertices(); ++v) middle_[static_cast<std::size_t>(v)] = is_passage_middle(in.map, graph.cell(v));
    }
    shift_ = paper_ ? 2 : 0;
  }

  [[nodiscard]] const Graph& graph() const { return *graph_; }
  [[nodiscard]] int shift() const { return shift_; }
  [[nodiscard]] int vertex(int state) const { return state >> shift_; }
  [[nodiscard]] int num_states() const { return graph_->vertices() << shift_; }
  [[nodiscard]] int start_state(int start_vertex) const { return paper_ ? (start_vertex << 2) | 1 : start_vertex; }
  [[nodiscard]] std::span<const int> neighbours(int vertex) const { return graph_->neighbours(vertex); }
  // May an agent in this state stay where it is? (Always under the standard rules.)
  [[nodiscard]] bool can_wait(int state) const {
    if (!paper_) return true;
    const int aux = state & 3;
    return middle_[static_cast<std::size_t>(state >> 2)] ? true : (aux & 1) != 0;
  }

  // Calls f(next_state) for every state one step later: the wait (if allowed) first, then moves.
  template <class F>
  void for_each_successor(int state, F&& f) const {
    if (!paper_) {
      f(state);
      for (const int n : graph_->neighbours(state)) f(n);
      return;
    }
    const int c = state >> 2;
    const int aux = state & 3;
    const std::span<const int> nb = graph_->neighbours(c);
    if (middle_[static_cast<std::size_t>(c)]) {  // exactly two neighbours (is_passage_middle)
      f((c << 2) | (aux ^ 2));  // start or finish a stop
      if ((aux & 2) == 0) {
        const int came_from = aux & 1;
        f(nb[static_cast<std::size_t>(1 - came_from)] << 2);  // arrive at the next intersection, having moved
      }
      return;
    }
    const bool fresh = (aux & 1) != 0;  // has not moved yet
    if (fresh) f((c << 2) | (aux ^ 2));  // stop at the start (2 steps)
    if ((aux & 2) != 0) return;          // half-way through a stop
    for (const int n : nb) {
      // The middle's own neighbour list holds its two ends in a fixed order: remember which one
      // we came from.
      f((n << 2) | (graph_->neighbours(n)[0] == c ? 0 : 1));
    }
  }

 private:
  bool paper_;
  const Graph* graph_;
  int shift_ = 0;
  std::vector<char> middle_;  // paper rules: per vertex, a passage middle?
};

}  // namespace swarm::planner::mapf::detail
