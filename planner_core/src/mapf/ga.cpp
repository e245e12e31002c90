// The paper's direction-ordering GA (ga.hpp): chromosome, operators, two fitness stages.
#include <algorithm>
#include <cmath>

#include "solvers.hpp"
#include "swarm/planner/mapf/warehouse.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner::mapf::detail {
namespace {

// Direction genes as in the paper: 1 up (+y), 2 down, 3 right (+x), 4 left.
constexpr int kDx[5] = {0, 0, 0, 1, -1};
constexpr int kDy[5] = {0, 1, -1, 0, 0};

struct Layout {
  int robots = 0;
  std::vector<int> moves;     // per robot: a + b
  std::vector<int> dir_at;    // per robot: offset of its direction part in a chromosome
  std::vector<int> idle_at;   // per robot: offset of its idle part (moves + 1 genes)
  std::vector<int> start;     // start cell index
  std::vector<std::vector<std::uint8_t>> base_dirs;  // one shortest path's moves, per robot
  int length = 0;             // genes per chromosome
};

using Chromosome = std::vector<std::uint8_t>;

struct Score {
  int collisions = 0;
  int idle_steps = 0;
};

// Decodes chromosomes into timed paths (cell indices) and counts collisions.
class Evaluator {
 public:
  Evaluator(const OccupancyGrid& map, const Layout& layout) : map_(map), layout_(layout) {
    paths_.resize(static_cast<std::size_t>(layout.robots));
    head_now_.assign(map.size(), -1);
    head_prev_.assign(map.size(), -1);
    next_now_.assign(static_cast<std::size_t>(layout.robots), -1);
    next_prev_.assign(static_cast<std::size_t>(layout.robots), -1);
  }

  void decode(const Chromosome& c) {
    const int w = map_.width();
    for (int r = 0; r < layout_.robots; ++r) {
      std::vector<int>& p = paths_[static_cast<std::size_t>(r)];
      p.clear();
      int cell = layout_.start[static_cast<std::size_t>(r)];
      const auto idle = [&](int k) { return 2 * c[static_cast<std::size_t>(layout_.idle_at[static_cast<std::size_t>(r)] + k)]; };
      p.push_back(cell);
      if (layout_.moves[static_cast<std::size_t>(r)] == 0) continue;  // on its goal: it leaves at once
      for (int s = 0; s < idle(0); ++s) p.push_back(cell);
      for (int m = 0; m < layout_.moves[static_cast<std::size_t>(r)]; ++m) {
        const int d = c[static_cast<std::size_t>(layout_.dir_at[static_cast<std::size_t>(r)] + m)];
        const int step = kDx[d] + kDy[d] * w;
        cell += step;  // the passage middle
        p.push_back(cell);
        for (int s = 0; s < idle(m + 1); ++s) p.push_back(cell);
        cell += step;  // the next intersection
        p.push_back(cell);
      }
    }
  }

  // Collisions (pairs on one cell, pairs swapping, per time step; a robot leaves on arrival) and
  // idle steps of the decoded paths.
  Score score() {
    Score s;
    int horizon = 0;
    for (const auto& p : paths_) {
      horizon = std::max(horizon, static_cast<int>(p.size()));
      for (std::size_t t = 1; t < p.size(); ++t) s.idle_steps += p[t] == p[t - 1];
    }
    for (int t = 0; t < horizon; ++t) {
      for (int c : touched_now_) head_now_[static_cast<std::size_t>(c)] = -1;
      touched_now_.clear();
      for (int r = 0; r < layout_.robots; ++r) {
        const auto& p = paths_[static_cast<std::size_t>(r)];
        if (t >= static_cast<int>(p.size())) continue;
        const int c = p[static_cast<std::size_t>(t)];
        int& head = head_now_[static_cast<std::size_t>(c)];
        if (head == -1) touched_now_.push_back(c);
        for (int q = head; q != -1; q = next_now_[static_cast<std::size_t>(q)]) ++s.collisions;
        next_now_[static_cast<std::size_t>(r)] = head;
        head = r;
        if (t == 0) continue;
        const int u = p[static_cast<std::size_t>(t - 1)];
        if (u == c) continue;
        // Someone who was on c a step ago and is on u now (and has not arrived before now).
        for (int q = head_prev_[static_cast<std::size_t>(c)]; q != -1; q = next_prev_[static_cast<std::size_t>(q)]) {
          const auto& pq = paths_[static_cast<std::size_t>(q)];
          // Seen from both robots: count it from the lower index only.
          if (q > r && t < static_cast<int>(pq.size()) && pq[static_cast<std::size_t>(t)] == u) ++s.collisions;
        }
      }
      std::swap(head_now_, head_prev_);
      std::swap(next_now_, next_prev_);
      std::swap(touched_now_, touched_prev_);
    }
    for (int c : touched_now_) head_now_[static_cast<std::size_t>(c)] = -1;  // clean for the next call
    for (int c : touched_prev_) head_prev_[static_cast<std::size_t>(c)] = -1;
    touched_now_.clear();
    touched_prev_.clear();
    return s;
  }

  const std::vector<std::vector<int>>& paths() const { return paths_; }

 private:
  const OccupancyGrid& map_;
  const Layout& layout_;
  std::vector<std::vector<int>> paths_;
  std::vector<int> head_now_, head_prev_, next_now_, next_prev_, touched_now_, touched_prev_;
};

}  // namespace

namespace {

// Roulette-wheel selection: index drawn with probability proportional to weight.
int roulette(const std::vector<double>& cumulative, Rng& rng) {
  const double x = rng.uniform01() * cumulative.back();
  const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), x);
  return std::min(static_cast<int>(it - cumulative.begin()), static_cast<int>(cumulative.size()) - 1);
}

class Ga {
 public:
  Ga(const Instance& in, const GaConfig& cfg, const StopCondition& stop)
      : in_(in), cfg_(cfg), stop_(stop), rng_(mix_seed(cfg.seed, 0x6761ULL)) {
    layout_.robots = in.agents();
    for (int r = 0; r < in.agents(); ++r) {
      const Cell s = in.starts[static_cast<std::size_t>(r)];
      const Cell g = in.goals[static_cast<std::size_t>(r)];
      const int a = (g.x - s.x) / 2;  // intersections apart, columns
      const int b = (g.y - s.y) / 2;  // rows
      std::vector<std::uint8_t> dirs;
      for (int k = 0; k < std::abs(a); ++k) dirs.push_back(a > 0 ? 3 : 4);
      for (int k = 0; k < std::abs(b); ++k) dirs.push_back(b > 0 ? 1 : 2);
      layout_.moves.push_back(static_cast<int>(dirs.size()));
      layout_.dir_at.push_back(layout_.length);
      layout_.length += static_cast<int>(dirs.size());
      layout_.idle_at.push_back(layout_.length);
      layout_.length += static_cast<int>(dirs.size()) + 1;
      layout_.start.push_back(in.map.index(s));
      layout_.base_dirs.push_back(std::move(dirs));
    }
  }

  Result run(bool two_stage) {
    Result out;
    Evaluator eval(in_.map, layout_);
    std::vector<Chromosome> pop;
    for (int k = 0; k < std::max(2, cfg_.population); ++k) pop.push_back(random_chromosome());
    const int g1 = std::max(0, cfg_.stage1_generations);
    const int g2 = std::max(0, cfg_.stage2_generations);
    std::vector<Score> scores(pop.size());
    std::vector<double> fitness(pop.size());
    bool stopped = false;
    const auto evaluate = [&](bool stage1) {
      for (std::size_t k = 0; k < pop.size(); ++k) {
        eval.decode(pop[k]);
        scores[k] = eval.score();
        fitness[k] = stage1 ? scores[k].collisions : cfg_.alpha * scores[k].collisions + cfg_.beta * scores[k].idle_steps;
      }
    };
    const int total = g1 + g2;
    for (int gen = 0; gen < total; ++gen) {
      const bool stage1 = two_stage && gen < g1;
      evaluate(stage1);
      ++out.stats.high_level_expanded;
      if (stop_.reached()) {
        stopped = true;
        break;
      }
      if (cfg_.stop_when_perfect && !stage1 && best_index(fitness) >= 0 &&
          scores[static_cast<std::size_t>(best_index(fitness))].collisions == 0 &&
          scores[static_cast<std::size_t>(best_index(fitness))].idle_steps == 0) {
        break;
      }
      pop = next_generation(pop, fitness);
    }
    evaluate(false);  // the final population, by the final (stage-2) fitness
    const int best = best_index(fitness);
    eval.decode(pop[static_cast<std::size_t>(best)]);
    for (const auto& p : eval.paths()) {
      Path path;
      for (int c : p) path.push_back(in_.map.cell_of(c));
      out.paths.push_back(std::move(path));
    }
    out.stats.low_level_expanded = out.stats.high_level_expanded * static_cast<long long>(pop.size());
    if (stopped) {
      out.status = scores[static_cast<std::size_t>(best)].collisions == 0 ? Status::Solved : Status::Timeout;
    } else if (scores[static_cast<std::size_t>(best)].collisions == 0) {
      out.status = Status::Solved;
    } else {
      out.status = Status::Failed;
      out.message = "the GA's best plan keeps " + std::to_string(scores[static_cast<std::size_t>(best)].collisions) +
                    " collisions after its generations";
    }
    return out;
  }

 private:
  static int best_index(const std::vector<double>& fitness) {
    return static_cast<int>(std::min_element(fitness.begin(), fitness.end()) - fitness.begin());
  }

  Chromosome random_chromosome() {
    Chromosome c(static_cast<std::size_t>(layout_.length), 0);
    for (int r = 0; r < layout_.robots; ++r) {
      std::vector<std::uint8_t> dirs = layout_.base_dirs[static_cast<std::size_t>(r)];
      for (std::size_t i = dirs.size(); i > 1; --i) std::swap(dirs[i - 1], dirs[rng_.below(i)]);
      std::copy(dirs.begin(), dirs.end(), c.begin() + layout_.dir_at[static_cast<std::size_t>(r)]);
      for (int k = 0; k <= layout_.moves[static_cast<std::size_t>(r)]; ++k) {
        c[static_cast<std::size_t>(layout_.idle_at[static_cast<std::size_t>(r)] + k)] =
            static_cast<std::uint8_t>(rng_.uniform_int(0, std::max(0, cfg_.max_initial_idle)));
      }
    }
    return c;
  }

  std::vector<Chromosome> next_generation(const std::vector<Chromosome>& pop, const std::vector<double>& fitness) {
    const std::size_t n = pop.size();
    std::vector<Chromosome> next;
    next.reserve(n);
    // Elitism: the best chromosomes pass unchanged (ties: the lower index).
    std::vector<int> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<int>(k);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return fitness[static_cast<std::size_t>(a)] < fitness[static_cast<std::size_t>(b)]; });
    for (int k = 0; k < std::min(cfg_.elite, static_cast<int>(n)); ++k) next.push_back(pop[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])]);
    std::vector<double> cumulative(n);
    double sum = 0;
    for (std::size_t k = 0; k < n; ++k) cumulative[k] = sum += 1.0 / (1.0 + fitness[k]);
    while (next.size() < n) {
      const Chromosome& p1 = pop[static_cast<std::size_t>(roulette(cumulative, rng_))];
      const Chromosome& p2 = pop[static_cast<std::size_t>(roulette(cumulative, rng_))];
      Chromosome c1 = p1, c2 = p2;
      if (rng_.bernoulli(cfg_.crossover_rate)) crossover(p1, p2, c1, c2);
      for (Chromosome* c : {&c1, &c2}) {
        if (next.size() >= n) break;
        if (rng_.bernoulli(cfg_.mutation_rate)) mutate(*c);
        next.push_back(std::move(*c));
      }
    }
    return next;
  }

  // Per robot: which parent gives the direction part, and (independently) the idle part.
  void crossover(const Chromosome& p1, const Chromosome& p2, Chromosome& c1, Chromosome& c2) {
    for (int r = 0; r < layout_.robots; ++r) {
      const int m = layout_.moves[static_cast<std::size_t>(r)];
      for (const auto& [at, len] : {std::pair{layout_.dir_at[static_cast<std::size_t>(r)], m},
                                    std::pair{layout_.idle_at[static_cast<std::size_t>(r)], m + 1}}) {
        const bool from_second = rng_.bernoulli(0.5);
        const Chromosome& a = from_second ? p2 : p1;
        const Chromosome& b = from_second ? p1 : p2;
        std::copy(a.begin() + at, a.begin() + at + len, c1.begin() + at);
        std::copy(b.begin() + at, b.begin() + at + len, c2.begin() + at);
      }
    }
  }

  // Per robot: swap two direction genes; one idle gene +1 or -1 (never below 0).
  void mutate(Chromosome& c) {
    for (int r = 0; r < layout_.robots; ++r) {
      const int m = layout_.moves[static_cast<std::size_t>(r)];
      if (m >= 2) {
        const int i = static_cast<int>(rng_.below(static_cast<std::uint64_t>(m)));
        int j = static_cast<int>(rng_.below(static_cast<std::uint64_t>(m - 1)));
        if (j >= i) ++j;
        std::swap(c[static_cast<std::size_t>(layout_.dir_at[static_cast<std::size_t>(r)] + i)],
                  c[static_cast<std::size_t>(layout_.dir_at[static_cast<std::size_t>(r)] + j)]);
      }
      std::uint8_t& g = c[static_cast<std::size_t>(layout_.idle_at[static_cast<std::size_t>(r)] +
                                                   static_cast<int>(rng_.below(static_cast<std::uint64_t>(m + 1))))];
      if (rng_.bernoulli(0.5)) {
        if (g < 255) ++g;
      } else if (g > 0) {
        --g;
      }
    }
  }

  const Instance& in_;
  GaConfig cfg_;
  const StopCondition& stop_;
  Rng rng_;
  Layout layout_;
};

}  // namespace

Result run_ga(const Instance& in, const GaConfig& config, bool two_stage, const StopCondition& stop) {
  if (!in.reserved.empty()) {
    Result r;
    r.status = Status::Unsupported;
    r.message = "the GA does not take reserved paths";
    return r;
  }
  if (in.graph) {
    Result r;
    r.status = Status::Unsupported;
    r.message = "the GA runs on the paper's warehouse world only: a graph instance has no directions to order "
                "(use cbs, ecbs or lacam)";
    return r;
  }
  if (in.rules != Rules::paper_warehouse() || !warehouse_size_of(in.map)) {
    Result r;
    r.status = Status::Unsupported;
    r.message = "the GA runs on the paper's warehouse world only (warehouse-RxC with the paper's rules)";
    return r;
  }
  for (int a = 0; a < in.agents(); ++a) {
    const Cell s = in.starts[static_cast<std::size_t>(a)];
    const Cell g = in.goals[static_cast<std::size_t>(a)];
    if (s.x % 2 == 0 || s.y % 2 == 0 || g.x % 2 == 0 || g.y % 2 == 0) {
      Result r;
      r.status = Status::Unsupported;
      r.message = "agent " + std::to_string(a) + ": the GA needs starts and goals on intersections";
      return r;
    }
  }
  Ga ga(in, config, stop);
  return ga.run(two_stage);
}

}  // namespace swarm::planner::mapf::detail
