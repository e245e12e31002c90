#include "low_level.hpp"

#include <algorithm>
#include <queue>

namespace swarm::planner::mapf::detail {
namespace {

struct Node {
  int state;
  int t;
  int parent;
  int conflicts;
  int f;
  bool closed;
};

struct FocalEntry {
  int conflicts;
  int f;
  int t;
  int id;
  // priority_queue keeps the largest on top: "larger" = worse.
  friend bool operator<(const FocalEntry& a, const FocalEntry& b) {
    if (a.conflicts != b.conflicts) return a.conflicts > b.conflicts;
    if (a.f != b.f) return a.f > b.f;
    if (a.t != b.t) return a.t < b.t;  // deeper first
    return a.id > b.id;
  }
};

}  // namespace

LowLevel::LowLevel(const Instance& in, const AgentModel& model, const PathTable* reserved)
    : model_(model), reserved_(reserved), vanish_(in.rules.at_goal == GoalRule::Vanish) {
  reserved_last_.assign(static_cast<std::size_t>(model.graph().vertices()), -1);
  if (reserved_ == nullptr) return;
  for (int r = 0;; ++r) {
    const CellPath* p = reserved_->path(r);
    if (p == nullptr) break;
    for (std::size_t t = 0; t < p->size(); ++t) {
      int& last = reserved_last_[static_cast<std::size_t>((*p)[t])];
      last = std::max(last, static_cast<int>(t));
    }
    reserved_last_[static_cast<std::size_t>(p->back())] = PathTable::kForever;
  }
}

int LowLevel::reserved_last_use(int cell) const { return reserved_last_[static_cast<std::size_t>(cell)]; }

LowLevelResult LowLevel::search(const LowLevelQuery& q, const std::function<bool()>& should_stop) {
  LowLevelResult out;
  const Graph& graph = model_.graph();
  FlatMap vertex_c(8), edge_c(8);
  int max_constraint_t = -1;
  int goal_last = -1;
  bool inserted = false;
  if (q.constraints != nullptr) {
    for (const Constraint& c : *q.constraints) {
      max_constraint_t = std::max(max_constraint_t, c.time);
      if (c.kind == Constraint::Vertex) {
        vertex_c.get_or_insert(FlatMap::key(c.cell, c.time), 1, inserted);
        if (c.cell == q.goal_cell) goal_last = std::max(goal_last, c.time);
      } else {
        edge_c.get_or_insert(FlatMap::key(c.time, graph.arc(c.cell, c.cell2)), 1, inserted);
      }
    }
  }
  int min_goal_time = 0;
  if (!vanish_) {
    const int res_last = reserved_last_[static_cast<std::size_t>(q.goal_cell)];
    if (res_last >= PathTable::kForever) return out;  // a reserved robot parks on the goal
    min_goal_time = std::max(goal_last, res_last) + 1;
  }
  int t_static = max_constraint_t;
  if (reserved_ != nullptr) t_static = std::max(t_static, reserved_->horizon());
  if (q.avoid != nullptr) t_static = std::max(t_static, q.avoid->horizon());
  t_static += 1;

  const auto h_of = [&](int cell, int t) {
    const int d = q.h->at(cell);
    if (d >= DistanceTable::kUnreachable) return d;
    return vanish_ ? d : std::max(d, min_goal_time - t);
  };
  const auto blocked = [&](int u, int v, int t1) {
    if (vertex_c.size() > 0 && vertex_c.find(FlatMap::key(v, t1)) != nullptr) return true;
    if (u != v && edge_c.size() > 0 && edge_c.find(FlatMap::key(t1, graph.arc(u, v))) != nullptr) return true;
    if (reserved_ != nullptr) {
      if (reserved_->count_at(v, t1, -1) > 0) return true;
      if (u != v && reserved_->count_swap(u, v, t1, -1) > 0) return true;
    }
    return false;
  };

  std::vector<Node> nodes;
  nodes.reserve(1024);
  FlatMap index(1024);
  std::vector<std::vector<int>> bucket;
  std::vector<int> open_count;
  std::priority_queue<FocalEntry> focal;
  int fmin = 0;
  int added_upto = -1;  // every bucket f <= added_upto has been moved into FOCAL
  const auto ensure_bucket = [&](int f) {
    if (f >= static_cast<int>(bucket.size())) {
      bucket.resize(static_cast<std::size_t>(f) + 1);
      open_count.resize(static_cast<std::size_t>(f) + 1, 0);
    }
  };
  const auto bound = [&] { return static_cast<int>(q.w * fmin + 1e-9); };
  const auto add_node = [&](int state, int t, int parent, int conflicts, int f) {
    const int id = static_cast<int>(nodes.size());
    nodes.push_back({state, t, parent, conflicts, f, false});
    ensure_bucket(f);
    bucket[static_cast<std::size_t>(f)].push_back(id);
    ++open_count[static_cast<std::size_t>(f)];
    if (f <= added_upto) focal.push({conflicts, f, t, id});
    return id;
  };
  // Raises fmin to the smallest f still open and moves the buckets under the new bound to FOCAL.
  const auto refresh = [&]() -> bool {
    while (fmin < static_cast<int>(open_count.size()) && open_count[static_cast<std::size_t>(fmin)] == 0) ++fmin;
    if (fmin >= static_cast<int>(open_count.size())) return false;
    const int b = std::min(bound(), static_cast<int>(bucket.size()) - 1);
    for (int f = added_upto + 1; f <= b; ++f) {
      for (int id : bucket[static_cast<std::size_t>(f)]) {
        const Node& n = nodes[static_cast<std::size_t>(id)];
        if (!n.closed) focal.push({n.conflicts, n.f, n.t, id});
      }
    }
    added_upto = std::max(added_upto, bound());
    return true;
  };

  const int start_cell = model_.vertex(q.start_state);
  {
    const int h0 = h_of(start_cell, 0);
    if (h0 >= DistanceTable::kUnreachable) return out;
    if (vertex_c.find(FlatMap::key(start_cell, 0)) != nullptr) return out;
    fmin = h0;
    index.get_or_insert(FlatMap::key(q.start_state, 0), 0, inserted);
    add_node(q.start_state, 0, -1, 0, h0);
    refresh();
  }

  int goal_id = -1;
  while (true) {
    if (focal.empty() && (!refresh() || focal.empty())) break;
    const FocalEntry top = focal.top();
    focal.pop();
    Node& n = nodes[static_cast<std::size_t>(top.id)];
    if (n.closed || top.conflicts != n.conflicts) continue;
    if ((++out.expanded & 255) == 0 && should_stop && should_stop()) {
      out.stopped = true;
      return out;
    }
    n.closed = true;
    const int lb_now = fmin;
    --open_count[static_cast<std::size_t>(n.f)];
    const int u = model_.vertex(n.state);
    if (u == q.goal_cell && (vanish_ || n.t >= min_goal_time)) {
      goal_id = top.id;
      out.lower_bound = lb_now;
      break;
    }
    if (u == q.goal_cell && vanish_) continue;  // unreachable: arrival ends the path
    const int t1 = n.t + 1;
    const int parent_conflicts = n.conflicts;
    const int parent_state = n.state;
    model_.for_each_successor(parent_state, [&](int s) {
      const int v = model_.vertex(s);
      if (blocked(u, v, t1)) return;
      const int h = h_of(v, t1);
      if (h >= DistanceTable::kUnreachable) return;
      int conflicts = parent_conflicts;
      if (q.avoid != nullptr) {
        conflicts += q.avoid->count_at(v, t1, q.agent);
        if (u != v) conflicts += q.avoid->count_swap(u, v, t1, q.agent);
      }
      const int f = t1 + h;
      const int t_key = std::min(t1, t_static + 1);
      bool fresh = false;
      int& slot = index.get_or_insert(FlatMap::key(s, t_key), -1, fresh);
      if (!fresh) {
        Node& old = nodes[static_cast<std::size_t>(slot)];
        if (!old.closed && old.t == t1 && conflicts < old.conflicts) {
          old.conflicts = conflicts;
          old.parent = top.id;
          if (old.f <= added_upto) focal.push({conflicts, old.f, old.t, slot});
        }
        return;
      }
      slot = static_cast<int>(nodes.size());
      add_node(s, t1, top.id, conflicts, f);
    });
    if (open_count[static_cast<std::size_t>(fmin)] == 0) refresh();
  }
  if (goal_id < 0) return out;
  out.found = true;
  for (int id = goal_id; id != -1; id = nodes[static_cast<std::size_t>(id)].parent) {
    out.cells.push_back(model_.vertex(nodes[static_cast<std::size_t>(id)].state));
  }
  std::reverse(out.cells.begin(), out.cells.end());
  // A path that waited on its goal before the end stops at its last arrival.
  while (!vanish_ && out.cells.size() >= 2 && out.cells[out.cells.size() - 2] == q.goal_cell &&
         static_cast<int>(out.cells.size()) - 2 >= min_goal_time) {
    out.cells.pop_back();
  }
  out.cost = static_cast<int>(out.cells.size()) - 1;
  out.conflicts = nodes[static_cast<std::size_t>(goal_id)].conflicts;
  return out;
}

}  // namespace swarm::planner::mapf::detail
