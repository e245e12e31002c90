// The `swarm` commands around one run: run, render, bench, report (command.hpp: the pattern).
#include <CLI/CLI.hpp>

#include <iostream>
#include <map>
#include <memory>

#include "cli_numbers.hpp"
#include "command.hpp"
#include "commands.hpp"
#include "experiment_command.hpp"
#include "run_command.hpp"
#include "swarm/planner/grid/map_io.hpp"

namespace swarm::tools {

Command add_run(CLI::App& app) {
  // The flags that override a scenario field only when given (RunOverrides holds optionals).
  struct Flags {
    RunOptions run;
    std::string map, start, mode;
    double map_resolution = 0;
    std::uint32_t groups = 0, robots = 0, max_ticks = 0, tick_ms = 0;
    std::uint64_t seed = 0;
    long timeout_s = 600;
    bool realtime = false;
    bool check = false;
    int domain = -1;
    CLI::Option *map_opt, *map_resolution_opt, *start_opt, *groups_opt, *robots_opt, *mode_opt, *seed_opt, *ticks_opt, *realtime_opt,
        *tick_ms_opt, *domain_opt;
  };
  auto f = std::make_shared<Flags>();
  RunOptions& run = f->run;
  RunOverrides& o = run.overrides;
  CLI::App* run_cmd = app.add_subcommand("run", "Run one multi-process swarm simulation");
  auto* scenario_opt = run_cmd->add_option(
      "--scenario", run.scenario_path,
      "Scenario file (protobuf text); default DATA/scenarios/default.pbtxt");
  run_cmd->add_option("scenario", run.scenario_path, "The scenario file, as --scenario")
      ->excludes(scenario_opt);
  f->map_opt = run_cmd->add_option(
      "--map", f->map,
      "Built-in map (open, maze1, maze2, small, warehouse-5x8, ...), a map_server YAML file or a MovingAI .map file");
  f->map_resolution_opt = run_cmd->add_option("--map-resolution", f->map_resolution,
                                              "Metres per cell of a MovingAI .map (default: the scenario's "
                                              "map_resolution_m, 0.2)")
                              ->check(number({planner::kMinResolutionM, planner::kMaxResolutionM}));
  f->start_opt = run_cmd->add_option("--start", f->start, "Start point X,Y in metres (map frame)");
  f->groups_opt = run_cmd->add_option("--groups", f->groups, "Number of groups");
  f->robots_opt = run_cmd->add_option("--robots-per-group", f->robots, "Robots per group, leader included");
  f->mode_opt = run_cmd->add_option("--mode", f->mode, "group-frontier | baseline | ideal");
  run_cmd->add_option("--mission", o.mission,
                      "The mission's phases in order, e.g. explore,cover (default: the scenario's; explore alone); "
                      "without --max-ticks, the scenario's max_ticks applies per phase")
      ->delimiter(',');
  f->seed_opt = run_cmd->add_option("--seed", f->seed, "Random seed");
  f->ticks_opt = run_cmd->add_option("--max-ticks", f->max_ticks, "Stop, incomplete, at this tick");
  f->realtime_opt = run_cmd->add_flag("--realtime", f->realtime,
                                      "Real-time mode: ticks at a wall rate, link delays in ms (delay_ms)");
  f->tick_ms_opt = run_cmd->add_option("--tick-ms", f->tick_ms, "Real-time tick length in milliseconds");
  run_cmd->add_option("--kill", o.kills,
                      "Crash a robot's process at a tick, e.g. member-1-2@100 or leader-1@100 (with a standby), or the "
                      "GCS's with a restart S seconds later, gcs@40+2 (repeatable)");
  run_cmd->add_option("--cut", o.cuts, "Cut an agent's links for ticks A..B, e.g. leader-1@80-180 (repeatable)");
  run_cmd->add_option("--freeze", o.freezes,
                      "Stop a robot's process at a tick for S seconds (a real DDS outage), e.g. leader-1@80+10 "
                      "(repeatable)");
  run_cmd->add_flag("--check", f->check,
                    "Check the scenario and flags and resolve the world (map, start, robots, goals) as a run "
                    "would, say what would run, and stop: nothing is created or started");
  run_cmd->add_option("--out", run.out_dir,
                      "Run directory; default runs/<time>-<map>-<mode>-s<seed>");
  run_cmd->add_flag("--view", run.view,
                    "Watch the run live in the browser (and in Foxglove: foxglove.websocket.v1) at the address printed");
  run_cmd->add_option("--view-port", run.view_port, "The live view's port")->capture_default_str()->check(CLI::Range(1, 65535));
  run_cmd->add_option("--view-bind", run.view_bind, "The live view's address (loopback unless told otherwise)")
      ->capture_default_str();
  run_cmd->add_option("--mcap", run.mcap_path,
                      "Also write the run's record as an MCAP file (Foxglove, Lichtblick), as `swarm export` does");
  run_cmd->add_option("--timeout", f->timeout_s, "Wall-clock limit in seconds (0 = none)")
      ->capture_default_str()
      ->check(wall_seconds());
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
  f->domain_opt = run_cmd->add_option("--domain", f->domain, "DDS domain id of the run (default: from the process id)")
                      ->check(number({1, kMaxDomainId}));
  run_cmd
      ->add_option("--agents-per-process", run.agents_per_process,
                   "Member robots of one group per process (each still has its own DDS endpoints); 1 = a process "
                   "per robot")
      ->capture_default_str()
      ->check(number(config::kPositive));
  return {run_cmd, [f](std::ostream& out, std::ostream& err) {
            RunOptions run = f->run;
            RunOverrides& o = run.overrides;
            if (f->map_opt->count()) o.map = f->map;
            if (f->map_resolution_opt->count()) o.map_resolution = f->map_resolution;
            if (f->start_opt->count()) o.start = f->start;
            if (f->groups_opt->count()) o.groups = f->groups;
            if (f->robots_opt->count()) o.robots_per_group = f->robots;
            if (f->mode_opt->count()) o.mode = f->mode;
            if (f->seed_opt->count()) o.seed = f->seed;
            if (f->ticks_opt->count()) o.max_ticks = f->max_ticks;
            if (f->realtime_opt->count()) o.realtime = f->realtime;
            if (f->tick_ms_opt->count()) o.tick_ms = f->tick_ms;
            if (f->domain_opt->count()) run.domain_id = f->domain;
            run.timeout = std::chrono::seconds(f->timeout_s);
            return f->check ? check_run_command(run, out, err) : run_command(run, out, err);
          }};
}

Command add_render(CLI::App& app) {
  struct Flags {
    RenderOptions render;
    std::uint32_t tick = 0;
    CLI::Option* tick_opt = nullptr;
  };
  auto f = std::make_shared<Flags>();
  CLI::App* render_cmd = app.add_subcommand("render", "Draw a run's map (or a frontier snapshot) again");
  render_cmd->add_option("run_dir", f->render.run_dir, "Run directory written by `swarm run`")->required();
  f->tick_opt = render_cmd->add_option("--tick", f->tick, "Draw the frontiers at this tick instead");
  render_cmd->add_option("--out", f->render.out_path,
                         "PNG to write; default RUN_DIR/map.png or RUN_DIR/frontiers-<T>.png");
  render_cmd->add_option("--scale", f->render.scale, "Pixels per cell")
      ->capture_default_str()
      ->check(number({1, 64}));
  return {render_cmd, [f](std::ostream& out, std::ostream& err) {
            RenderOptions render = f->render;
            if (f->tick_opt->count()) render.tick = f->tick;
            return render_command(render, out, err);
          }};
}

Command add_export(CLI::App& app) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* cmd = app.add_subcommand("export", "Write a run's record as an MCAP file (Foxglove, Lichtblick)");
  cmd->add_option("run_dir", o->run_dir, "Run directory written by `swarm run`")->required();
  cmd->add_option("--mcap", o->mcap_path, "The MCAP file to write")->required();
  return {cmd, [o](std::ostream& out, std::ostream& err) { return export_command(*o, out, err); }};
}

Command add_view(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Replay a run in the browser (RUN_DIR), or watch a running swarm live (--attach --scenario FILE)");
  auto* run_dir = cmd->add_option("run_dir", o->run_dir, "Run directory written by `swarm run`");
  auto* attach = cmd->add_flag("--attach", o->attach, "Watch a running swarm (a deployment) live, read-only")
                     ->excludes(run_dir);
  cmd->add_option("--scenario", o->scenario_path, "With --attach: the swarm's scenario file (its map, team, tick)")
      ->needs(attach);
  cmd->add_option("--domain", o->domain, "With --attach: the swarm's DDS domain id")
      ->capture_default_str()
      ->check(number({0, 232}))
      ->needs(attach);
  cmd->add_option("--partition", o->partition, "With --attach: the swarm's DDS partition")->capture_default_str()->needs(attach);
  cmd->add_option("--discovery-server", o->discovery_server,
                  "With --attach: HOST:PORT of the swarm's Fast DDS discovery server (default: simple discovery)")
      ->needs(attach);
  cmd->add_option("--profile", o->profile, "With --attach: Fast DDS XML profile (default: as `swarm probe`)")->needs(attach);
  cmd->add_option("--security-dir", o->security_dir,
                  "With --attach, for a secure swarm: a folder with the swarm's CA, governance and a watcher's "
                  "certificate (a `swarm run --secure`'s RUN_DIR/security, or scripts/make-certs.sh DIR --read-only "
                  "swarm-view beside the deployment's CA)")
      ->check(CLI::ExistingDirectory)
      ->needs(attach);
  cmd->add_option("--identity", o->identity, "With --security-dir: the watcher's certificate name")
      ->capture_default_str()
      ->needs(attach);
  cmd->add_option("--view-port", o->server.port, "The port to serve on")->capture_default_str()->check(CLI::Range(1, 65535));
  cmd->add_option("--view-bind", o->server.bind, "The address to serve on (loopback unless told otherwise)")
      ->capture_default_str();
  return {cmd, [o](std::ostream& out, std::ostream& err) {
            if (o->run_dir.empty() && !o->attach) {
              err << "swarm view: give a run directory to replay, or --attach --scenario FILE to watch a swarm live\n";
              return 2;
            }
            if (o->attach && o->scenario_path.empty()) {
              err << "swarm view --attach: --scenario FILE is needed: the swarm's map, team and tick length\n";
              return 2;
            }
            return view_command(*o, out, err);
          }};
}

Command add_bench(CLI::App& app) {
  CLI::App* bench_cmd =
      app.add_subcommand("bench", "Benchmarks: ray casting rays/s, A*, and the default mission's ticks/s "
                         "([planner|mission|tour|mapf|darp] [Google Benchmark flags])");
  bench_cmd->prefix_command();
  return {bench_cmd, [bench_cmd](std::ostream&, std::ostream& err) {
            return bench_command(executable_dir(), bench_cmd->remaining(), err);
          }};
}

Command add_report(CLI::App& app) {
  auto report = std::make_shared<ReportOptions>();
  CLI::App* report_cmd = app.add_subcommand(
      "report", "Rebuild an experiment's (or run directories') tables and plots without re-running");
  report_cmd->add_option("dirs", report->dirs, "An experiment directory, or run directories / folders of them")
      ->required();
  report_cmd->add_option("--out", report->out_dir,
                         "Where to write; default the experiment directory, or "
                         "runs/report-<time> for run directories");
  return {report_cmd, [report](std::ostream& out, std::ostream& err) { return report_command(*report, out, err); }};
}

}  // namespace swarm::tools
