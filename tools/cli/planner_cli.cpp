// The offline planners' commands on one instance: mapf, darp, tour, clean (command.hpp: the
// pattern; their flags beside them in mapf_cli.hpp and darp_cli.hpp).
#include <CLI/CLI.hpp>

#include <memory>

#include "clean_command.hpp"
#include "command.hpp"
#include "darp_cli.hpp"
#include "mapf_cli.hpp"
#include "tour_command.hpp"

namespace swarm::tools {

Command add_mapf(CLI::App& app) {
  std::shared_ptr<MapfCli> cli = add_mapf_cli(app);
  return {cli->command, [cli](std::ostream& out, std::ostream& err) { return mapf_command(cli->resolved(), out, err); }};
}

Command add_darp(CLI::App& app) {
  auto o = std::make_shared<DarpOptions>();
  CLI::App* c = add_darp_flags(app, *o);
  return {c, [o](std::ostream& out, std::ostream& err) { return darp_command(*o, out, err); }};
}

Command add_tour(CLI::App& app) {
  auto o = std::make_shared<TourCommandOptions>();
  CLI::App* c = app.add_subcommand("tour", "Plan a collection tour (GA + A*) for a tour file: table and pictures");
  c->add_option("file", o->file, "Tour file (README: Collection tours)")->required();
  c->add_option("--variants", o->variants, "nna, distance, distance-angle (default all)")->delimiter(',');
  c->add_option("--search", o->search, "ga (the paper), ga-polished or exact")->capture_default_str();
  c->add_option("--seed", o->seed, "GA seed")->capture_default_str();
  c->add_option("--generations", o->generations, "GA generations (the paper: 1000)")->capture_default_str();
  c->add_flag("--skip-unreachable", o->skip_unreachable, "Plan without objects the start cannot reach");
  c->add_option("--out", o->out_dir, "Output directory; default runs/tour-<file>-<time>");
  return {c, [o](std::ostream& out, std::ostream& err) { return tour_command(*o, out, err); }};
}

Command add_clean(CLI::App& app) {
  auto o = std::make_shared<CleanCommandOptions>();
  CLI::App* c = app.add_subcommand("clean", "Plowing vs Group-k cleaning order on a map: groups, paths, coverage");
  c->add_option("map", o->map, "Built-in map (clutter, empty, ...), map_server YAML or MovingAI .map")
      ->required();
  c->add_option("--start", o->start, "Start cell X,Y; default (1, 1) from the top left");
  c->add_option("--k", o->k, "Group-k's complexity threshold")->capture_default_str();
  c->add_option("--seed", o->seed, "Seed of Release_Group's random tie-break")->capture_default_str();
  c->add_option("--sweep", o->sweep, "columns or rows")->capture_default_str();
  c->add_option("--margin", o->margin, "Widen each group's area by M cells (not in the paper)")
      ->capture_default_str();
  c->add_option("--out", o->out_dir, "Output directory; default runs/clean-<map>-<time>");
  return {c, [o](std::ostream& out, std::ostream& err) { return clean_command(*o, out, err); }};
}

}  // namespace swarm::tools
