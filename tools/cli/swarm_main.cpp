// `swarm`: the one command a user needs. Parses flags and hands over to one function per
// subcommand (run_command.hpp, commands.hpp, experiment_command.hpp). Exit statuses: 0 ok, 1 the
// run failed, 2 a bad flag / scenario / run directory, 130 interrupted.
#include <CLI/CLI.hpp>

#include <array>
#include <iostream>
#include <map>

#include "commands.hpp"
#include "darp_cli.hpp"
#include "experiment_command.hpp"
#include "offline_cli.hpp"
#include "mapf_cli.hpp"
#include "probe_command.hpp"
#include "run_command.hpp"

int main(int argc, char** argv) {
  using namespace swarm::tools;
  CLI::App app{
      "swarm: multi-robot exploration over DDS: run a swarm, run experiments, draw, report, "
      "benchmark, divide areas (darp)"};
  app.require_subcommand(1);

  RunOptions run;
  RunOverrides& o = run.overrides;
  std::string map, start, mode;
  std::uint32_t groups = 0, robots = 0, max_ticks = 0;
  std::uint64_t seed = 0;
  long timeout_s = 600;
  CLI::App* run_cmd = app.add_subcommand("run", "Run one multi-process swarm simulation");
  auto* scenario_opt = run_cmd->add_option(
      "--scenario", run.scenario_path,
      "Scenario file (protobuf text); default DATA/scenarios/default.pbtxt");
  run_cmd->add_option("scenario", run.scenario_path, "The scenario file, as --scenario")
      ->excludes(scenario_opt);
  auto* map_opt = run_cmd->add_option(
      "--map", map, "Built-in map (open, maze1, maze2, small, warehouse-5x8) or a map_server YAML file");
  auto* start_opt = run_cmd->add_option("--start", start, "Start point X,Y in metres (map frame)");
  auto* groups_opt = run_cmd->add_option("--groups", groups, "Number of groups");
  auto* robots_opt =
      run_cmd->add_option("--robots-per-group", robots, "Robots per group, leader included");
  auto* mode_opt = run_cmd->add_option("--mode", mode, "group-frontier | baseline | ideal");
  run_cmd->add_option("--mission", o.mission,
                      "The mission's phases in order, e.g. explore,cover (default: the scenario's; explore alone)")
      ->delimiter(',');
  auto* seed_opt = run_cmd->add_option("--seed", seed, "Random seed");
  auto* ticks_opt = run_cmd->add_option("--max-ticks", max_ticks, "Stop, incomplete, at this tick");
  bool realtime = false;
  std::uint32_t tick_ms = 0;
  auto* realtime_opt = run_cmd->add_flag("--realtime", realtime,
                                         "Real-time mode: ticks at a wall rate, link delays in ms (delay_ms)");
  auto* tick_ms_opt = run_cmd->add_option("--tick-ms", tick_ms, "Real-time tick length in milliseconds");
  run_cmd->add_option("--kill", o.kills,
                      "Crash a robot's process at a tick, e.g. member-1-2@100 or leader-1@100 (with a standby), or the "
                      "GCS's with a restart S seconds later, gcs@40+2 (repeatable)");
  run_cmd->add_option("--cut", o.cuts, "Cut an agent's links for ticks A..B, e.g. leader-1@80-180 (repeatable)");
  run_cmd->add_option("--freeze", o.freezes,
                      "Stop a robot's process at a tick for S seconds (a real DDS outage), e.g. leader-1@80+10 "
                      "(repeatable)");
  run_cmd->add_option("--out", run.out_dir,
                      "Run directory; default runs/<time>-<map>-<mode>-s<seed>");
  run_cmd->add_option("--timeout", timeout_s, "Wall-clock limit in seconds (0 = none)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  run_cmd
      ->add_option("--discovery", run.discovery,
                   "How the processes find each other: server (a Fast DDS discovery server of the run's own, "
                   "on loopback) or simple (every process announces itself to every other: traffic grows with the square of the count)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, RunOptions::Discovery>{{"server", RunOptions::Discovery::Server},
                                                        {"simple", RunOptions::Discovery::Simple}}))
      ->capture_default_str();
  run_cmd->add_flag("--secure", run.secure,
                    "DDS-Security: a CA and one certificate per process in RUN_DIR/security; every process "
                    "authenticates and encrypts, so a participant without a certificate sees nothing (simple discovery)");
  run_cmd->add_option("--partition", run.partition, "DDS partition of the run (default: unique to the run)");
  int domain = -1;
  auto* domain_opt = run_cmd->add_option("--domain", domain, "DDS domain id of the run (default: from the process id)")
                         ->check(CLI::Range(1, kMaxDomainId));
  run_cmd
      ->add_option("--agents-per-process", run.agents_per_process,
                   "Member robots of one group per process (each still has its own DDS endpoints); 1 = a process "
                   "per robot")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);

  RenderOptions render;
  std::uint32_t tick = 0;
  CLI::App* render_cmd =
      app.add_subcommand("render", "Draw a run's map (or a frontier snapshot) again");
  render_cmd->add_option("run_dir", render.run_dir, "Run directory written by `swarm run`")
      ->required();
  auto* tick_opt =
      render_cmd->add_option("--tick", tick, "Draw the frontiers at this tick instead");
  render_cmd->add_option("--out", render.out_path,
                         "PNG to write; default RUN_DIR/map.png or RUN_DIR/frontiers-<T>.png");
  render_cmd->add_option("--scale", render.scale, "Pixels per cell")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));

  CLI::App* bench_cmd =
      app.add_subcommand("bench", "Benchmarks: ray casting rays/s, A*, and the default mission's ticks/s "
                         "([planner|mission|tour|mapf|darp] [Google Benchmark flags])");
  bench_cmd->prefix_command();

  // `swarm experiment KIND`: one subcommand per kind, the same flags on each.
  CLI::App* experiment_cmd = app.add_subcommand(
      "experiment", "Run many swarms in parallel and table, plot and save the results");
  experiment_cmd->require_subcommand(1);
  const std::array<std::pair<ExperimentKind, const char*>, 4> kinds = {{
      {ExperimentKind::kExplore,
       "Paper's Table 2: group-frontier vs baseline vs ideal on open, maze1, maze2 (5 seeds)"},
      {ExperimentKind::kLatency,
       "Steps vs leader<->GCS and member<->leader link delay (maze1, 3 seeds)"},
      {ExperimentKind::kBandwidth,
       "Map-change encodings' bytes, and steps vs a leader<->GCS bandwidth cap (maze1, 3 seeds)"},
      {ExperimentKind::kLoss, "Steps and completion vs message loss on every link (maze1, 3 seeds)"},
  }};
  std::array<ExperimentOptions, 4> experiment;
  std::array<std::int64_t, 4> seeds_flag{}, jobs_flag{};
  std::array<long, 4> experiment_timeout{};
  std::array<CLI::App*, 4> kind_cmd{};
  std::array<CLI::Option*, 4> seeds_opt{}, jobs_opt{};
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    ExperimentOptions& e = experiment[k];
    e.kind = kinds[k].first;
    experiment_timeout[k] = static_cast<long>(e.timeout.count());
    CLI::App* c = experiment_cmd->add_subcommand(kind_name(e.kind), kinds[k].second);
    kind_cmd[k] = c;
    seeds_opt[k] = c->add_option("--seeds", seeds_flag[k],
                                 "Number of seeds (seeds 1..N); default " +
                                     std::to_string(default_seeds(e.kind)));
    std::string maps, methods;
    for (const auto& m : default_maps(e.kind)) maps += (maps.empty() ? "" : ",") + m;
    for (const auto& m : default_methods(e.kind)) methods += (methods.empty() ? "" : ",") + m;
    c->add_option("--maps", e.maps,
                  "Comma-separated built-in maps (open, maze1, maze2, small, warehouse-5x8) or YAML files; "
                  "default " + maps)
        ->delimiter(',');
    c->add_option("--methods", e.methods,
                  "Comma-separated: group-frontier, baseline, ideal; default " + methods)
        ->delimiter(',');
    jobs_opt[k] = c->add_option("--jobs", jobs_flag[k], "Runs at once; default the core count");
    c->add_option("--out", e.out_dir,
                  "Experiment directory; default runs/experiment-" + kind_name(e.kind) + "-<time>");
    c->add_option("--scenario", e.scenario_path,
                  "Base scenario file; default DATA/scenarios/default.pbtxt");
    c->add_option("--timeout", experiment_timeout[k],
                  "Wall-clock limit per run in seconds (0 = none); a stuck run fails")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
  }

  const auto mapf = add_mapf_cli(app);
  const auto experiment_mapf = add_experiment_mapf_cli(experiment_cmd);
  DarpOptions darp;
  CLI::App* darp_cmd = add_darp(app, darp);
  DarpExperimentOptions darp_experiment;
  CLI::App* darp_experiment_cmd = add_experiment_darp(*experiment_cmd, darp_experiment);

  ReportOptions report;
  CLI::App* report_cmd = app.add_subcommand(
      "report", "Rebuild an experiment's (or run directories') tables and plots without re-running");
  report_cmd->add_option("dirs", report.dirs,
                         "An experiment directory, or run directories / folders of them")
      ->required();
  report_cmd->add_option("--out", report.out_dir,
                         "Where to write; default the experiment directory, or "
                         "runs/report-<time> for run directories");

  const OfflineCommands offline(app, *experiment_cmd);  // tour, clean, experiment tour / clean
  ProbeOptions probe;
  CLI::App* probe_cmd = add_probe(app, probe);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;  // prints the help, or the error
  }

  if (const std::optional<int> status = offline.run(std::cout, std::cerr)) return *status;
  if (run_cmd->parsed()) {
    if (map_opt->count()) o.map = map;
    if (start_opt->count()) o.start = start;
    if (groups_opt->count()) o.groups = groups;
    if (robots_opt->count()) o.robots_per_group = robots;
    if (mode_opt->count()) o.mode = mode;
    if (seed_opt->count()) o.seed = seed;
    if (ticks_opt->count()) o.max_ticks = max_ticks;
    if (realtime_opt->count()) o.realtime = realtime;
    if (tick_ms_opt->count()) o.tick_ms = tick_ms;
    if (domain_opt->count()) run.domain_id = domain;
    run.timeout = std::chrono::seconds(timeout_s);
    return run_command(run, std::cout, std::cerr);
  }
  if (render_cmd->parsed()) {
    if (tick_opt->count()) render.tick = tick;
    return render_command(render, std::cout, std::cerr);
  }
  if (darp_cmd->parsed()) return darp_command(darp, std::cout, std::cerr);
  if (darp_experiment_cmd->parsed()) return experiment_darp_command(darp_experiment, std::cout, std::cerr);
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    if (!kind_cmd[k]->parsed()) continue;
    ExperimentOptions& e = experiment[k];
    if (seeds_opt[k]->count()) e.seeds = seeds_flag[k];
    if (jobs_opt[k]->count()) e.jobs = jobs_flag[k];
    e.timeout = std::chrono::seconds(experiment_timeout[k]);
    return experiment_command(e, std::cout, std::cerr);
  }
  if (report_cmd->parsed()) return report_command(report, std::cout, std::cerr);
  if (probe_cmd->parsed()) return probe_command(probe, std::cout, std::cerr);
  if (mapf->parsed()) return mapf_command(mapf->resolved(), std::cout, std::cerr);
  if (experiment_mapf->parsed()) return experiment_mapf_command(experiment_mapf->resolved(), std::cout, std::cerr);
  return bench_command(executable_dir(), bench_cmd->remaining(), std::cerr);
}
