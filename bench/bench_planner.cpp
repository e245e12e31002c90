// Planner-core micro-benchmarks: LiDAR ray casting (the simulator's inner loop), A* on MovingAI
// maps, and one exploration planning round on a 100 x 100 map with ~2,000 frontier cells (a few
// ms each; under 100 ms is the goal on a loaded machine). Run: build/bin/swarm-bench-planner [--benchmark_filter=RayCast]
// MovingAI data is read from $SWARM_BENCHMARKS_DIR/movingai (default set at configure time).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "swarm_test/big_explore_world.hpp"
#include "swarm_test/data.hpp"
#include "swarm/planner/explore/explore.hpp"
#include "swarm/planner/grid/astar.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/sensing/raycast.hpp"

namespace {

using namespace swarm::planner;

constexpr int kBeams = 360;
constexpr float kRangeCells = 15.0f;

std::string movingai_dir() {
  return swarm::test::benchmarks_dir() + "/movingai/";
}

// 100 x 100 cells: outer walls, a 4 x 4 grid of rooms with door gaps, and 3 % scattered clutter.
OccupancyGrid rooms_map() {
  constexpr int kSize = 100;
  OccupancyGrid g(kSize, kSize, 0.2, 0.0, 0.0, CellState::Free);
  for (int i = 0; i < kSize; ++i) {
    for (int j = 0; j < kSize; ++j) {
      const bool wall_x = i % 25 == 0 || i == kSize - 1;
      const bool wall_y = j % 25 == 0 || j == kSize - 1;
      const bool door = (j % 25 >= 10 && j % 25 <= 13) || (i % 25 >= 10 && i % 25 <= 13);
      if ((wall_x || wall_y) && !(door && i > 0 && j > 0 && i < kSize - 1 && j < kSize - 1)) {
        g.set(Cell{i, j}, CellState::Occupied);
      }
    }
  }
  std::mt19937 rng(42);
  std::bernoulli_distribution clutter(0.03);
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (clutter(rng)) g.set(static_cast<int>(i), CellState::Occupied);
  }
  return g;
}

std::vector<Cell> free_cells_sample(const OccupancyGrid& g, std::size_t n) {
  std::vector<Cell> all;
  for (int i = 0; i < static_cast<int>(g.size()); ++i) {
    if (g.at(i) == CellState::Free) all.push_back(g.cell_of(i));
  }
  std::mt19937 rng(7);
  std::shuffle(all.begin(), all.end(), rng);
  if (all.size() > n) all.resize(n);
  return all;
}

// Free inside, walls on the border only; origins at least 16 cells from the border, so every
// ray runs the full 15 cells (the worst case per ray).
OccupancyGrid open_map() {
  constexpr int kSize = 100;
  OccupancyGrid g(kSize, kSize, 0.2, 0.0, 0.0, CellState::Free);
  for (int i = 0; i < kSize; ++i) {
    for (const Cell c : {Cell{i, 0}, Cell{i, kSize - 1}, Cell{0, i}, Cell{kSize - 1, i}}) {
      g.set(c, CellState::Occupied);
    }
  }
  return g;
}

std::vector<Cell> interior_cells(const OccupancyGrid& g, int margin) {
  std::vector<Cell> out;
  for (int y = margin; y < g.height() - margin; ++y) {
    for (int x = margin; x < g.width() - margin; ++x) out.push_back({x, y});
  }
  return out;
}

// One 360-beam, 15-cell scan per iteration; items = rays, so the report shows rays/s.
// Arg 0: the 100 x 100 rooms map with walls and clutter; arg 1: open map, every ray full length.
void BM_RayCast(benchmark::State& state) {
  const bool open = state.range(0) == 1;
  const OccupancyGrid truth = open ? open_map() : rooms_map();
  const std::vector<Cell> origins =
      open ? interior_cells(truth, 16) : free_cells_sample(truth, 1024);
  std::vector<float> ranges(kBeams);
  std::size_t k = 0;
  double hits = 0;
  for (auto _ : state) {
    scan(truth, origins[k], kBeams, kRangeCells, ranges.data());
    benchmark::DoNotOptimize(ranges.data());
    benchmark::ClobberMemory();
    for (float r : ranges) hits += r < kRangeCells;
    k = k + 1 == origins.size() ? 0 : k + 1;
  }
  state.SetItemsProcessed(state.iterations() * kBeams);
  state.counters["hit_fraction"] = hits / (static_cast<double>(state.iterations()) * kBeams);
}
BENCHMARK(BM_RayCast)->ArgName("open")->Arg(0)->Arg(1);

// The agent side: integrating one scan into a map (the map is reset every 1024 scans).
void BM_IntegrateScan(benchmark::State& state) {
  const OccupancyGrid truth = rooms_map();
  const std::vector<Cell> origins = free_cells_sample(truth, 1024);
  std::vector<std::vector<float>> scans(origins.size(), std::vector<float>(kBeams));
  for (std::size_t i = 0; i < origins.size(); ++i) {
    scan(truth, origins[i], kBeams, kRangeCells, scans[i].data());
  }
  OccupancyGrid map(truth.width(), truth.height());
  std::vector<CellChange> changes;
  std::size_t k = 0;
  for (auto _ : state) {
    changes.clear();
    benchmark::DoNotOptimize(
        integrate_scan(map, origins[k], scans[k].data(), kBeams, kRangeCells, &changes));
    if (++k == origins.size()) {
      k = 0;
      state.PauseTiming();
      map = OccupancyGrid(truth.width(), truth.height());
      state.ResumeTiming();
    }
  }
  state.SetItemsProcessed(state.iterations() * kBeams);
}
BENCHMARK(BM_IntegrateScan);

struct Query {
  Cell start;
  Cell goal;
};

std::vector<Query> load_scen(const OccupancyGrid& map, const std::string& path) {
  std::ifstream in(path);
  std::vector<Query> out;
  std::string line;
  std::getline(in, line);  // "version 1"
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    int bucket = 0, w = 0, h = 0, sx = 0, sy = 0, gx = 0, gy = 0;
    std::string file;
    if (ls >> bucket >> file >> w >> h >> sx >> sy >> gx >> gy) {
      out.push_back({from_movingai_xy(map, sx, sy), from_movingai_xy(map, gx, gy)});
    }
  }
  return out;
}

// One A* query per iteration, cycling through the map's random-1 scenario (start/goal pairs).
void BM_AStar(benchmark::State& state, const std::string& name) {
  OccupancyGrid map;
  std::vector<Query> queries;
  try {
    map = load_movingai_map(movingai_dir() + name + ".map");
    queries = load_scen(map, movingai_dir() + name + "-random-1.scen");
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  if (queries.empty()) {
    state.SkipWithError("no scenario lines");
    return;
  }
  std::size_t k = 0;
  double cells = 0;
  for (auto _ : state) {
    const auto path = astar(map, queries[k].start, queries[k].goal);
    benchmark::DoNotOptimize(path);
    cells += path ? static_cast<double>(path->size()) : 0.0;
    k = k + 1 == queries.size() ? 0 : k + 1;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["path_cells"] = cells / static_cast<double>(state.iterations());
}
BENCHMARK_CAPTURE(BM_AStar, maze_32_32_2, std::string("maze-32-32-2"));
BENCHMARK_CAPTURE(BM_AStar, den520d, std::string("den520d"));

// One leader's planning round (arg 1: group frontiers, the paper's method; 0: the baseline's
// global assignment), rounds 0..9 in turn.
void BM_ExplorePlan(benchmark::State& state) {
  const swarm::test::BigExploreWorld w;
  ExploreConfig cfg;
  cfg.use_group_frontiers = state.range(0) != 0;
  int round = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(plan_group_exploration(w.input(round), cfg));
    round = (round + 1) % 10;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ExplorePlan)->ArgName("group_frontiers")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
