// The default mission as a benchmark: 3 groups x 3 robots on maze1, 11 processes over real Fast
// DDS in lockstep, started exactly as `swarm run` starts them. One iteration = one whole mission.
// Reported time is the lockstep loop (tick 0 to the GCS's completion); discovery and start-up are
// the "wall_with_startup_s" counter. Target on a 2-core machine: >= 200 ticks/s.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_command.hpp"

namespace {

void BM_DefaultMission(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("swarm-bench-" + std::to_string(::getpid()));
  double ticks = 0, loop_seconds = 0, startup_seconds = 0;
  int runs = 0;
  for (auto _ : state) {
    swarm::tools::RunOptions options;
    options.out_dir = (root / std::to_string(runs)).string();
    const auto start = std::chrono::steady_clock::now();
    const swarm::tools::PreparedRun run = swarm::tools::prepare_run(options);
    auto processes = swarm::tools::build_run_processes(run.launch, run.world.scenario);
    for (auto& p : processes) p.echo_stdout = false;
    const auto result = swarm::tools::run_processes(processes, std::chrono::seconds(300));
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!result.ok) {
      state.SkipWithError(("the mission failed: " + result.message).c_str());
      break;
    }
    std::ifstream in(run.launch.run_dir + "/metrics.json");
    const auto m = nlohmann::json::parse(in);
    const double loop = m["wall_seconds"];
    state.SetIterationTime(loop);
    ticks += m["ticks_run"].get<double>();
    loop_seconds += loop;
    startup_seconds += total - loop;
    ++runs;
  }
  fs::remove_all(root);
  if (runs > 0) {
    state.counters["ticks_per_second"] = ticks / loop_seconds;
    state.counters["ticks"] = ticks / runs;
    state.counters["wall_with_startup_s"] = (loop_seconds + startup_seconds) / runs;
    state.counters["processes"] = 11;
  }
}
BENCHMARK(BM_DefaultMission)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
