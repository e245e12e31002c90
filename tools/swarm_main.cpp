// `swarm`: the one command a user needs. Parses flags and hands over to one function per
// subcommand (run_command.hpp, commands.hpp). Exit statuses: 0 ok, 1 the run failed, 2 a bad
// flag / scenario / run directory, 130 interrupted.
#include <CLI/CLI.hpp>

#include <iostream>

#include "commands.hpp"
#include "run_command.hpp"

int main(int argc, char** argv) {
  using namespace swarm::tools;
  CLI::App app{"swarm: multi-robot exploration over DDS: run a swarm, draw its record, benchmark"};
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
      "--map", map, "Built-in map (open, maze1, maze2, small) or a map_server YAML file");
  auto* start_opt = run_cmd->add_option("--start", start, "Start point X,Y in metres (map frame)");
  auto* groups_opt = run_cmd->add_option("--groups", groups, "Number of groups");
  auto* robots_opt =
      run_cmd->add_option("--robots-per-group", robots, "Robots per group, leader included");
  auto* mode_opt = run_cmd->add_option("--mode", mode, "group-frontier | baseline | ideal");
  auto* seed_opt = run_cmd->add_option("--seed", seed, "Random seed");
  auto* ticks_opt = run_cmd->add_option("--max-ticks", max_ticks, "Stop, incomplete, at this tick");
  run_cmd->add_option("--out", run.out_dir,
                      "Run directory; default runs/<time>-<map>-<mode>-s<seed>");
  run_cmd->add_option("--timeout", timeout_s, "Wall-clock limit in seconds (0 = none)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);

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
                         "([planner|mission] [Google Benchmark flags])");
  bench_cmd->prefix_command();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;  // prints the help, or the error
  }

  if (run_cmd->parsed()) {
    if (map_opt->count()) o.map = map;
    if (start_opt->count()) o.start = start;
    if (groups_opt->count()) o.groups = groups;
    if (robots_opt->count()) o.robots_per_group = robots;
    if (mode_opt->count()) o.mode = mode;
    if (seed_opt->count()) o.seed = seed;
    if (ticks_opt->count()) o.max_ticks = max_ticks;
    run.timeout = std::chrono::seconds(timeout_s);
    return run_command(run, std::cout, std::cerr);
  }
  if (render_cmd->parsed()) {
    if (tick_opt->count()) render.tick = tick;
    return render_command(render, std::cout, std::cerr);
  }
  return bench_command(executable_dir(), bench_cmd->remaining(), std::cerr);
}
