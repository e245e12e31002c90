#include "experiment_runner.hpp"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "run_end.hpp"
#include "traffic_over_time.hpp"
#include "swarm/record/record.hpp"
#include "swarm/record/metrics.hpp"
#include "swarm/record/render.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;

// Map and mid-run frontier pictures of a finished run (like `swarm render`).
void draw_pictures(RunOutcome& o) {
  try {
    const auto frames = swarm::record::read_record(swarm::record::run_record_path(o.run_dir));
    const std::string map_png = (fs::path(o.run_dir) / "map.png").string();
    swarm::record::render_map_png(frames, map_png);
    o.pictures.push_back(map_png);
    const auto metrics = swarm::record::read_metrics((fs::path(o.run_dir) / "metrics.json").string());
    const std::uint32_t tick = middle_tick(metrics.steps);
    const std::string frontier_png =
        (fs::path(o.run_dir) / ("frontiers-" + std::to_string(tick) + ".png")).string();
    swarm::record::render_frontier_png(frames, tick, frontier_png);
    o.pictures.push_back(frontier_png);
  } catch (const std::exception& e) {
    o.picture_error = e.what();
  }
}

RunOutcome run_one(const RunJob& job, int domain) {
  RunOutcome o;
  const auto start = std::chrono::steady_clock::now();
  RunOptions options = job.options;
  options.preferred_domain = domain;
  PreparedRun run;
  try {
    run = prepare_run(options);
  } catch (const std::exception& e) {
    o.message = e.what();
    return o;
  }
  o.run_dir = run.launch.run_dir;
  run.launch.progress_bar = false;
  std::vector<ProcessSpec> procs = build_run_processes(run.launch, run.world.scenario);
  for (ProcessSpec& p : procs) p.echo_stdout = false;
  const SupervisorResult r = run_processes(procs, options.timeout);
  o.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.ok) (void)record_early_end(o.run_dir, run.world.scenario, early_end_reason(r));
  if (r.interrupted) {
    o.interrupted = true;
    o.message = "interrupted";
    return o;
  }
  if (!r.ok) {
    o.message = r.message;  // names the process, and the timeout when it was one
    o.message += " (not counted: a run must end cleanly; metrics.json says what it did up to the stop)";
    o.log_path = r.log_path;
    return o;
  }
  if (!fs::exists(fs::path(o.run_dir) / "metrics.json")) {
    o.message = "every process exited normally, but the GCS wrote no metrics.json";
    o.log_path = (fs::path(o.run_dir) / "logs" / "gcs.log").string();
    return o;
  }
  try {
    write_traffic_files(swarm::record::read_record(swarm::record::run_record_path(o.run_dir)), o.run_dir);
  } catch (const std::exception& e) {
    o.message = std::string("every process exited normally, but the traffic over time failed: ") + e.what();
    return o;
  }
  o.ok = true;
  if (job.pictures) draw_pictures(o);
  return o;
}

}  // namespace

std::uint32_t middle_tick(double steps) {
  const auto half = static_cast<std::int64_t>(steps / 2);
  return static_cast<std::uint32_t>(half < 1 ? 1 : half);
}

std::vector<RunOutcome> run_jobs(const std::vector<RunJob>& jobs, const RunnerOptions& options) {
  std::vector<RunOutcome> outcomes(jobs.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex report_mutex;
  const int workers = std::max(1, std::min<int>(options.jobs, static_cast<int>(jobs.size())));
  auto work = [&](int w) {
    const int domain = 1 + (options.first_domain - 1 + w) % kMaxDomainId;
    for (std::size_t i = next++; i < jobs.size(); i = next++) {
      RunOutcome o;
      if (stop) {
        o.interrupted = true;
        o.message = "not run (interrupted)";
      } else {
        o = run_one(jobs[i], domain);
        if (o.interrupted) stop = true;
      }
      outcomes[i] = o;
      std::lock_guard<std::mutex> lock(report_mutex);
      if (options.on_finished) options.on_finished(i, o);
    }
  };
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w) threads.emplace_back(work, w);
  for (auto& t : threads) t.join();
  return outcomes;
}

}  // namespace swarm::tools
