// CBS / ECBS (cbs.hpp): one constraint-tree search; w = 1 is CBS (with ICBS's conflict priority
// and bypassing), w > 1 is ECBS (focal search on both levels).
#include <algorithm>
#include <deque>
#include <chrono>
#include <memory>
#include <set>
#include <tuple>

#include "agent_model.hpp"
#include "low_level.hpp"
#include "path_table.hpp"
#include "solvers.hpp"

namespace swarm::planner::mapf::detail {
namespace {

struct AgentPlan {
  CellPath cells;
  int cost = 0;
  int lower_bound = 0;  // the low level's bound on this agent's optimum under its constraints
};
using PlanPtr = const AgentPlan*;  // into ConflictSearch::plan_pool_ (a deque: never moves)

struct HlConflict {
  int a = 0;
  int b = 0;
  int kind = 0;  // 0 vertex (both on `cell` at t), 1 edge (a: cell -> cell2, b: cell2 -> cell, ending t)
  int cell = 0;
  int cell2 = 0;
  int t = 0;
};

// Cells per level of an agent's MDD (all its paths of exactly its cost under its constraints).
struct Mdd {
  std::vector<int> first;  // level t's cells are cells[first[t] .. first[t + 1])
  std::vector<int> cells;
  [[nodiscard]] int width(int t) const { return first[static_cast<std::size_t>(t) + 1] - first[static_cast<std::size_t>(t)]; }
  [[nodiscard]] int cell(int t) const { return cells[static_cast<std::size_t>(first[static_cast<std::size_t>(t)])]; }
};
using MddPtr = const Mdd*;  // into ConflictSearch::mdd_pool_

struct CtNode {
  int parent = -1;
  std::vector<Constraint> added;
  std::vector<PlanPtr> plans;
  std::vector<HlConflict> conflicts;
  std::vector<MddPtr> mdds;  // per agent, built on demand (CBS only)
  long long cost = 0;
  long long lb = 0;
  int depth = 0;
};

class ConflictSearch {
 public:
  ConflictSearch(const Instance& in, double w, bool prioritize, bool bypass, TimeoutPlan plan, const StopCondition& stop)
      : in_(in),
        n_(in.agents()),
        w_(w),
        prioritize_(prioritize && w <= 1.0),
        bypass_(bypass),
        timeout_plan_(plan),
        stop_(stop),
        graph_(in),
        model_(in, graph_),
        vanish_(in.rules.at_goal == GoalRule::Vanish) {
    reserved_cells_.resize(in.reserved.size());
    for (std::size_t r = 0; r < in.reserved.size(); ++r) {
      for (Cell c : in.reserved[r]) reserved_cells_[r].push_back(graph_.vertex(c));
      reserved_.add(static_cast<int>(r), &reserved_cells_[r], true);
    }
    low_ = std::make_unique<LowLevel>(in, model_, in.reserved.empty() ? nullptr : &reserved_);
    for (int a = 0; a < n_; ++a) {
      goal_cell_.push_back(graph_.vertex(in.goals[static_cast<std::size_t>(a)]));
      h_.emplace_back(graph_.graph(), goal_cell_.back());
      start_state_.push_back(model_.start_state(graph_.vertex(in.starts[static_cast<std::size_t>(a)])));
    }
    should_stop_ = [this] { return stop_.reached(); };
  }

  Result run() {
    Result out;
    // Root: agents planned one after another, each avoiding (softly) those planned before it.
    auto root = std::make_unique<CtNode>();
    root->plans.resize(static_cast<std::size_t>(n_));
    {
      PathTable so_far(n_);
      for (int a = 0; a < n_; ++a) {
        const std::vector<Constraint> none;
        auto plan = plan_agent(a, none, &so_far);
        if (!plan) {
          out.status = stopped_ ? Status::Timeout : Status::Infeasible;
          if (!stopped_) out.message = "agent " + std::to_string(a) + " has no path to its goal";
          return finish(out);
        }
        root->plans[static_cast<std::size_t>(a)] = plan;
        so_far.add(a, &root->plans[static_cast<std::size_t>(a)]->cells, !vanish_);
      }
    }
    root->mdds.resize(static_cast<std::size_t>(n_));
    summarise_root(*root);
    push(std::move(root));

    while (true) {
      if (stop_.reached()) {
        out.status = Status::Timeout;
        return finish(out);
      }
      const int id = pop();
      if (id < 0) {
        out.status = Status::Infeasible;
        out.message = "every branch of the constraint tree is closed: no plan exists";
        return finish(out);
      }
      CtNode& node = *nodes_[static_cast<std::size_t>(id)];
      last_expanded_ = id;
      note_best(id);
      ++stats_.high_level_expanded;
      if (node.conflicts.empty()) {
        best_ = id;
        out.status = Status::Solved;
        return finish(out);
      }
      expand(id);
      if (stopped_) {
        out.status = Status::Timeout;
        return finish(out);
      }
    }
  }

 private:
  // ---- low level -----------------------------------------------------------------------------
  PlanPtr plan_agent(int a, const std::vector<Constraint>& constraints, const PathTable* avoid) {
    LowLevelQuery q;
    q.agent = a;
    q.start_state = start_state_[static_cast<std::size_t>(a)];
    q.goal_cell = goal_cell_[static_cast<std::size_t>(a)];
    q.h = &h_[static_cast<std::size_t>(a)];
    q.constraints = &constraints;
    q.avoid = avoid;
    q.w = w_;
    LowLevelResult r = low_->search(q, should_stop_);
    stats_.low_level_expanded += r.expanded;
    if (r.stopped) stopped_ = true;
    if (!r.found) return nullptr;
    AgentPlan& p = plan_pool_.emplace_back();
    p.cells = std::move(r.cells);
    p.cost = r.cost;
    p.lower_bound = w_ <= 1.0 ? r.cost : std::min(r.lower_bound, r.cost);
    return &p;
  }

  std::vector<Constraint> constraints_of(int id, int agent) const {
    std::vector<Constraint> out;
    for (int n = id; n != -1; n = nodes_[static_cast<std::size_t>(n)]->parent) {
      for (const Constraint& c : nodes_[static_cast<std::size_t>(n)]->added) {
        if (c.agent == agent) out.push_back(c);
      }
    }
    return out;
  }

  // ---- conflicts -------------------------------------------------------------------------------
  // Conflicts of agent a's path with the agents of `table` (a itself skipped). `both_moving_after`:
  // keep a conflict of two moving agents only with agents b > a (the root's scan sees each such
  // pair from both sides); `tail`: also a's parked tail (Stay) against agents passing later.
  void conflicts_of(int a, const CellPath& p, const PathTable& table, bool only_higher, bool tail,
                    std::vector<HlConflict>& out) const {
    const int len = static_cast<int>(p.size());
    for (int t = 0; t < len; ++t) {
      const int c = p[static_cast<std::size_t>(t)];
      table.for_each_at(c, t, [&](int b) {
        if (b == a) return;
        const CellPath* pb = table.path(b);
        const bool b_parked = t >= static_cast<int>(pb->size());
        if (only_higher && !b_parked && b < a) return;
        out.push_back({a, b, 0, c, c, t});
      });
      if (t > 0 && p[static_cast<std::size_t>(t - 1)] != c) {
        const int u = p[static_cast<std::size_t>(t - 1)];
        table.for_each_swap(u, c, t, [&](int b) {
          if (b == a || (only_higher && b < a)) return;
          out.push_back({a, b, 1, u, c, t});
        });
      }
    }
    if (tail && !vanish_) {
      const int g = p.back();
      for (int t = len; t < table.horizon(); ++t) {
        table.for_each_at(g, t, [&](int b) {
          if (b == a || t >= static_cast<int>(table.path(b)->size())) return;
          out.push_back({a, b, 0, g, g, t});
        });
      }
    }
  }

  PathTable table_of(const CtNode& node) const {
    PathTable t(n_);
    for (int a = 0; a < n_; ++a) t.add(a, &node.plans[static_cast<std::size_t>(a)]->cells, !vanish_);
    return t;
  }

  void summarise_root(CtNode& node) {
    const PathTable table = table_of(node);
    node.conflicts.clear();
    node.cost = node.lb = 0;
    for (int a = 0; a < n_; ++a) {
      conflicts_of(a, node.plans[static_cast<std::size_t>(a)]->cells, table, true, false, node.conflicts);
      node.cost += node.plans[static_cast<std::size_t>(a)]->cost;
      node.lb += node.plans[static_cast<std::size_t>(a)]->lower_bound;
    }
  }

  // The parent's conflicts without agent a's, plus those of a's new path.
  std::vector<HlConflict> conflicts_after(const CtNode& parent, int a, const CellPath& p, const PathTable& table) const {
    std::vector<HlConflict> out;
    for (const HlConflict& c : parent.conflicts) {
      if (c.a != a && c.b != a) out.push_back(c);
    }
    conflicts_of(a, p, table, false, true, out);
    return out;
  }

  // ---- MDDs and conflict priority ---------------------------------------------------------------
  MddPtr mdd_of(int id, int a) {
    CtNode& node = *nodes_[static_cast<std::size_t>(id)];
    MddPtr& slot = node.mdds[static_cast<std::size_t>(a)];
    if (!slot) slot = build_mdd(a, constraints_of(id, a), node.plans[static_cast<std::size_t>(a)]->cost);
    return slot;
  }

  MddPtr build_mdd(int a, const std::vector<Constraint>& cons, int cost) {
    const int goal = goal_cell_[static_cast<std::size_t>(a)];
    const DistanceTable& h = h_[static_cast<std::size_t>(a)];
    FlatMap vc(8), ec(8);
    bool ins = false;
    int goal_last = -1;
    for (const Constraint& c : cons) {
      if (c.kind == Constraint::Vertex) {
        vc.get_or_insert(FlatMap::key(c.cell, c.time), 1, ins);
        if (c.cell == goal) goal_last = std::max(goal_last, c.time);
      } else {
        ec.get_or_insert(FlatMap::key(c.time, graph_.graph().arc(c.cell, c.cell2)), 1, ins);
      }
    }
    const auto legal = [&](int u, int v, int t1) {
      if (vc.find(FlatMap::key(v, t1)) != nullptr) return false;
      if (u != v && ec.size() > 0 && ec.find(FlatMap::key(t1, graph_.graph().arc(u, v))) != nullptr) return false;
      if (!in_.reserved.empty()) {
        if (reserved_.count_at(v, t1, -1) > 0) return false;
        if (u != v && reserved_.count_swap(u, v, t1, -1) > 0) return false;
      }
      return true;
    };
    std::vector<std::vector<int>> states(static_cast<std::size_t>(cost) + 1);
    states[0].push_back(start_state_[static_cast<std::size_t>(a)]);
    for (int t = 0; t < cost; ++t) {
      FlatMap seen(states[static_cast<std::size_t>(t)].size() * 4);
      for (int s : states[static_cast<std::size_t>(t)]) {
        const int u = model_.vertex(s);
        if (vanish_ && u == goal) continue;
        model_.for_each_successor(s, [&](int s2) {
          const int v = model_.vertex(s2);
          const int d = h.at(v);
          if (d >= DistanceTable::kUnreachable || t + 1 + d > cost) return;
          if (vanish_ && v == goal && t + 1 != cost) return;
          if (!legal(u, v, t + 1)) return;
          bool fresh = false;
          seen.get_or_insert(static_cast<std::uint64_t>(s2), 1, fresh);
          if (fresh) states[static_cast<std::size_t>(t) + 1].push_back(s2);
        });
      }
    }
    // Backwards: keep the states that lead to the goal at `cost`.
    std::vector<std::vector<int>> level_cells(static_cast<std::size_t>(cost) + 1);
    std::vector<int> keep;
    for (int s : states[static_cast<std::size_t>(cost)]) {
      if (model_.vertex(s) == goal && cost > goal_last) keep.push_back(s);
    }
    for (int t = cost; t >= 0; --t) {
      FlatMap cells(keep.size() * 2 + 2);
      for (int s : keep) {
        bool fresh = false;
        cells.get_or_insert(static_cast<std::uint64_t>(model_.vertex(s)), 1, fresh);
        if (fresh) level_cells[static_cast<std::size_t>(t)].push_back(model_.vertex(s));
      }
      if (t == 0) break;
      FlatMap next(keep.size() * 2 + 2);
      bool fresh = false;
      for (int s : keep) next.get_or_insert(static_cast<std::uint64_t>(s), 1, fresh);
      std::vector<int> prev;
      for (int s : states[static_cast<std::size_t>(t) - 1]) {
        const int u = model_.vertex(s);
        if (vanish_ && u == goal) continue;
        bool ok = false;
        model_.for_each_successor(s, [&](int s2) {
          if (!ok && next.find(static_cast<std::uint64_t>(s2)) != nullptr && legal(u, model_.vertex(s2), t)) ok = true;
        });
        if (ok) prev.push_back(s);
      }
      keep.swap(prev);
    }
    Mdd& mdd = mdd_pool_.emplace_back();
    for (const auto& level : level_cells) {
      mdd.first.push_back(static_cast<int>(mdd.cells.size()));
      mdd.cells.insert(mdd.cells.end(), level.begin(), level.end());
    }
    mdd.first.push_back(static_cast<int>(mdd.cells.size()));
    return &mdd;
  }

  // 2 = cardinal for this agent, 0 = not. `parked`: the agent already sits on its goal then.
  bool cardinal_for(int id, int agent, int cell_before, int cell, int t) {
    const CtNode& node = *nodes_[static_cast<std::size_t>(id)];
    const int cost = node.plans[static_cast<std::size_t>(agent)]->cost;
    if (t > cost) return !vanish_;  // parked on its goal (Stay): it must arrive later
    const MddPtr m = mdd_of(id, agent);
    if (m->width(t) != 1 || m->cell(t) != cell) return false;
    if (cell_before < 0) return true;
    return m->width(t - 1) == 1 && m->cell(t - 1) == cell_before;
  }

  int choose_conflict(int id) {
    const CtNode& node = *nodes_[static_cast<std::size_t>(id)];
    int best = 0;
    int best_rank = -1;
    int best_t = 0;
    for (int k = 0; k < static_cast<int>(node.conflicts.size()); ++k) {
      const HlConflict c = node.conflicts[static_cast<std::size_t>(k)];
      int rank = 0;
      if (prioritize_) {
        const bool ca = c.kind == 0 ? cardinal_for(id, c.a, -1, c.cell, c.t) : cardinal_for(id, c.a, c.cell, c.cell2, c.t);
        const bool cb = c.kind == 0 ? cardinal_for(id, c.b, -1, c.cell, c.t) : cardinal_for(id, c.b, c.cell2, c.cell, c.t);
        rank = static_cast<int>(ca) + static_cast<int>(cb);
      }
      if (rank > best_rank || (rank == best_rank && c.t < best_t)) {
        best = k;
        best_rank = rank;
        best_t = c.t;
        if (rank == 2 && prioritize_) break;
      }
    }
    return best;
  }

  // ---- expansion --------------------------------------------------------------------------------
  void expand(int id) {
    const int k = choose_conflict(id);
    const HlConflict c = nodes_[static_cast<std::size_t>(id)]->conflicts[static_cast<std::size_t>(k)];
    const PathTable table = table_of(*nodes_[static_cast<std::size_t>(id)]);
    std::vector<std::unique_ptr<CtNode>> children;
    for (int side = 0; side < 2; ++side) {
      const CtNode& node = *nodes_[static_cast<std::size_t>(id)];
      Constraint con;
      con.agent = side == 0 ? c.a : c.b;
      con.time = c.t;
      if (c.kind == 0) {
        con.kind = Constraint::Vertex;
        con.cell = con.cell2 = c.cell;
      } else {
        con.kind = Constraint::Edge;
        con.cell = side == 0 ? c.cell : c.cell2;
        con.cell2 = side == 0 ? c.cell2 : c.cell;
      }
      std::vector<Constraint> cons = constraints_of(id, con.agent);
      cons.push_back(con);
      PlanPtr plan = plan_agent(con.agent, cons, &table);
      if (stopped_) return;
      if (!plan) continue;
      auto child = std::make_unique<CtNode>();
      child->parent = id;
      child->added = {con};
      child->plans = node.plans;
      child->mdds = node.mdds;
      child->mdds[static_cast<std::size_t>(con.agent)] = nullptr;
      const PlanPtr& old = node.plans[static_cast<std::size_t>(con.agent)];
      if (plan->lower_bound < old->lower_bound) {
        // More constraints never lower the optimum: keep the parent's (tighter) bound.
        AgentPlan& tighter = plan_pool_.emplace_back(*plan);
        tighter.lower_bound = old->lower_bound;
        plan = &tighter;
      }
      child->plans[static_cast<std::size_t>(con.agent)] = plan;
      child->cost = node.cost - old->cost + plan->cost;
      child->lb = node.lb - old->lower_bound + plan->lower_bound;
      child->depth = node.depth + 1;
      child->conflicts = conflicts_after(node, con.agent, plan->cells, table);
      ++stats_.high_level_generated;
      // ECBS: within the global focal bound, so the adopted node stays eligible for FOCAL.
      const bool cheap_enough = w_ <= 1.0 ? child->cost == node.cost
                                          : static_cast<double>(child->cost) <= w_ * static_cast<double>(focal_lb_) + 1e-9;
      if (bypass_ && cheap_enough && child->conflicts.size() < node.conflicts.size()) {
        // Bypass: the parent takes the better path (valid under its own, weaker constraints) and
        // goes back to OPEN instead of splitting.
        std::unique_ptr<CtNode>& mine = nodes_[static_cast<std::size_t>(id)];
        mine->plans[static_cast<std::size_t>(con.agent)] = plan;
        mine->conflicts = std::move(child->conflicts);
        mine->cost = child->cost;
        if (w_ > 1.0) mine->mdds[static_cast<std::size_t>(con.agent)] = nullptr;
        reinsert(id);
        return;
      }
      children.push_back(std::move(child));
    }
    for (auto& ch : children) push(std::move(ch));
  }

  // ---- OPEN / FOCAL -------------------------------------------------------------------------------
  using Key = std::pair<long long, int>;
  using FocalKey = std::tuple<std::size_t, long long, int>;

  void push(std::unique_ptr<CtNode> node) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back(std::move(node));
    insert(id);
  }
  void reinsert(int id) { insert(id); }
  void insert(int id) {
    const CtNode& n = *nodes_[static_cast<std::size_t>(id)];
    open_lb_.insert({n.lb, id});
    open_cost_.insert({n.cost, id});
    if (focal_lb_ >= 0 && static_cast<double>(n.cost) <= w_ * static_cast<double>(focal_lb_) + 1e-9) {
      focal_.insert({n.conflicts.size(), n.cost, id});
    }
  }
  // The best node by the focal rule (CBS: lowest cost, then fewest conflicts); -1 if OPEN is empty.
  int pop() {
    if (open_lb_.empty()) return -1;
    const long long lb_min = open_lb_.begin()->first;
    if (focal_lb_ < 0 || lb_min > focal_lb_) {
      // The bound rose: every node whose cost is within w of it joins FOCAL.
      const double old_bound = focal_lb_ < 0 ? -1.0 : w_ * static_cast<double>(focal_lb_);
      const double new_bound = w_ * static_cast<double>(lb_min);
      for (auto it = open_cost_.begin(); it != open_cost_.end() && static_cast<double>(it->first) <= new_bound + 1e-9; ++it) {
        if (static_cast<double>(it->first) > old_bound + 1e-9) {
          const CtNode& n = *nodes_[static_cast<std::size_t>(it->second)];
          focal_.insert({n.conflicts.size(), n.cost, it->second});
        }
      }
      focal_lb_ = lb_min;
    }
    if (focal_.empty()) {
      // Cannot happen for consistent bounds (the lb-minimal node has cost >= lb... and is within w
      // of itself only if cost <= w lb); fall back to the lb-minimal node.
      const int id = open_lb_.begin()->second;
      erase(id);
      return id;
    }
    const int id = std::get<2>(*focal_.begin());
    erase(id);
    return id;
  }
  void erase(int id) {
    const CtNode& n = *nodes_[static_cast<std::size_t>(id)];
    open_lb_.erase({n.lb, id});
    open_cost_.erase({n.cost, id});
    focal_.erase({n.conflicts.size(), n.cost, id});
  }

  // ---- results ------------------------------------------------------------------------------------
  void note_best(int id) {
    const CtNode& n = *nodes_[static_cast<std::size_t>(id)];
    if (best_ < 0) {
      best_ = id;
      return;
    }
    const CtNode& b = *nodes_[static_cast<std::size_t>(best_)];
    if (n.conflicts.size() < b.conflicts.size() || (n.conflicts.size() == b.conflicts.size() && n.cost < b.cost)) best_ = id;
  }

  Result finish(Result& out) {
    int id = best_;
    if (out.status == Status::Timeout && timeout_plan_ == TimeoutPlan::LastExpanded && last_expanded_ >= 0) {
      id = last_expanded_;
    }
    if (id >= 0 && (out.status == Status::Solved || out.status == Status::Timeout)) {
      const CtNode& n = *nodes_[static_cast<std::size_t>(id)];
      for (const PlanPtr& p : n.plans) {
        Path path;
        for (int c : p->cells) path.push_back(graph_.cell(c));
        out.paths.push_back(std::move(path));
      }
    }
    out.stats = stats_;
    return out;
  }

  const Instance& in_;
  int n_;
  double w_;
  bool prioritize_;
  bool bypass_;
  TimeoutPlan timeout_plan_;
  const StopCondition& stop_;
  InstanceGraph graph_;
  AgentModel model_;
  bool vanish_;
  std::vector<CellPath> reserved_cells_;
  PathTable reserved_;
  std::unique_ptr<LowLevel> low_;
  std::vector<DistanceTable> h_;
  std::vector<int> goal_cell_;
  std::vector<int> start_state_;
  std::function<bool()> should_stop_;
  bool stopped_ = false;

  std::deque<AgentPlan> plan_pool_;
  std::deque<Mdd> mdd_pool_;
  std::vector<std::unique_ptr<CtNode>> nodes_;
  std::set<Key> open_lb_;
  std::set<Key> open_cost_;
  std::set<FocalKey> focal_;
  long long focal_lb_ = -1;
  int best_ = -1;
  int last_expanded_ = -1;
  SearchStats stats_;
};

}  // namespace

Result run_conflict_search(const Instance& in, double w, bool prioritize, bool bypass, TimeoutPlan timeout_plan,
                           const StopCondition& stop) {
  ConflictSearch search(in, w, prioritize, bypass, timeout_plan, stop);
  return search.run();
}

}  // namespace swarm::planner::mapf::detail
