// Who is where when: the timed paths of a set of agents, indexed by (vertex, time step), for the
// solvers' conflict checks, conflict-avoidance tie-breaking and reservation lookups. An agent that
// "parks" stays on its last vertex for ever after its path (GoalRule::Stay, reserved robots); one
// that does not leaves the table when its path ends (GoalRule::Vanish). Paths are vertices of the
// instance's graph (InstanceGraph, instance.hpp) per time step and must outlive the table. Not
// thread-safe to build.
#pragma once

#include <algorithm>
#include <vector>

#include "flat_map.hpp"

namespace swarm::planner::mapf::detail {

using CellPath = std::vector<int>;  // vertex (InstanceGraph, instance.hpp) per time step

class PathTable {
 public:
  PathTable() = default;
  explicit PathTable(int agents) : paths_(static_cast<std::size_t>(agents), nullptr), parks_(static_cast<std::size_t>(agents), 0) {}

  void add(int agent, const CellPath* path, bool parks) {
    if (path == nullptr || path->empty()) return;
    if (agent >= static_cast<int>(paths_.size())) {
      paths_.resize(static_cast<std::size_t>(agent) + 1, nullptr);
      parks_.resize(static_cast<std::size_t>(agent) + 1, 0);
    }
    paths_[static_cast<std::size_t>(agent)] = path;
    parks_[static_cast<std::size_t>(agent)] = parks;
    const int len = static_cast<int>(path->size());
    horizon_ = std::max(horizon_, len);
    bool inserted = false;
    for (int t = 0; t < len; ++t) {
      int& head = at_.get_or_insert(FlatMap::key((*path)[static_cast<std::size_t>(t)], t), -1, inserted);
      entries_.push_back({agent, head});
      head = static_cast<int>(entries_.size()) - 1;
    }
    if (parks) {
      int& head = parked_.get_or_insert(static_cast<std::uint64_t>(path->back()), -1, inserted);
      entries_.push_back({agent, head});
      head = static_cast<int>(entries_.size()) - 1;
    }
  }

  [[nodiscard]] int horizon() const { return horizon_; }
  [[nodiscard]] const CellPath* path(int agent) const {
    return agent < static_cast<int>(paths_.size()) ? paths_[static_cast<std::size_t>(agent)] : nullptr;
  }

  // The cell of `agent` at time t, or -1 when it is not in the table then.
  [[nodiscard]] int cell_at(int agent, int t) const {
    const CellPath* p = path(agent);
    if (p == nullptr) return -1;
    if (t < static_cast<int>(p->size())) return (*p)[static_cast<std::size_t>(t)];
    return parks_[static_cast<std::size_t>(agent)] ? p->back() : -1;
  }

  // Calls f(agent) for every agent on `cell` at time t (parked ones included).
  template <class F>
  void for_each_at(int cell, int t, F&& f) const {
    if (const int* head = at_.find(FlatMap::key(cell, t))) {
      for (int e = *head; e != -1; e = entries_[static_cast<std::size_t>(e)].next) f(entries_[static_cast<std::size_t>(e)].agent);
    }
    if (const int* head = parked_.find(static_cast<std::uint64_t>(cell))) {
      for (int e = *head; e != -1; e = entries_[static_cast<std::size_t>(e)].next) {
        const int a = entries_[static_cast<std::size_t>(e)].agent;
        if (t >= static_cast<int>(paths_[static_cast<std::size_t>(a)]->size())) f(a);
      }
    }
  }
  [[nodiscard]] int count_at(int cell, int t, int exclude) const {
    int n = 0;
    for_each_at(cell, t, [&](int a) { n += a != exclude; });
    return n;
  }
  // Calls f(agent) for every agent that moves to -> from during the step ending at t (so that a
  // move from -> to in that step would swap with it).
  template <class F>
  void for_each_swap(int from, int to, int t, F&& f) const {
    if (t <= 0 || from == to) return;
    for_each_at(to, t - 1, [&](int a) {
      if (cell_at(a, t) == from) f(a);
    });
  }
  [[nodiscard]] int count_swap(int from, int to, int t, int exclude) const {
    int n = 0;
    for_each_swap(from, to, t, [&](int a) { n += a != exclude; });
    return n;
  }
  // The last time step at which some agent is on `cell`; kForever if one parks there; -1 if never.
  static constexpr int kForever = 1 << 29;
  [[nodiscard]] int last_use(int cell) const {
    if (parked_.find(static_cast<std::uint64_t>(cell)) != nullptr) return kForever;
    int last = -1;
    for (int t = horizon_ - 1; t >= 0 && last < 0; --t) {
      if (at_.find(FlatMap::key(cell, t)) != nullptr) last = t;
    }
    return last;
  }

 private:
  struct Entry {
    int agent;
    int next;
  };
  std::vector<const CellPath*> paths_;
  std::vector<char> parks_;
  FlatMap at_;
  FlatMap parked_;
  std::vector<Entry> entries_;
  int horizon_ = 0;
};

}  // namespace swarm::planner::mapf::detail
