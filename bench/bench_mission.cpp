// The default mission as a benchmark: 3 groups x 3 robots on maze1, 11 processes over real Fast
// DDS in lockstep, started exactly as `swarm run` starts them. One iteration = one whole mission.
// Reported time is the lockstep loop (tick 0 to the GCS's completion); discovery and start-up are
// the "wall_with_startup_s" counter. Target on a 2-core machine: >= 200 ticks/s.
// With view:1, the same mission watched by the live view (`swarm run --view`). BM_ViewOverhead
// measures what the view costs the same way the experiments compare settings: pairs of runs, one
// watched and one not, alternating which goes first, and the paired difference of their loop times
// with its 95 % confidence interval (target: the view adds < 5 %, its interval's upper end too).
// BM_ExportMcap: the default mission's record written as MCAP (`swarm export`), target < 1 s.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <vector>

#include "mcap_export.hpp"
#include "mission_run.hpp"
#include "stats.hpp"
#include "swarm/record/record.hpp"

namespace {

// state.range(0) = 1: watched by the live view (`swarm run --view`), with no browser connected.
void BM_DefaultMission(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("swarm-bench-" + std::to_string(::getpid()));
  double ticks = 0, loop_seconds = 0, total_seconds = 0;
  int runs = 0;
  swarm::tools::RunOptions options;
  options.view = state.range(0) == 1;
  options.view_port = 20000 + ::getpid() % 20000;
  for (auto _ : state) {
    std::string error;
    const auto t = swarm::bench::run_mission(options, root, runs, error);
    if (!t) {
      state.SkipWithError(error.c_str());
      break;
    }
    state.SetIterationTime(t->loop_seconds);
    ticks += t->ticks;
    loop_seconds += t->loop_seconds;
    total_seconds += t->total_seconds;
    ++runs;
  }
  fs::remove_all(root);
  if (runs > 0) {
    state.counters["ticks_per_second"] = ticks / loop_seconds;
    state.counters["ticks"] = ticks / runs;
    state.counters["wall_with_startup_s"] = total_seconds / runs;
    state.counters["processes"] = 12;  // sim, gcs, 3 leaders, 6 members and the discovery server
  }
}
BENCHMARK(BM_DefaultMission)->ArgName("view")->Arg(0)->Arg(1)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

void BM_ViewOverhead(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("swarm-bench-overhead-" + std::to_string(::getpid()));
  const int pairs = static_cast<int>(state.range(0));
  std::vector<double> plain, viewed;
  int run = 0;
  for (auto _ : state) {
    for (int p = 0; p < pairs; ++p) {
      for (const bool view : p % 2 == 0 ? std::vector<bool>{false, true} : std::vector<bool>{true, false}) {
        swarm::tools::RunOptions options;
        options.view = view;
        options.view_port = 20000 + ::getpid() % 20000;
        std::string error;
        const auto t = swarm::bench::run_mission(options, root, run++, error);
        if (!t) {
          state.SkipWithError(error.c_str());
          fs::remove_all(root);
          return;
        }
        (view ? viewed : plain).push_back(t->loop_seconds);
      }
    }
  }
  fs::remove_all(root);
  const swarm::tools::PairedDifference d = swarm::tools::paired_difference(viewed, plain);
  state.counters["pairs"] = static_cast<double>(d.n);
  state.counters["plain_s"] = swarm::tools::summarize(plain).mean;
  state.counters["viewed_s"] = swarm::tools::summarize(viewed).mean;
  state.counters["overhead_pct"] = d.mean_pct;
  state.counters["ci95_low_pct"] = d.low_pct;
  state.counters["ci95_high_pct"] = d.high_pct;
}
BENCHMARK(BM_ViewOverhead)->ArgName("pairs")->Arg(24)->Iterations(1)->Unit(benchmark::kSecond);

void BM_ExportMcap(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("swarm-bench-mcap-" + std::to_string(::getpid()));
  std::string error;
  if (!swarm::bench::run_mission(swarm::tools::RunOptions{}, root, 0, error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  const auto frames = swarm::record::read_record((root / "0").string());
  const swarm::config::World world = swarm::config::resolve_world(frames.front().header().scenario(), ".");
  swarm::tools::McapExport done;
  for (auto _ : state) done = swarm::tools::export_mcap(frames, &world, (root / "run.mcap").string());
  state.counters["messages"] = static_cast<double>(done.messages);
  state.counters["bytes"] = static_cast<double>(done.bytes);
  fs::remove_all(root);
}
BENCHMARK(BM_ExportMcap)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
