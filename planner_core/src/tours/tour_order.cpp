#include "swarm/planner/tours/tour_order.hpp"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <limits>
#include <utility>

#include "swarm/planner/grid/astar.hpp"
#include "swarm/planner/tours/turns.hpp"

namespace swarm::planner {

std::strong_ordering operator<=>(const GridLength& a, const GridLength& b) {
  // a - b = x + y sqrt 2 with x, y integers: its sign without floating point.
  const std::int64_t x = a.straight - b.straight;
  const std::int64_t y = a.diagonal - b.diagonal;
  if (x >= 0 && y >= 0) return (x == 0 && y == 0) ? std::strong_ordering::equal : std::strong_ordering::greater;
  if (x <= 0 && y <= 0) return std::strong_ordering::less;
  // Opposite signs: compare x^2 with 2 y^2 (never equal: sqrt 2 is irrational, x, y != 0).
  const std::int64_t x2 = x * x;
  const std::int64_t y2 = 2 * y * y;
  if (x > 0) return x2 > y2 ? std::strong_ordering::greater : std::strong_ordering::less;
  return y2 > x2 ? std::strong_ordering::greater : std::strong_ordering::less;
}

GridLength grid_length(const std::vector<Cell>& path) {
  GridLength len;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const int dx = std::abs(path[i].x - path[i - 1].x);
    const int dy = std::abs(path[i].y - path[i - 1].y);
    assert(dx <= 1 && dy <= 1 && "grid_length: not 8-neighbours");
    if (dx + dy == 1) ++len.straight;
    if (dx + dy == 2) ++len.diagonal;
  }
  return len;
}

namespace {

Leg make_leg(std::vector<Cell> cells, bool through_objects) {
  Leg leg;
  leg.length = grid_length(cells);
  leg.inner_turns = rotation_eighths(cells, std::nullopt, &leg.last_heading);
  for (std::size_t i = 1; i < cells.size() && !leg.first_heading; ++i) {
    leg.first_heading = step_heading(cells[i - 1], cells[i]);
  }
  leg.through_objects = through_objects;
  leg.cells = std::move(cells);
  return leg;
}

}  // namespace

LegTable::LegTable(const OccupancyGrid& map, const OccupancyGrid* fallback, std::vector<Cell> stops)
    : stops_(std::move(stops)) {
  assert(stops_.size() >= 2);
  const int s = static_cast<int>(stops_.size());
  const int n = s - 2;
  legs_.resize(static_cast<std::size_t>(s) * static_cast<std::size_t>(s));
  const AStarOptions options{.unknown_is_free = false, .motion = MotionModel::eight()};
  for (int from = 0; from <= n; ++from) {
    for (int to = 1; to <= n + 1; ++to) {
      if (from == to || (from == 0 && to == n + 1 && n > 0)) continue;
      const Cell a = stops_[static_cast<std::size_t>(from)];
      const Cell b = stops_[static_cast<std::size_t>(to)];
      std::optional<std::vector<Cell>> path = astar(map, a, b, options);
      bool through = false;
      if (!path && fallback != nullptr) {
        path = astar(*fallback, a, b, options);
        through = path.has_value();
      }
      Leg& leg = legs_[static_cast<std::size_t>(from * s + to)];
      if (path) {
        leg = make_leg(std::move(*path), through);
      } else {
        complete_ = false;
      }
    }
  }
}

const Leg& LegTable::leg(int from, int to) const {
  const int s = static_cast<int>(stops_.size());
  assert(from >= 0 && from < s - 1 && to >= 1 && to < s && from != to);
  return legs_[static_cast<std::size_t>(from * s + to)];
}

bool better(const OrderCost& a, const OrderCost& b, OrderObjective objective) {
  const auto c = a.length <=> b.length;
  if (c != 0) return c < 0;
  return objective == OrderObjective::kDistanceThenRotation && a.rotation < b.rotation;
}

namespace {

// Walks legs, accumulating length and rotation; the heading carries across legs that do not move.
struct Walker {
  const LegTable& legs;
  OrderCost cost;
  int heading;
  int at = 0;

  void to(int stop) {
    const Leg& l = legs.leg(at, stop);
    assert(l.reachable());
    cost.length += l.length;
    if (l.first_heading) {
      cost.rotation += turn_eighths(heading, *l.first_heading) + l.inner_turns;
      heading = *l.last_heading;
    }
    at = stop;
  }
};

std::vector<int> free_objects(int n, const std::vector<int>& prefix) {
  std::vector<char> fixed(static_cast<std::size_t>(n) + 2, 0);
  for (int p : prefix) {
    assert(p >= 1 && p <= n && !fixed[static_cast<std::size_t>(p)]);
    fixed[static_cast<std::size_t>(p)] = 1;
  }
  std::vector<int> out;
  for (int i = 1; i <= n; ++i) {
    if (!fixed[static_cast<std::size_t>(i)]) out.push_back(i);
  }
  return out;
}

std::vector<int> joined(const std::vector<int>& prefix, const std::vector<int>& rest) {
  std::vector<int> all = prefix;
  all.insert(all.end(), rest.begin(), rest.end());
  return all;
}

}  // namespace

OrderCost order_cost(const LegTable& legs, const std::vector<int>& order, int initial_heading) {
  assert(static_cast<int>(order.size()) == legs.objects());
  Walker w{legs, {}, initial_heading};
  for (int o : order) w.to(o);
  w.to(legs.objects() + 1);
  return w.cost;
}

namespace {

// order_crossover and cross_mut writing into `child`, with `mark` (one flag per gene value) as
// scratch: the GA breeds 48 000 children per run, so no allocation per child.
void crossover_into(const std::vector<int>& p1, const std::vector<int>& p2, std::size_t s,
                    std::size_t e, std::vector<int>& child, std::vector<char>& mark) {
  assert(p1.size() == p2.size() && s < e && e < p1.size());
  child.assign(p1.begin() + static_cast<std::ptrdiff_t>(s), p1.begin() + static_cast<std::ptrdiff_t>(e) + 1);
  for (int g : child) mark[static_cast<std::size_t>(g)] = 1;
  for (int g : p2) {
    if (!mark[static_cast<std::size_t>(g)]) child.push_back(g);
  }
  for (std::size_t k = s; k <= e; ++k) mark[static_cast<std::size_t>(p1[k])] = 0;
  assert(child.size() == p1.size());
}

void cross_mut_into(const std::vector<int>& p1, const std::vector<int>& p2,
                    const OrderGaConfig& config, Rng& rng, std::vector<int>& child,
                    std::vector<char>& mark) {
  const std::size_t n = p1.size();
  if (rng.uniform01() <= config.crossover_rate && n >= 2) {
    const std::size_t a = rng.below(n);
    std::size_t b = rng.below(n - 1);
    if (b >= a) ++b;
    crossover_into(p1, p2, std::min(a, b), std::max(a, b), child, mark);
  } else {
    child = rng.uniform01() < 0.5 ? p1 : p2;
  }
  if (n >= 1 && rng.uniform01() < config.mutation_rate) {
    const std::size_t a = rng.below(n);
    const std::size_t b = rng.below(n);
    std::swap(child[a], child[b]);
  }
}

std::vector<char> gene_marks(const std::vector<int>& genes) {
  int top = 0;
  for (int g : genes) {
    assert(g >= 0);
    top = std::max(top, g);
  }
  return std::vector<char>(static_cast<std::size_t>(top) + 1, 0);
}

// The cost of prefix + genes, without joining them.
OrderCost cost_of(const LegTable& legs, const std::vector<int>& prefix, const std::vector<int>& genes,
                  int initial_heading) {
  assert(prefix.size() + genes.size() == static_cast<std::size_t>(legs.objects()));
  Walker w{legs, {}, initial_heading};
  for (int o : prefix) w.to(o);
  for (int o : genes) w.to(o);
  w.to(legs.objects() + 1);
  return w.cost;
}

}  // namespace

std::vector<int> order_crossover(const std::vector<int>& p1, const std::vector<int>& p2,
                                 std::size_t s, std::size_t e) {
  std::vector<char> mark = gene_marks(p1);
  std::vector<int> child;
  crossover_into(p1, p2, s, e, child, mark);
  return child;
}

std::vector<int> cross_mut(const std::vector<int>& p1, const std::vector<int>& p2,
                           const OrderGaConfig& config, Rng& rng) {
  std::vector<char> mark = gene_marks(p1);
  std::vector<int> child;
  cross_mut_into(p1, p2, config, rng, child, mark);
  return child;
}

OrderSearch order_ga(const LegTable& legs, int initial_heading, const std::vector<int>& prefix,
                     OrderObjective objective, const OrderGaConfig& config, Rng& rng,
                     const std::function<bool()>& stop) {
  assert(config.population >= 2 && config.elites >= 0 && config.elites < config.population);
  assert(config.parents_from_top >= 1 && config.generations >= 1);
  const std::vector<int> genes = free_objects(legs.objects(), prefix);
  OrderSearch out;
  if (genes.size() < 2) {
    out.order = joined(prefix, genes);
    out.cost = order_cost(legs, out.order, initial_heading);
    return out;
  }

  struct Individual {
    std::vector<int> genes;
    OrderCost cost;
  };
  const auto sort_population = [&](std::vector<Individual>& pop) {
    std::stable_sort(pop.begin(), pop.end(), [&](const Individual& a, const Individual& b) {
      return better(a.cost, b.cost, objective);
    });
  };

  const auto n_pop = static_cast<std::size_t>(config.population);
  std::vector<Individual> pop(n_pop), next(n_pop);
  for (Individual& ind : pop) {
    ind.genes = genes;
    for (std::size_t k = genes.size() - 1; k > 0; --k) std::swap(ind.genes[k], ind.genes[rng.below(k + 1)]);  // Fisher-Yates
    ind.cost = cost_of(legs, prefix, ind.genes, initial_heading);
  }
  out.generations = 1;
  const std::size_t top = std::min<std::size_t>(static_cast<std::size_t>(config.parents_from_top), n_pop);
  const std::size_t elites = static_cast<std::size_t>(config.elites);
  std::vector<char> mark = gene_marks(genes);
  for (int generation = 1; generation < config.generations; ++generation) {
    sort_population(pop);
    if (stop && stop()) {
      out.stopped = true;
      break;
    }
    for (std::size_t k = 0; k < elites; ++k) next[k] = pop[k];
    for (std::size_t k = elites; k < n_pop; ++k) {
      const std::size_t i = rng.below(top);
      std::size_t j = i;
      if (top > 1) {
        j = rng.below(top - 1);
        if (j >= i) ++j;
      }
      cross_mut_into(pop[i].genes, pop[j].genes, config, rng, next[k].genes, mark);
      next[k].cost = cost_of(legs, prefix, next[k].genes, initial_heading);
    }
    std::swap(pop, next);
    ++out.generations;
  }
  sort_population(pop);
  out.order = joined(prefix, pop.front().genes);
  out.cost = pop.front().cost;
  return out;
}

std::vector<int> greedy_order(const LegTable& legs, const std::vector<int>& prefix) {
  std::vector<int> rest = free_objects(legs.objects(), prefix);
  std::vector<int> order = prefix;
  int at = prefix.empty() ? 0 : prefix.back();
  while (!rest.empty()) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < rest.size(); ++k) {
      if (legs.leg(at, rest[k]).length < legs.leg(at, rest[best]).length) best = k;
    }
    at = rest[best];
    order.push_back(at);
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return order;
}

namespace {

// Held-Karp over the free objects, state (subset, last object, heading), lexicographic costs.
OrderSearch exact_order(const LegTable& legs, int initial_heading, const std::vector<int>& prefix,
                        const std::vector<int>& genes, OrderObjective objective) {
  const int m = static_cast<int>(genes.size());
  const int dest = legs.objects() + 1;
  Walker head{legs, {}, initial_heading};
  for (int p : prefix) head.to(p);

  const std::size_t states = (std::size_t{1} << m) * static_cast<std::size_t>(m) * 8;
  std::vector<OrderCost> cost(states);
  std::vector<std::int32_t> parent(states, -2);  // -2 unreached, -1 first object
  const auto index = [m](std::size_t mask, int last, int heading) {
    return (mask * static_cast<std::size_t>(m) + static_cast<std::size_t>(last)) * 8 +
           static_cast<std::size_t>(heading);
  };
  const auto relax = [&](std::size_t to, const OrderCost& c, std::int32_t from) {
    if (parent[to] == -2 || better(c, cost[to], objective)) {
      cost[to] = c;
      parent[to] = from;
    }
  };
  for (int j = 0; j < m; ++j) {
    Walker w = head;
    w.to(genes[static_cast<std::size_t>(j)]);
    relax(index(std::size_t{1} << j, j, w.heading), w.cost, -1);
  }
  for (std::size_t mask = 1; mask < (std::size_t{1} << m); ++mask) {
    for (int j = 0; j < m; ++j) {
      if (!(mask & (std::size_t{1} << j))) continue;
      for (int h = 0; h < 8; ++h) {
        const std::size_t from = index(mask, j, h);
        if (parent[from] == -2) continue;
        for (int k = 0; k < m; ++k) {
          if (mask & (std::size_t{1} << k)) continue;
          Walker w{legs, cost[from], h, genes[static_cast<std::size_t>(j)]};
          w.to(genes[static_cast<std::size_t>(k)]);
          relax(index(mask | (std::size_t{1} << k), k, w.heading), w.cost,
                static_cast<std::int32_t>(from));
        }
      }
    }
  }
  const std::size_t full = (std::size_t{1} << m) - 1;
  std::optional<std::size_t> best_state;
  OrderCost best;
  for (int j = 0; j < m; ++j) {
    for (int h = 0; h < 8; ++h) {
      const std::size_t s = index(full, j, h);
      if (parent[s] == -2) continue;
      Walker w{legs, cost[s], h, genes[static_cast<std::size_t>(j)]};
      w.to(dest);
      if (!best_state || better(w.cost, best, objective)) {
        best = w.cost;
        best_state = s;
      }
    }
  }
  assert(best_state);
  std::vector<int> rest;
  for (std::int64_t s = static_cast<std::int64_t>(*best_state); s >= 0; s = parent[static_cast<std::size_t>(s)]) {
    rest.push_back(genes[(static_cast<std::size_t>(s) / 8) % static_cast<std::size_t>(m)]);
  }
  std::reverse(rest.begin(), rest.end());
  OrderSearch out;
  out.order = joined(prefix, rest);
  out.cost = best;
  out.exact = true;
  assert(order_cost(legs, out.order, initial_heading) == best);
  return out;
}

}  // namespace

// First-improvement 2-opt (reverse a stretch) and Or-opt (move a block of 1-3) on the free part.
OrderSearch polish_order(const LegTable& legs, int initial_heading, std::size_t fixed,
                         std::vector<int> order, OrderObjective objective) {
  assert(fixed <= order.size());
  OrderCost cost = order_cost(legs, order, initial_heading);
  const auto try_order = [&](std::vector<int>& candidate) {
    const OrderCost c = order_cost(legs, candidate, initial_heading);
    if (!better(c, cost, objective)) return false;
    order.swap(candidate);
    cost = c;
    return true;
  };
  const std::size_t n = order.size();
  std::vector<int> candidate;
  for (bool improved = true; improved;) {
    improved = false;
    for (std::size_t i = fixed; i + 1 < n && !improved; ++i) {
      for (std::size_t j = i + 1; j < n && !improved; ++j) {
        candidate = order;
        std::reverse(candidate.begin() + static_cast<std::ptrdiff_t>(i),
                     candidate.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        improved = try_order(candidate);
      }
    }
    for (std::size_t len = 1; len <= 3 && !improved; ++len) {
      for (std::size_t i = fixed; i + len <= n && !improved; ++i) {
        for (std::size_t k = fixed; k + len <= n && !improved; ++k) {
          if (k == i) continue;
          candidate = order;
          std::vector<int> block(candidate.begin() + static_cast<std::ptrdiff_t>(i),
                                 candidate.begin() + static_cast<std::ptrdiff_t>(i + len));
          candidate.erase(candidate.begin() + static_cast<std::ptrdiff_t>(i),
                          candidate.begin() + static_cast<std::ptrdiff_t>(i + len));
          candidate.insert(candidate.begin() + static_cast<std::ptrdiff_t>(k), block.begin(), block.end());
          improved = try_order(candidate);
        }
      }
    }
  }
  return {std::move(order), cost, 0, false, false};
}

OrderSearch reference_order(const LegTable& legs, int initial_heading, const std::vector<int>& prefix,
                            const std::vector<int>& hint, OrderObjective objective) {
  const std::vector<int> genes = free_objects(legs.objects(), prefix);
  if (genes.empty()) {
    OrderSearch out;
    out.order = prefix;
    out.cost = order_cost(legs, prefix, initial_heading);
    out.exact = true;
    return out;
  }
  if (static_cast<int>(genes.size()) <= kExactMaxFreeObjects) {
    return exact_order(legs, initial_heading, prefix, genes, objective);
  }
  std::vector<int> start = greedy_order(legs, prefix);
  const bool hint_usable = hint.size() == start.size() &&
                           std::equal(prefix.begin(), prefix.end(), hint.begin()) &&
                           std::is_permutation(hint.begin(), hint.end(), start.begin());
  if (hint_usable && better(order_cost(legs, hint, initial_heading),
                            order_cost(legs, start, initial_heading), objective)) {
    start = hint;
  }
  return polish_order(legs, initial_heading, prefix.size(), std::move(start), objective);
}

}  // namespace swarm::planner
