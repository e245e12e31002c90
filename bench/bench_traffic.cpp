// The traffic layer's planner (planner/traffic/traffic.hpp) at scale: 100 and 1,000 robots with a
// stream of random goals (each robot gets a new one as it reaches the last: lifelong), planned in
// windows of 16 steps. Counters: ms_per_step (planning time of one step of every robot),
// goals_per_step (throughput), longest_wait (most steps in a row a robot got no closer to its goal).
// Maps: warehouse-10-20-10-2-1 and den520d (MovingAI, $SWARM_BENCHMARKS_DIR/movingai) and the
// built-in open.
// Run: build/bin/swarm-bench-traffic   (or `swarm bench traffic`). Not part of CI.
#include <benchmark/benchmark.h>

#include <chrono>
#include <set>
#include <string>
#include <vector>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm/planner/traffic/traffic.hpp"
#include "swarm_test/data.hpp"
#include "swarm_test/free_region.hpp"

namespace {

namespace pt = swarm::planner::traffic;
using swarm::planner::Cell;
using swarm::planner::CellState;
using swarm::planner::OccupancyGrid;

constexpr int kWindow = 16;
constexpr int kWindows = 20;

OccupancyGrid load(const std::string& name) {
  if (name == "open") return swarm::planner::load_map_yaml(swarm::test::source_dir() + "/maps/open.yaml");
  return swarm::planner::load_movingai_map(swarm::test::benchmarks_dir() + "/movingai/" + name + ".map");
}

void lifelong(benchmark::State& state, const std::string& map_name) {
  const auto robots = static_cast<std::size_t>(state.range(0));
  const OccupancyGrid map = load(map_name);
  const std::vector<Cell> cells = swarm::test::free_region(map);
  double ms_per_step = 0;
  double goals_per_step = 0;
  int longest_wait = 0;
  std::uint64_t rescues = 0, rescues_failed = 0;
  for (auto _ : state) {
    swarm::planner::Rng rng(7);
    std::vector<pt::Agent> agents;
    std::set<int> taken;
    while (agents.size() < robots) {
      const Cell c = cells[rng.below(cells.size())];
      if (taken.insert(map.index(c)).second) agents.push_back({c, {cells[rng.below(cells.size())]}});
    }
    pt::Planner p(map, swarm::planner::MotionModel::four(), {.seed = 7});
    long goals = 0;
    double seconds = 0;
    for (int k = 0; k < kWindows; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const pt::Window w = p.plan(agents, kWindow);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      for (std::size_t a = 0; a < agents.size(); ++a) {
        agents[a].at = w.paths[a].back();
        goals += w.done[a];
        agents[a].goals.erase(agents[a].goals.begin(), agents[a].goals.begin() + w.done[a]);
        if (agents[a].goals.empty()) agents[a].goals.push_back(cells[rng.below(cells.size())]);
      }
    }
    ms_per_step = 1000.0 * seconds / (kWindow * kWindows);
    goals_per_step = static_cast<double>(goals) / (kWindow * kWindows);
    longest_wait = p.longest_wait();
    rescues = p.rescues();
    rescues_failed = p.rescues_failed();
  }
  state.counters["ms_per_step"] = ms_per_step;
  state.counters["goals_per_step"] = goals_per_step;
  state.counters["longest_wait"] = longest_wait;
  state.counters["rescues"] = static_cast<double>(rescues);
  state.counters["rescues_failed"] = static_cast<double>(rescues_failed);
}

void Traffic_Open(benchmark::State& s) { lifelong(s, "open"); }
void Traffic_Warehouse(benchmark::State& s) { lifelong(s, "warehouse-10-20-10-2-1"); }
void Traffic_Den520d(benchmark::State& s) { lifelong(s, "den520d"); }

BENCHMARK(Traffic_Open)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Traffic_Warehouse)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Traffic_Den520d)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
