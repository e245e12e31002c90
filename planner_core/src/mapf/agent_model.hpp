// How one agent may act, as the solvers see it: a state (its cell plus, under the paper's rules,
// a little memory) and the states it can be in one time step later. Built once per instance from
// the motion model (motion.hpp decides which cells neighbour) and the world rules (instance.hpp).
//
// Standard rules: state = cell index; successors = the 4 neighbours and a wait.
// Paper rules (WaitRule::PassageMiddles): state = cell index * 4 + aux, where at an intersection
// aux bit 0 = "has not moved yet" (only then may it stop there) and at a passage middle bit 0 =
// which of its two neighbours it came from (it may not turn back); bit 1 = half-way through a
// 2-step stop (it must wait once more). So an agent enters intersections only at even time steps.
// Not thread-safe to build; const use is thread-safe.
#pragma once

#include <array>
#include <vector>

#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf::detail {

class AgentModel {
 public:
  explicit AgentModel(const Instance& in) : paper_(in.rules.waits == WaitRule::PassageMiddles) {
    const int cells = static_cast<int>(in.map.size());
    neighbours_.assign(static_cast<std::size_t>(cells), {-1, -1, -1, -1});
    middle_.assign(static_cast<std::size_t>(cells), 0);
    for (int i = 0; i < cells; ++i) {
      const Cell c = in.map.cell_of(i);
      if (!in.map.is_free(c)) continue;
      int k = 0;
      in.motion.for_each_neighbour(in.map, c, [&](Cell n, double) { neighbours_[static_cast<std::size_t>(i)][k++] = in.map.index(n); });
      middle_[static_cast<std::size_t>(i)] = paper_ && is_passage_middle(in.map, c);
    }
    shift_ = paper_ ? 2 : 0;
  }

  [[nodiscard]] int shift() const { return shift_; }
  [[nodiscard]] int cell(int state) const { return state >> shift_; }
  [[nodiscard]] int num_states() const { return static_cast<int>(neighbours_.size()) << shift_; }
  [[nodiscard]] int start_state(int start_cell) const { return paper_ ? (start_cell << 2) | 1 : start_cell; }
  [[nodiscard]] const std::array<int, 4>& neighbours(int cell_index) const {
    return neighbours_[static_cast<std::size_t>(cell_index)];
  }
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
      for (int n : neighbours_[static_cast<std::size_t>(state)]) {
        if (n >= 0) f(n);
      }
      return;
    }
    const int c = state >> 2;
    const int aux = state & 3;
    const auto& nb = neighbours_[static_cast<std::size_t>(c)];
    if (middle_[static_cast<std::size_t>(c)]) {
      f((c << 2) | (aux ^ 2));  // start or finish a stop
      if ((aux & 2) == 0) {
        const int came_from = aux & 1;
        const int onward = nb[static_cast<std::size_t>(1 - came_from)];
        if (onward >= 0) f(onward << 2);  // arrive at the next intersection, having moved
      }
      return;
    }
    const bool fresh = (aux & 1) != 0;  // has not moved yet
    if (fresh) f((c << 2) | (aux ^ 2));  // stop at the start (2 steps)
    if ((aux & 2) != 0) return;          // half-way through a stop
    for (int n : nb) {
      if (n < 0) continue;
      // The middle's own neighbour list holds its two ends in a fixed order: remember which one
      // we came from.
      const auto& mb = neighbours_[static_cast<std::size_t>(n)];
      f((n << 2) | (mb[0] == c ? 0 : 1));
    }
  }

 private:
  bool paper_;
  int shift_ = 0;
  std::vector<std::array<int, 4>> neighbours_;
  std::vector<char> middle_;
};

}  // namespace swarm::planner::mapf::detail
