// `swarm bench scale`: how start-up and the lockstep rate grow with the team, over real Fast DDS
// with the run's own discovery server, started exactly as `swarm run` starts them. Exploration of
// maze1 from the default start, stopped at 150 ticks (a whole mission takes longer with few
// robots than with many, which would mix two questions). One iteration = one run.
//
//   robots 9 / 25 / 50 / 100 / 200 = groups x robots per group 3x3 / 5x5 / 5x10 / 10x10 / 10x20
//   arg 1: member robots per process (1 = one process per robot, as `swarm run` by default)
//
// Counters: startup_s (launch to tick 0, plus the short shutdown), ticks_per_second (the loop),
// processes. Targets on the 2-core development machine (issue 11): 100 robots start in <= 15 s
// and run >= 20 ticks/s; 9 robots >= 300 ticks/s.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include "mission_run.hpp"

namespace {

constexpr std::uint32_t kTicks = 150;

void BM_Scale(benchmark::State& state) {
  namespace fs = std::filesystem;
  const int robots = static_cast<int>(state.range(0));
  const int per_process = static_cast<int>(state.range(1));
  const int groups = robots == 9 ? 3 : robots <= 50 ? 5 : 10;
  const int per_group = robots / groups;
  const fs::path root = fs::temp_directory_path() / ("swarm-bench-scale-" + std::to_string(::getpid()));
  swarm::tools::RunOptions options;
  options.overrides.groups = static_cast<std::uint32_t>(groups);
  options.overrides.robots_per_group = static_cast<std::uint32_t>(per_group);
  options.overrides.max_ticks = kTicks;
  options.agents_per_process = per_process;
  options.timeout = std::chrono::seconds(600);
  double ticks = 0, loop_seconds = 0, startup = 0;
  int runs = 0;
  for (auto _ : state) {
    std::string error;
    const auto t = swarm::bench::run_mission(options, root, runs, error);
    if (!t) {
      state.SkipWithError(error.c_str());
      break;
    }
    state.SetIterationTime(t->total_seconds);
    ticks += t->ticks;
    loop_seconds += t->loop_seconds;
    startup += t->startup_seconds();
    ++runs;
  }
  fs::remove_all(root);
  if (runs > 0) {
    const int member_processes = groups * ((per_group - 1 + per_process - 1) / per_process);
    state.counters["robots"] = robots;
    state.counters["processes"] = 3 + groups + member_processes;  // discovery server, sim, gcs, leaders, members
    state.counters["startup_s"] = startup / runs;
    state.counters["ticks_per_second"] = ticks / loop_seconds;
  }
}
BENCHMARK(BM_Scale)
    ->ArgNames({"robots", "per_process"})
    ->Args({9, 1})
    ->Args({25, 1})
    ->Args({50, 1})
    ->Args({100, 1})
    ->Args({100, 9})
    ->Args({200, 1})
    ->Args({200, 19})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
