// `swarm`: the one command a user needs. Every subcommand is a Command (command.hpp): declared
// here in the order `swarm --help` lists them, run once parsed. Exit statuses: 0 ok, 1 the run
// failed, 2 a bad flag / scenario / run directory, 130 interrupted.
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

#include "cli_numbers.hpp"
#include "command.hpp"

namespace {

// "" when the words before the first flag name commands; otherwise the message for the first
// that does not ("swarm frobnicate" would only get CLI11's "A subcommand is required").
std::string unknown_command(CLI::App& app, int argc, char** argv) {
  CLI::App* at = &app;
  std::string path = "swarm";
  for (int i = 1; i < argc && at->get_require_subcommand_min() > 0; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') return "";
    CLI::App* sub = nullptr;
    try {
      sub = at->get_subcommand(word);
    } catch (const CLI::OptionNotFound&) {
      std::string names;
      for (const CLI::App* c : at->get_subcommands([](CLI::App*) { return true; })) {
        names += (names.empty() ? "" : ", ") + c->get_name();
      }
      return path + ": unknown command '" + word + "' (expected one of " + names + "; " + path + " --help)";
    }
    path += " " + word;
    at = sub;
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace swarm::tools;
  CLI::App app{
      "swarm: multi-robot exploration over DDS: run a swarm, run experiments, draw, report, "
      "benchmark, divide areas (darp)"};
  app.require_subcommand(1);

  std::vector<Command> commands{add_run(app), add_render(app), add_export(app), add_view(app), add_bench(app)};
  CLI::App* experiment = app.add_subcommand("experiment", "Run many swarms in parallel and table, plot and save the results");
  experiment->require_subcommand(1);
  for (Command& c : add_swarm_experiments(*experiment)) commands.push_back(std::move(c));
  commands.push_back(add_mapf(app));
  commands.push_back(add_experiment_mapf(*experiment));
  commands.push_back(add_darp(app));
  commands.push_back(add_experiment_darp(*experiment));
  commands.push_back(add_report(app));
  commands.push_back(add_tour(app));
  commands.push_back(add_clean(app));
  commands.push_back(add_experiment_tour(*experiment));
  commands.push_back(add_experiment_clean(*experiment));
  commands.push_back(add_task_experiment(*experiment, "cover",
                                         "Live coverage makespan vs robots, member<->leader delay and loss; "
                                         "hierarchical vs flat DARP (swarm runs)"));
  commands.push_back(add_task_experiment(*experiment, "mapf-live",
                                         "Live MAPF makespan and conflicts vs member<->leader delay and robots; "
                                         "ECBS vs LaCAM (swarm runs)"));
  commands.push_back(add_experiment_mission(*experiment));
  commands.push_back(add_probe(app));
  check_number_options(app);

  if (const std::string unknown = unknown_command(app, argc, argv); !unknown.empty()) {
    std::cerr << unknown << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;  // prints the help, or the error
  }
  for (const Command& c : commands) {
    if (c.app->parsed()) return c.run(std::cout, std::cerr);
  }
  return 2;  // unreachable: one subcommand is required
}
