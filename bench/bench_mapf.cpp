// MAPF solvers on the MovingAI benchmark (issue 9's Speed targets), 10 s per instance, one thread:
//   CBS        random-32-32-20, 20 / 30 / 40 agents   (target: >= libMultiRobotPlanning's 4/5, 2/5)
//   ECBS w=1.2 random-32-32-20, 100 / 150 agents      (target: 100 agents 5/5)
//   LaCAM*     random-32-32-20, 400 agents; den520d and warehouse-10-20-10-2-1, 1000 agents
//              (target: 5/5 within 10 s each)
// Each benchmark runs scenarios random-1..5 once; counters: solved (of 5), max_s (slowest solve),
// soc_over_lb (mean sum of costs / lower bound of the solved ones).
// Run: build/bin/swarm-bench-mapf [--benchmark_filter=Cbs]   (or `swarm bench mapf`)
// Data: $SWARM_BENCHMARKS_DIR/movingai (default set at configure time). Not part of CI.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm_test/data.hpp"

namespace {

namespace pm = swarm::planner::mapf;

constexpr double kLimitS = 10.0;

void run_five(benchmark::State& state, const std::string& map_name, pm::SolverKind kind, double w) {
  const std::string dir = swarm::test::benchmarks_dir() + "/movingai/";
  const auto agents = static_cast<int>(state.range(0));
  const auto map = swarm::planner::load_movingai_map(dir + map_name + ".map");
  int solved = 0;
  double max_s = 0, ratio = 0;
  for (auto _ : state) {
    solved = 0;
    max_s = ratio = 0;
    for (int s = 1; s <= 5; ++s) {
      const auto scen = pm::load_movingai_scen(dir + map_name + "-random-" + std::to_string(s) + ".scen");
      const pm::Instance in = pm::instance_from_scen(map, scen, agents, map_name + ".map");
      pm::SolverConfig cfg;
      cfg.kind = kind;
      cfg.ecbs.w = w;
      const pm::Result r = pm::solve(in, cfg, pm::StopCondition::after(kLimitS));
      max_s = std::max(max_s, r.seconds);
      if (r.status == pm::Status::Solved) {
        ++solved;
        ratio += static_cast<double>(r.soc) / static_cast<double>(r.lower_bound);
      }
    }
  }
  state.counters["solved"] = solved;
  state.counters["max_s"] = max_s;
  state.counters["soc_over_lb"] = solved > 0 ? ratio / solved : 0.0;
}

void Cbs_Random32(benchmark::State& s) { run_five(s, "random-32-32-20", pm::SolverKind::Cbs, 1.0); }
void Ecbs12_Random32(benchmark::State& s) { run_five(s, "random-32-32-20", pm::SolverKind::Ecbs, 1.2); }
void Lacam_Random32(benchmark::State& s) { run_five(s, "random-32-32-20", pm::SolverKind::Lacam, 1.0); }
void Lacam_Den520d(benchmark::State& s) { run_five(s, "den520d", pm::SolverKind::Lacam, 1.0); }
void Lacam_Warehouse(benchmark::State& s) { run_five(s, "warehouse-10-20-10-2-1", pm::SolverKind::Lacam, 1.0); }

BENCHMARK(Cbs_Random32)->Arg(20)->Arg(30)->Arg(40)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(Ecbs12_Random32)->Arg(100)->Arg(150)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(Lacam_Random32)->Arg(400)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(Lacam_Den520d)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(Lacam_Warehouse)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
