// LaCAM* with PIBT (lacam.hpp). Search over configurations (one state per agent); successors
// generated lazily by PIBT under a growing tree of low-level constraints.
#include <algorithm>
#include <deque>
#include <memory>
#include <numeric>
#include <queue>
#include <stack>
#include <unordered_map>
#include <unordered_set>

#include "agent_model.hpp"
#include "swarm/planner/mapf/pibt_swap.hpp"
#include "solvers.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner::mapf::detail {
namespace {

constexpr int kGone = -1;       // a Vanish agent after its arrival
constexpr int kUndecided = -2;  // PIBT has not chosen this agent's next state yet

using Config = std::vector<int>;

struct ConfigHash {
  std::size_t operator()(const Config& c) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (int v : c) {
      h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};

// Exact BFS distances to one goal, computed lazily: the BFS runs only as far as the queries need.
class LazyDistance {
 public:
  LazyDistance(const AgentModel& model, std::size_t cells, int goal) : model_(&model) {
    dist_.assign(cells, DistanceTable::kUnreachable);
    dist_[static_cast<std::size_t>(goal)] = 0;
    queue_.push_back(goal);
  }
  int operator()(int cell) {
    int& d = dist_[static_cast<std::size_t>(cell)];
    while (d == DistanceTable::kUnreachable && head_ < queue_.size()) {
      const int c = queue_[head_++];
      const int dc = dist_[static_cast<std::size_t>(c)] + 1;
      for (const int n : model_->neighbours(c)) {
        if (dist_[static_cast<std::size_t>(n)] != DistanceTable::kUnreachable) continue;
        dist_[static_cast<std::size_t>(n)] = dc;
        queue_.push_back(n);
      }
    }
    return d;
  }

 private:
  const AgentModel* model_;
  std::vector<int> dist_;
  std::vector<int> queue_;
  std::size_t head_ = 0;
};

struct LowNode {  // "agent who[k] goes to state where[k]" for k < depth
  std::vector<int> who;
  std::vector<int> where;
};

struct HighNode {
  Config config;
  HighNode* parent = nullptr;
  std::unordered_set<HighNode*> neighbours;  // LaCAM*: every node reached from here
  long long g = 0;
  long long h = 0;
  long long f = 0;
  std::vector<float> priority;
  std::vector<int> order;
  std::queue<LowNode> tree;
};

class Lacam {
 public:
  Lacam(const Instance& in, const LacamConfig& cfg, const StopCondition& stop)
      : in_(in),
        cfg_(cfg),
        stop_(stop),
        graph_(in),
        model_(in, graph_),
        n_(in.agents()),
        vanish_(in.rules.at_goal == GoalRule::Vanish),
        paper_(in.rules.waits == WaitRule::PassageMiddles),
        rng_(mix_seed(cfg.seed, 0x6c6163616dULL)) {
    const auto cells = static_cast<std::size_t>(graph_.vertices());
    for (int a = 0; a < n_; ++a) {
      goal_.push_back(graph_.vertex(in.goals[static_cast<std::size_t>(a)]));
      dist_.emplace_back(model_, cells, goal_.back());
    }
    occupied_now_.assign(cells, -1);
    occupied_next_.assign(cells, -1);
    next_.assign(static_cast<std::size_t>(n_), kUndecided);
    tie_.assign(cells, 0.0f);
  }

  Result run() {
    Result out;
    Config start(static_cast<std::size_t>(n_));
    for (int a = 0; a < n_; ++a) start[static_cast<std::size_t>(a)] = model_.start_state(graph_.vertex(in_.starts[static_cast<std::size_t>(a)]));
    HighNode* root = make_node(start, nullptr);
    std::stack<HighNode*> open;
    open.push(root);
    HighNode* goal = nullptr;
    long long loops = 0;
    while (!open.empty()) {
      if ((++loops & 63) == 0 && stop_.reached()) break;
      HighNode* h = open.top();
      if (h->tree.empty()) {
        open.pop();
        continue;
      }
      if (goal != nullptr && h->f >= goal->f) {
        open.pop();
        continue;
      }
      if (goal == nullptr && is_goal(h->config)) {
        goal = h;
        if (!cfg_.refine) break;
        continue;
      }
      LowNode low = std::move(h->tree.front());
      h->tree.pop();
      widen(*h, low);
      ++out.stats.low_level_expanded;
      if (!next_config(*h, low)) continue;
      Config c(static_cast<std::size_t>(n_));
      for (int a = 0; a < n_; ++a) c[static_cast<std::size_t>(a)] = next_[static_cast<std::size_t>(a)];
      auto it = explored_.find(c);
      if (it != explored_.end()) {
        HighNode* known = it->second;
        if (cfg_.refine) rewrite(h, known, goal, open);
        HighNode* again = rng_.bernoulli(cfg_.restart_rate) ? root : known;
        if (goal == nullptr || again->f < goal->f) open.push(again);
      } else {
        HighNode* fresh = make_node(c, h);
        ++out.stats.high_level_generated;
        if (goal == nullptr || fresh->f < goal->f) open.push(fresh);
      }
    }
    out.stats.high_level_expanded = loops;
    if (goal != nullptr) {
      out.status = Status::Solved;
      out.paths = paths_to(goal);
    } else if (open.empty()) {
      out.status = Status::Infeasible;
      out.message = "LaCAM explored every reachable configuration: no plan exists";
    } else {
      // The best plan found: the way to the configuration nearest the goals (least summed
      // distance), then every agent straight on to its goal, ignoring the others; the caller
      // counts the conflicts that leaves (solver.cpp), as for a timed-out CBS.
      out.status = Status::Timeout;
      out.paths = paths_to(nearest_);
      finish_alone(nearest_->config, out.paths);
      int arrived = 0;
      for (int a = 0; a < n_; ++a) arrived += at_goal(a, nearest_->config[static_cast<std::size_t>(a)]) ? 1 : 0;
      out.message = "no plan within the limit; the best found has " + std::to_string(arrived) + " of " +
                    std::to_string(n_) + " agents on their goals, the others driven straight there";
    }
    return out;
  }

 private:
  HighNode* make_node(const Config& c, HighNode* parent) {
    nodes_.push_back(std::make_unique<HighNode>());
    HighNode* h = nodes_.back().get();
    h->config = c;
    h->parent = parent;
    h->tree.push(LowNode{});
    if (parent != nullptr) {
      if (cfg_.refine) parent->neighbours.insert(h);
      h->g = parent->g + edge_cost(parent->config, c);
    }
    h->h = heuristic(c);
    h->f = h->g + h->h;
    if (nearest_ == nullptr || h->h < nearest_->h) nearest_ = h;
    h->priority.resize(static_cast<std::size_t>(n_));
    for (int a = 0; a < n_; ++a) {
      const std::size_t i = static_cast<std::size_t>(a);
      const bool arrived = at_goal(a, c[i]);
      if (parent == nullptr) {
        h->priority[i] = arrived ? 0.0f : static_cast<float>(distance(a, c[i])) / static_cast<float>(std::max(1, n_));
      } else if (!arrived) {
        h->priority[i] = parent->priority[i] + 1.0f;  // waiting raises an agent's priority (PIBT)
      } else {
        h->priority[i] = parent->priority[i] - static_cast<float>(static_cast<int>(parent->priority[i]));
      }
    }
    h->order.resize(static_cast<std::size_t>(n_));
    std::iota(h->order.begin(), h->order.end(), 0);
    std::stable_sort(h->order.begin(), h->order.end(), [&](int a, int b) {
      return h->priority[static_cast<std::size_t>(a)] > h->priority[static_cast<std::size_t>(b)];
    });
    explored_.emplace(h->config, h);
    return h;
  }

  bool at_goal(int a, int state) const {
    return state == kGone || model_.vertex(state) == goal_[static_cast<std::size_t>(a)];
  }
  bool is_goal(const Config& c) const {
    for (int a = 0; a < n_; ++a) {
      if (!at_goal(a, c[static_cast<std::size_t>(a)])) return false;
    }
    return true;
  }
  int distance(int a, int state) {
    return state == kGone ? 0 : dist_[static_cast<std::size_t>(a)](model_.vertex(state));
  }
  long long heuristic(const Config& c) {
    long long s = 0;
    for (int a = 0; a < n_; ++a) s += distance(a, c[static_cast<std::size_t>(a)]);
    return s;
  }
  // Sum of loss: one per agent not resting on its goal across the step.
  long long edge_cost(const Config& from, const Config& to) const {
    long long cost = 0;
    for (int a = 0; a < n_; ++a) {
      cost += !(at_goal(a, from[static_cast<std::size_t>(a)]) && at_goal(a, to[static_cast<std::size_t>(a)]));
    }
    return cost;
  }

  // The states an agent may take next (the wait first when allowed); a Vanish agent on its goal
  // leaves.
  void successors(int a, int state, std::vector<int>& out) const {
    out.clear();
    if (state == kGone || (vanish_ && at_goal(a, state))) {
      out.push_back(kGone);
      return;
    }
    model_.for_each_successor(state, [&](int s) { out.push_back(s); });
  }

  void widen(HighNode& h, const LowNode& low) {
    const std::size_t depth = low.who.size();
    if (depth >= static_cast<std::size_t>(n_)) return;
    const int a = h.order[depth];
    std::vector<int> succ;
    successors(a, h.config[static_cast<std::size_t>(a)], succ);
    for (std::size_t i = succ.size(); i > 1; --i) std::swap(succ[i - 1], succ[rng_.below(i)]);
    for (int s : succ) {
      LowNode child{low.who, low.where};
      child.who.push_back(a);
      child.where.push_back(s);
      h.tree.push(std::move(child));
    }
  }

  // ---- configuration generator: constraints first, then PIBT in priority order ------------------
  bool next_config(const HighNode& h, const LowNode& low) {
    for (int c : touched_) {
      occupied_now_[static_cast<std::size_t>(c)] = -1;
      occupied_next_[static_cast<std::size_t>(c)] = -1;
    }
    touched_.clear();
    const Config& cur = h.config;
    for (int a = 0; a < n_; ++a) {
      const int s = cur[static_cast<std::size_t>(a)];
      next_[static_cast<std::size_t>(a)] = kUndecided;
      if (s == kGone) {
        next_[static_cast<std::size_t>(a)] = kGone;
        continue;
      }
      occupied_now_[static_cast<std::size_t>(model_.vertex(s))] = a;
      touched_.push_back(model_.vertex(s));
      if (vanish_ && at_goal(a, s)) next_[static_cast<std::size_t>(a)] = kGone;
    }
    illegal_ = false;
    for (std::size_t k = 0; k < low.who.size(); ++k) {
      const int a = low.who[k];
      const int s = low.where[k];
      if (s == kGone) continue;
      const int v = model_.vertex(s);
      if (occupied_next_[static_cast<std::size_t>(v)] != -1) return false;
      const int u = model_.vertex(cur[static_cast<std::size_t>(a)]);
      const int there = occupied_now_[static_cast<std::size_t>(v)];
      if (there != -1 && there != a && next_[static_cast<std::size_t>(there)] >= 0 &&
          model_.vertex(next_[static_cast<std::size_t>(there)]) == u) {
        return false;  // swap
      }
      reserve(a, s);
    }
    for (int a : h.order) {
      if (next_[static_cast<std::size_t>(a)] == kUndecided && !pibt(a, cur)) return false;
      if (illegal_) return false;
    }
    return true;
  }

  void reserve(int a, int s) {
    next_[static_cast<std::size_t>(a)] = s;
    const int v = model_.vertex(s);
    occupied_next_[static_cast<std::size_t>(v)] = a;
    touched_.push_back(v);
  }

  int cell_now(int a, const Config& cur) const { return model_.vertex(cur[static_cast<std::size_t>(a)]); }

  bool pibt(int a, const Config& cur) {
    const int s_now = cur[static_cast<std::size_t>(a)];
    const int u = model_.vertex(s_now);
    std::vector<int> cand;
    model_.for_each_successor(s_now, [&](int s) { cand.push_back(s); });
    for (int s : cand) tie_[static_cast<std::size_t>(model_.vertex(s))] = static_cast<float>(rng_.uniform01());
    std::sort(cand.begin(), cand.end(), [&](int x, int y) {
      return static_cast<float>(distance(a, x)) + tie_[static_cast<std::size_t>(model_.vertex(x))] <
             static_cast<float>(distance(a, y)) + tie_[static_cast<std::size_t>(model_.vertex(y))];
    });
    int swapper = -1;
    if (cfg_.swap && !paper_) {
      swapper = swap_partner(a, cand, cur);
      if (swapper != -1) std::reverse(cand.begin(), cand.end());
    }
    for (std::size_t k = 0; k < cand.size(); ++k) {
      const int s = cand[k];
      const int v = model_.vertex(s);
      if (occupied_next_[static_cast<std::size_t>(v)] != -1) continue;
      const int other = occupied_now_[static_cast<std::size_t>(v)];
      if (other != -1 && other != a && next_[static_cast<std::size_t>(other)] >= 0 &&
          model_.vertex(next_[static_cast<std::size_t>(other)]) == u) {
        continue;  // would swap with `other`
      }
      reserve(a, s);
      if (other != -1 && other != a && next_[static_cast<std::size_t>(other)] == kUndecided && !pibt(other, cur)) {
        continue;
      }
      if (k == 0 && swapper != -1 && next_[static_cast<std::size_t>(swapper)] == kUndecided &&
          occupied_next_[static_cast<std::size_t>(u)] == -1) {
        reserve(swapper, cur_state_at(u, cur, swapper));
      }
      return true;
    }
    // No free cell: stay (if the rules allow it here).
    const int wait = wait_state(s_now);
    if (wait < 0) illegal_ = true;
    reserve(a, wait < 0 ? s_now : wait);
    return false;
  }

  // The swap partner moves onto `cell` (the pusher's cell): under standard rules state == cell.
  int cur_state_at(int cell, const Config&, int) const { return cell; }

  int wait_state(int s) const {
    int w = -1;
    model_.for_each_successor(s, [&](int s2) {
      if (w < 0 && model_.vertex(s2) == model_.vertex(s)) w = s2;
    });
    return w;
  }

  // ---- PIBT's swap technique (LaCAM*, standard rules) -------------------------------------------
  int degree_excluding(int cell, int excluded, int& other) const {
    int n = 0;
    for (const int nb : model_.neighbours(cell)) {
      if (nb == excluded) continue;
      const int who = occupied_now_[static_cast<std::size_t>(nb)];
      const bool parked_dead_end = who != -1 && goal_[static_cast<std::size_t>(who)] == nb && model_.graph().degree(nb) == 1;
      if (parked_dead_end) continue;
      ++n;
      other = nb;
    }
    return n;
  }
  bool swap_required(int pusher, int puller, int v_pusher, int v_puller) {
    return mapf::swap_required(
        pusher, puller, v_pusher, v_puller,
        [this](int cell, int excluded, int& other) { return degree_excluding(cell, excluded, other); },
        [this](int agent, int v) { return dist_[static_cast<std::size_t>(agent)](v); });  // the tables grow as asked
  }
  bool swap_possible(int v_pusher, int v_puller) const {
    return mapf::swap_possible(v_pusher, v_puller, [this](int cell, int excluded, int& other) {
      return degree_excluding(cell, excluded, other);
    });
  }
  int swap_partner(int a, const std::vector<int>& cand, const Config& cur) {
    const int u = cell_now(a, cur);
    const int best = model_.vertex(cand.front());
    if (best == u) return -1;
    const int b = occupied_now_[static_cast<std::size_t>(best)];
    if (b != -1 && next_[static_cast<std::size_t>(b)] == kUndecided && swap_required(a, b, u, best) && swap_possible(best, u)) {
      return b;
    }
    for (const int nb : model_.neighbours(u)) {  // clearing: someone beside us must pass first
      const int k = occupied_now_[static_cast<std::size_t>(nb)];
      if (k == -1 || nb == best) continue;
      if (swap_required(k, a, u, best) && swap_possible(best, u)) return k;
    }
    return -1;
  }

  // ---- LaCAM*: rewiring after a known configuration is reached again -----------------------------
  void rewrite(HighNode* from, HighNode* to, HighNode* goal, std::stack<HighNode*>& open) {
    from->neighbours.insert(to);
    std::deque<HighNode*> q{from};
    while (!q.empty()) {
      HighNode* n = q.front();
      q.pop_front();
      for (HighNode* m : n->neighbours) {
        const long long g = n->g + edge_cost(n->config, m->config);
        if (g < m->g) {
          m->g = g;
          m->f = m->g + m->h;
          m->parent = n;
          q.push_back(m);
          if (goal != nullptr && m->f < goal->f) open.push(m);
        }
      }
    }
  }

  std::vector<Path> paths_to(HighNode* goal) const {
    std::vector<const Config*> seq;
    for (HighNode* h = goal; h != nullptr; h = h->parent) seq.push_back(&h->config);
    std::reverse(seq.begin(), seq.end());
    std::vector<Path> paths(static_cast<std::size_t>(n_));
    for (int a = 0; a < n_; ++a) {
      Path& p = paths[static_cast<std::size_t>(a)];
      for (const Config* c : seq) {
        const int s = (*c)[static_cast<std::size_t>(a)];
        if (s == kGone) break;
        p.push_back(graph_.cell(model_.vertex(s)));
        if (vanish_ && model_.vertex(s) == goal_[static_cast<std::size_t>(a)]) break;
      }
      if (!vanish_) {  // drop the trailing waits on the goal
        while (p.size() >= 2 && p[p.size() - 2] == p.back()) p.pop_back();
      }
    }
    return paths;
  }

  // Extends each path from `config` along a shortest way (in the agent model's own states, so the
  // paper's stops are finished as its rules say) to its agent's goal, ignoring the others.
  void finish_alone(const Config& config, std::vector<Path>& paths) {
    std::vector<int> next;
    for (int a = 0; a < n_; ++a) {
      const int from = config[static_cast<std::size_t>(a)];
      if (from == kGone || at_goal(a, from)) continue;
      // Breadth-first over states; the first state on the goal cell ends the search.
      std::unordered_map<int, int> parent{{from, from}};
      std::deque<int> queue{from};
      int reached = -1;
      while (!queue.empty() && reached < 0) {
        const int s = queue.front();
        queue.pop_front();
        successors(a, s, next);
        for (int n : next) {
          if (n == kGone || !parent.emplace(n, s).second) continue;
          if (at_goal(a, n)) {
            reached = n;
            break;
          }
          queue.push_back(n);
        }
      }
      std::vector<int> way;
      for (int s = reached; s >= 0 && s != from; s = parent.at(s)) way.push_back(s);
      Path& p = paths[static_cast<std::size_t>(a)];
      for (auto it = way.rbegin(); it != way.rend(); ++it) p.push_back(graph_.cell(model_.vertex(*it)));
    }
  }

  HighNode* nearest_ = nullptr;  // the generated configuration with the least summed distance
  const Instance& in_;
  LacamConfig cfg_;
  const StopCondition& stop_;
  InstanceGraph graph_;
  AgentModel model_;
  int n_;
  bool vanish_;
  bool paper_;
  Rng rng_;
  std::vector<int> goal_;
  std::vector<LazyDistance> dist_;
  std::vector<int> occupied_now_, occupied_next_, next_, touched_;
  std::vector<float> tie_;
  bool illegal_ = false;
  std::vector<std::unique_ptr<HighNode>> nodes_;
  std::unordered_map<Config, HighNode*, ConfigHash> explored_;
};

}  // namespace

Result run_lacam(const Instance& in, const LacamConfig& config, const StopCondition& stop) {
  if (!in.reserved.empty()) {
    Result r;
    r.status = Status::Unsupported;
    r.message = "LaCAM searches configurations, not time: it does not take reserved paths (use cbs or ecbs)";
    return r;
  }
  Lacam lacam(in, config, stop);
  return lacam.run();
}

}  // namespace swarm::planner::mapf::detail
