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
//
// BM_ViewPage: the viewer's page (`swarm view`) replaying the 200-robot run in headless Chromium:
// the whole frames (map, routes, robots, names) it draws a second, 60 ticks back to back
// (target >= 20).
#include <benchmark/benchmark.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <thread>

#include "mission_run.hpp"

extern char** environ;

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

void BM_ViewPage(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("swarm-bench-view-" + std::to_string(::getpid()));
  swarm::tools::RunOptions options;
  options.overrides.groups = 10;
  options.overrides.robots_per_group = 20;
  options.overrides.max_ticks = kTicks;
  options.agents_per_process = 19;
  options.timeout = std::chrono::seconds(600);
  std::string error;
  if (!swarm::bench::run_mission(options, root, 0, error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  const std::string swarm_exe = swarm::tools::executable_dir() + "/swarm";
  const std::string port = std::to_string(20000 + ::getpid() % 20000);
  std::vector<std::string> args = {swarm_exe, "view", (root / "0").string(), "--view-port", port};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t viewer = -1;
  if (::posix_spawn(&viewer, swarm_exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0) {
    state.SkipWithError("cannot start swarm view");
    return;
  }
  std::this_thread::sleep_for(std::chrono::seconds(2));
  double fps = 0;
  for (auto _ : state) {
    const std::string cmd = "chromium --headless=new --no-sandbox --disable-gpu --window-size=800,800 "
                            "--dump-dom 'http://127.0.0.1:" + port + "/?fps=1' 2>/dev/null";
    std::string dom;
    if (FILE* pipe = ::popen(cmd.c_str(), "r")) {
      std::array<char, 4096> buf{};
      std::size_t n = 0;
      while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) dom.append(buf.data(), n);
      ::pclose(pipe);
    }
    const auto at = dom.find("<title>fps ");
    if (at == std::string::npos) {
      state.SkipWithError("the page reported no frame rate (is chromium installed?)");
      break;
    }
    fps = std::stod(dom.substr(at + 11));
  }
  ::kill(viewer, SIGTERM);
  ::waitpid(viewer, nullptr, 0);
  fs::remove_all(root);
  state.counters["robots"] = 200;
  state.counters["frames_per_second"] = fps;
}
BENCHMARK(BM_ViewPage)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
