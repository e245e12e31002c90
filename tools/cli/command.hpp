// One pattern for every command of the `swarm` line. add_<name>(parent) declares a subcommand of
// `parent` with its flags and returns it as a Command whose `run` owns the flags' values; after
// parsing, swarm_main.cpp runs the one that was parsed:
//
//   std::vector<Command> commands;
//   commands.push_back(add_tour(app));
//   ...
//   app.parse(argc, argv);
//   for (const Command& c : commands) if (c.app->parsed()) return c.run(std::cout, std::cerr);
//
// Each command returns the process's exit status (0 ok, 1 the work failed, 2 bad input) and
// writes its messages to `out` / `err`. The add_* functions are listed in the order `swarm --help`
// shows them.
#pragma once

#include <functional>
#include <ostream>
#include <vector>

namespace CLI {
class App;
}

namespace swarm::tools {

struct Command {
  CLI::App* app = nullptr;
  std::function<int(std::ostream& out, std::ostream& err)> run;
};

// run_cli.cpp: a swarm run and what reads its results.
Command add_run(CLI::App& app);
Command add_render(CLI::App& app);
Command add_export(CLI::App& app);
Command add_view(CLI::App& app);
Command add_bench(CLI::App& app);
Command add_report(CLI::App& app);

// experiment_cli.cpp: `swarm experiment KIND` (subcommands of `experiment`).
std::vector<Command> add_swarm_experiments(CLI::App& experiment);  // explore, latency, bandwidth, loss
Command add_experiment_mapf(CLI::App& experiment);
Command add_experiment_darp(CLI::App& experiment);
Command add_experiment_tour(CLI::App& experiment);
Command add_experiment_clean(CLI::App& experiment);
Command add_task_experiment(CLI::App& experiment, const char* task, const char* what);  // cover, mapf-live
Command add_experiment_mission(CLI::App& experiment);

// planner_cli.cpp: the offline planners on one instance.
Command add_mapf(CLI::App& app);
Command add_darp(CLI::App& app);
Command add_tour(CLI::App& app);
Command add_clean(CLI::App& app);

// probe_command.cpp
Command add_probe(CLI::App& app);

}  // namespace swarm::tools
