// Collection tours and cleaning orders (planner/tours/tour.hpp, tour_order.hpp, plow.hpp, group_k.hpp):
// the paper's GA on one type's objects (1000 generations), the exact order, a whole tour like the
// paper's scenario 2 (5 types x 10 objects on 20 x 20 cells), and plowing / Group-k of the
// built-in clutter room. Run: swarm bench tour [--benchmark_filter=Ga]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "swarm/planner/coverage/group_k.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/coverage/plow.hpp"
#include "swarm/planner/tours/tour.hpp"
#include "swarm_test/data.hpp"

namespace {

using namespace swarm::planner;

const OccupancyGrid& room20() {
  static const OccupancyGrid g = [] {
    OccupancyGrid m(20, 20, 0.1, 0, 0, CellState::Free);
    for (const auto& [x0, y0, x1, y1] : std::vector<std::array<int, 4>>{{3, 7, 5, 12}, {12, 4, 15, 5}, {7, 13, 10, 14}, {15, 10, 16, 14}}) {
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) m.set({x, y}, CellState::Occupied);
      }
    }
    return m;
  }();
  return g;
}

// `types` x `per_type` objects on free cells, drawn by seed; destinations in the top right.
TourProblem problem(int types, int per_type, std::uint64_t seed) {
  const OccupancyGrid& map = room20();
  TourProblem p;
  p.start = {10, 1};
  for (int t = 0; t < types; ++t) p.destinations.push_back({19 - t, 19});
  Rng rng(seed);
  while (static_cast<int>(p.objects.size()) < types * per_type) {
    const Cell c{rng.uniform_int(0, 19), rng.uniform_int(0, 17)};
    if (map.is_free(c) && c != p.start) p.objects.push_back({c, static_cast<int>(p.objects.size()) % types});
  }
  return p;
}

std::vector<Cell> stops(int n) {
  const TourProblem p = problem(1, n, 3);
  std::vector<Cell> s{p.start};
  for (const TourObject& o : p.objects) s.push_back(o.cell);
  s.push_back(p.destinations.front());
  return s;
}

void BM_LegTable(benchmark::State& state) {
  const std::vector<Cell> s = stops(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(LegTable(room20(), nullptr, s).complete());
}
BENCHMARK(BM_LegTable)->Arg(10)->Arg(30)->Unit(benchmark::kMillisecond);

// The paper's GA: 50 x 1000 orders, each costed from the cached legs in O(n).
void BM_OrderGa(benchmark::State& state) {
  const LegTable legs(room20(), nullptr, stops(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    Rng rng(1);
    benchmark::DoNotOptimize(order_ga(legs, kHeadingUp, {}, OrderObjective::kDistanceThenRotation, {}, rng).cost);
  }
}
BENCHMARK(BM_OrderGa)->Arg(8)->Arg(10)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_ExactOrder(benchmark::State& state) {
  const LegTable legs(room20(), nullptr, stops(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(reference_order(legs, kHeadingUp, {}).cost);
}
BENCHMARK(BM_ExactOrder)->Arg(8)->Arg(10)->Arg(13)->Unit(benchmark::kMillisecond);

// A whole tour of 5 types x 10 objects (the paper's scenario 2 size) per search.
void BM_PlanTour(benchmark::State& state) {
  const TourProblem p = problem(5, 10, 7);
  TourOptions o;
  o.search = static_cast<TourOptions::Search>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(plan_tour(room20(), p, o).length);
  state.SetLabel(search_name(o.search));
}
BENCHMARK(BM_PlanTour)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

const OccupancyGrid& clutter() {
  static const OccupancyGrid g = load_map_yaml(swarm::test::source_dir() + "/maps/clutter.yaml");
  return g;
}

void BM_Plow(benchmark::State& state) {
  const CellMask all = free_cells(clutter());
  for (auto _ : state) benchmark::DoNotOptimize(plow(clutter(), all, {1, 48}).cells.size());
}
BENCHMARK(BM_Plow)->Unit(benchmark::kMillisecond);

void BM_GroupK(benchmark::State& state) {
  const CellMask all = free_cells(clutter());
  for (auto _ : state) benchmark::DoNotOptimize(group_k(clutter(), all, {1, 48}).path.cells.size());
}
BENCHMARK(BM_GroupK)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
