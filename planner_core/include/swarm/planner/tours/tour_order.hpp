// The visiting order of one type's objects: the GA of Kim & Lee 2025 (seeds/001, Tables 1-3; digest
// docs/papers.md section 4), and an exact / near-exact reference to measure it against.
//
// A run of one type has stops: 0 = where the robot is, 1..n = the objects, n + 1 = the type's
// destination. An order is a permutation of 1..n; its cost is the length of the A* legs
// 0 -> o1 -> ... -> on -> n + 1 (8-connected cells, diagonal = sqrt 2) and the rotation of the
// whole cell path (turns.hpp) from an initial heading, the turns where legs meet included.
// Lengths are kept exact (GridLength: straight and diagonal step counts) and rotations in whole
// eighths of a turn, so "equal length" is decided exactly and the rotation tie-break fires exactly
// when the paper's Sort_Population would (it compares 1 / L for equality).
//
// The GA (order_ga) is the paper's: N chromosomes, G populations; each generation is sorted
// (stable, by the objective), the best 2 are kept (elitism) and N - 2 children are bred from two
// distinct parents drawn uniformly from the top 10: with probability C a crossover (a segment
// [s, e], s < e, of parent 1 goes FIRST, then parent 2's remaining genes in parent 2's order),
// otherwise a copy of either parent; then with probability mu a swap of two random genes. A
// prefix of the order can be fixed (the NNA baseline fixes the first waypoint); the GA permutes
// the rest. Every random draw goes through planner::Rng, so a seed gives the same order anywhere.
//
// The reference (reference_order) is a dynamic programme over subsets (Held & Karp 1962) with the
// last stop and the heading in the state, exact for either objective, when at most
// kExactMaxFreeObjects objects are free; beyond that a 2-opt + Or-opt local search (Lin 1965; Or
// 1976) from the better of a given order and the greedy nearest-neighbour order (not exact).
//
//   LegTable legs(blocked_map, &map, stops);                  // A* for every leg, once
//   Rng rng(mix_seed(seed, run));
//   OrderSearch ga = order_ga(legs, kHeadingUp, {}, OrderObjective::kDistanceThenRotation, {}, rng);
//   OrderSearch best = reference_order(legs, kHeadingUp, {}, ga.order);
//   double gap = ga.cost.length.cells() / best.cost.length.cells() - 1;
//
// Complexity: LegTable runs n (n + 1) + 1 A* searches; a GA generation costs N n; the DP
// 2^m m^2 8 for m free objects. Thread-safety: a LegTable is read-only after construction; the
// search functions share no state (one Rng per call).
#pragma once

#include <compare>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {

// The exact length of an 8-connected path: straight + diagonal * sqrt 2 cells. Compared exactly.
struct GridLength {
  std::int64_t straight = 0;
  std::int64_t diagonal = 0;

  [[nodiscard]] double cells() const { return static_cast<double>(straight) + static_cast<double>(diagonal) * 1.41421356237309504880; }
  GridLength& operator+=(const GridLength& o) {
    straight += o.straight;
    diagonal += o.diagonal;
    return *this;
  }
  friend GridLength operator+(GridLength a, const GridLength& b) { return a += b; }
  friend bool operator==(const GridLength&, const GridLength&) = default;
  // Exact: compares a.straight - b.straight with (b.diagonal - a.diagonal) sqrt 2 in integers.
  friend std::strong_ordering operator<=>(const GridLength& a, const GridLength& b);
};

// The length of a path of 8-neighbour steps (a repeated cell adds nothing). Asserts each step is
// between 8-neighbours.
[[nodiscard]] GridLength grid_length(const std::vector<Cell>& path);

// One leg between two stops: an A* path and what the order search needs to know about it.
struct Leg {
  std::vector<Cell> cells;           // front = from, back = to; empty = no path
  GridLength length;
  int inner_turns = 0;               // eighths turned between its first and last step
  std::optional<int> first_heading;  // nullopt: from == to (the leg does not move)
  std::optional<int> last_heading;
  bool through_objects = false;      // planned on the fallback map (it crosses other objects)
  [[nodiscard]] bool reachable() const { return !cells.empty(); }
};

// The legs between a run's stops (0 = origin, 1..n = objects, n + 1 = destination): every leg an
// order can use (0 -> i, i -> j, i -> n + 1; 0 -> n + 1 when n = 0), A* 8-connected on
// `map` (astar.hpp, Free cells only), or on `fallback` when `map` has no path (nullptr: none).
class LegTable {
 public:
  LegTable(const OccupancyGrid& map, const OccupancyGrid* fallback, std::vector<Cell> stops);

  [[nodiscard]] int objects() const { return static_cast<int>(stops_.size()) - 2; }
  [[nodiscard]] const std::vector<Cell>& stops() const { return stops_; }
  // Asserts the leg is one an order can use.
  [[nodiscard]] const Leg& leg(int from, int to) const;
  // True when every leg has a path.
  [[nodiscard]] bool complete() const { return complete_; }

 private:
  std::vector<Cell> stops_;
  std::vector<Leg> legs_;  // (n + 2) x (n + 2), row = from
  bool complete_ = true;
};

// Length, then rotation (eighths).
struct OrderCost {
  GridLength length;
  int rotation = 0;
  friend bool operator==(const OrderCost&, const OrderCost&) = default;
};

enum class OrderObjective {
  kDistance,              // length only (equal lengths keep their population order)
  kDistanceThenRotation,  // length, and among equal lengths the smaller rotation
};

// Strictly better under the objective.
[[nodiscard]] bool better(const OrderCost& a, const OrderCost& b, OrderObjective objective);

// The cost of visiting `order` (each of 1..n once) from stop 0 facing `initial_heading`, then the
// destination. Asserts every leg it uses has a path.
[[nodiscard]] OrderCost order_cost(const LegTable& legs, const std::vector<int>& order,
                                   int initial_heading);

// The paper's parameters (Table 4).
struct OrderGaConfig {
  int population = 50;           // N
  int generations = 1000;        // G: populations evaluated, the first one random
  double crossover_rate = 1.0;   // C
  double mutation_rate = 0.05;   // mu: one swap per child with this probability
  int parents_from_top = 10;     // parents are drawn from the best this many
  int elites = 2;                // the best this many go to the next generation unchanged
};

// Crossover on fixed cut points: p1[s..e] (inclusive, s < e) first, then p2's other genes in p2's
// order. Both parents are permutations of the same genes.
[[nodiscard]] std::vector<int> order_crossover(const std::vector<int>& p1, const std::vector<int>& p2,
                                               std::size_t s, std::size_t e);

// The paper's CrossMut (Table 3): crossover with probability C on a random segment (two distinct
// uniform positions), else a copy of either parent (1/2 each); then with probability mu a swap of
// two uniform positions (possibly the same: no change).
[[nodiscard]] std::vector<int> cross_mut(const std::vector<int>& p1, const std::vector<int>& p2,
                                         const OrderGaConfig& config, Rng& rng);

struct OrderSearch {
  std::vector<int> order;  // the whole order, prefix included
  OrderCost cost;
  int generations = 0;     // GA: populations evaluated
  bool stopped = false;    // GA: the stop predicate ended it early (best so far)
  bool exact = false;      // reference: proven best for the lexicographic objective
};

// The GA on the objects not in `prefix` (the order starts with `prefix`). Polls `stop` once per
// generation. With fewer than 2 free objects there is one order and no GA runs.
[[nodiscard]] OrderSearch order_ga(const LegTable& legs, int initial_heading,
                                   const std::vector<int>& prefix, OrderObjective objective,
                                   const OrderGaConfig& config, Rng& rng,
                                   const std::function<bool()>& stop = {});

// Nearest-neighbour order after `prefix`: each time the object whose leg is shortest (ties: lowest
// number). Used when a search was stopped, and to start the local search.
[[nodiscard]] std::vector<int> greedy_order(const LegTable& legs, const std::vector<int>& prefix);

// 2-opt + Or-opt local search from `order`, keeping its first `fixed` stops: the order it returns
// is never worse under `objective` and no single reversal or block move (1-3 stops) improves it.
[[nodiscard]] OrderSearch polish_order(const LegTable& legs, int initial_heading, std::size_t fixed,
                                       std::vector<int> order, OrderObjective objective);

inline constexpr int kExactMaxFreeObjects = 13;  // DP memory: 2^13 * 13 * 8 states, ~25 MB

// The best order starting with `prefix` under `objective`: exact (DP) when at most
// kExactMaxFreeObjects objects are free, else a 2-opt + Or-opt local search started from the better
// of `hint` (if it is a whole order starting with prefix) and the greedy order. With kDistance,
// equal lengths are decided by the search order (deterministic, not by rotation).
[[nodiscard]] OrderSearch reference_order(
    const LegTable& legs, int initial_heading, const std::vector<int>& prefix,
    const std::vector<int>& hint = {},
    OrderObjective objective = OrderObjective::kDistanceThenRotation);

}  // namespace swarm::planner
