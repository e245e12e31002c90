#include "offline_cli.hpp"

#include <CLI/CLI.hpp>

#include "clean_command.hpp"
#include "experiment_tasks.hpp"
#include "offline_experiments.hpp"
#include "tour_command.hpp"

namespace swarm::tools {

struct OfflineCommands::Impl {
  CLI::App* tour_cmd = nullptr;
  CLI::App* clean_cmd = nullptr;
  CLI::App* tour_exp = nullptr;
  CLI::App* clean_exp = nullptr;
  CLI::App* cover_exp = nullptr;
  CLI::App* mapf_live_exp = nullptr;
  TourCommandOptions tour;
  CleanCommandOptions clean;
  TourExperimentOptions tour_experiment;
  CleanExperimentOptions clean_experiment;
  TaskExperimentOptions cover_experiment, mapf_live_experiment;
};

namespace {

CLI::App* add_task_experiment(CLI::App& experiment, const std::string& task, const std::string& what,
                              TaskExperimentOptions& o) {
  o.task = task;
  CLI::App* c = experiment.add_subcommand(task, what);
  c->add_option("--map", o.map, "Built-in map or map_server YAML")->capture_default_str();
  c->add_option("--seeds", o.seeds, "Seeds 1..N per point and variant")->capture_default_str();
  c->add_option("--jobs", o.jobs, "Runs at once")->capture_default_str();
  c->add_option("--timeout", o.timeout_s, "Wall-clock limit per run in seconds")->capture_default_str();
  c->add_option("--out", o.out_dir, "Experiment directory; default runs/experiment-" + task + "-<time>");
  c->add_flag("--quick", o.quick, "Only the first two points of the first sweep (a smoke test)");
  return c;
}

}  // namespace

OfflineCommands::OfflineCommands(CLI::App& app, CLI::App& experiment) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.tour_cmd = app.add_subcommand("tour", "Plan a collection tour (GA + A*) for a tour file: table and pictures");
  m.tour_cmd->add_option("file", m.tour.file, "Tour file (README: Collection tours)")->required();
  m.tour_cmd->add_option("--variants", m.tour.variants, "nna, distance, distance-angle (default all)")->delimiter(',');
  m.tour_cmd->add_option("--search", m.tour.search, "ga (the paper), ga-polished or exact")->capture_default_str();
  m.tour_cmd->add_option("--seed", m.tour.seed, "GA seed")->capture_default_str();
  m.tour_cmd->add_option("--generations", m.tour.generations, "GA generations (the paper: 1000)")->capture_default_str();
  m.tour_cmd->add_flag("--skip-unreachable", m.tour.skip_unreachable, "Plan without objects the start cannot reach");
  m.tour_cmd->add_option("--out", m.tour.out_dir, "Output directory; default runs/tour-<file>-<time>");

  m.clean_cmd = app.add_subcommand("clean", "Plowing vs Group-k cleaning order on a map: groups, paths, coverage");
  m.clean_cmd->add_option("map", m.clean.map, "Built-in map (clutter, empty, ...), map_server YAML or MovingAI .map")
      ->required();
  m.clean_cmd->add_option("--start", m.clean.start, "Start cell X,Y; default (1, 1) from the top left");
  m.clean_cmd->add_option("--k", m.clean.k, "Group-k's complexity threshold")->capture_default_str();
  m.clean_cmd->add_option("--seed", m.clean.seed, "Seed of Release_Group's random tie-break")->capture_default_str();
  m.clean_cmd->add_option("--sweep", m.clean.sweep, "columns or rows")->capture_default_str();
  m.clean_cmd->add_option("--margin", m.clean.margin, "Widen each group's area by M cells (not in the paper)")
      ->capture_default_str();
  m.clean_cmd->add_option("--out", m.clean.out_dir, "Output directory; default runs/clean-<map>-<time>");

  TourExperimentOptions& te = m.tour_experiment;
  m.tour_exp = experiment.add_subcommand(
      "tour", "Collection tours: NNA vs distance vs distance + angle on the paper's scenarios (offline)");
  m.tour_exp->add_option("--scenarios", te.scenarios, "Tour files; default scenarios/tour/scenario1,2.tour")
      ->delimiter(',');
  m.tour_exp->add_option("--seeds", te.seeds, "GA seeds 1..N per layout")->capture_default_str();
  m.tour_exp->add_option("--layouts", te.layouts, "The file's layout and N - 1 re-scattered ones")->capture_default_str();
  m.tour_exp->add_option("--jobs", te.jobs, "Threads; default the core count");
  m.tour_exp->add_option("--out", te.out_dir, "Experiment directory; default runs/experiment-tour-<time>");

  CleanExperimentOptions& ce = m.clean_experiment;
  m.clean_exp = experiment.add_subcommand("clean", "Plowing vs Group-k: clean area over time (offline)");
  m.clean_exp->add_option("--maps", ce.maps, "Maps; default clutter,empty")->delimiter(',');
  m.clean_exp->add_option("--seeds", ce.seeds, "Starts: 1 = the paper's (1, 1), others random")->capture_default_str();
  m.clean_exp->add_option("--k", ce.k, "Group-k's complexity threshold")->capture_default_str();
  m.clean_exp->add_option("--margin", ce.margin, "Widen each group's area by M cells (not in the paper)")
      ->capture_default_str();
  m.clean_exp->add_option("--jobs", ce.jobs, "Threads; default the core count");
  m.clean_exp->add_option("--out", ce.out_dir, "Experiment directory; default runs/experiment-clean-<time>");

  m.cover_exp = add_task_experiment(experiment, "cover",
                                    "Live coverage makespan vs robots, member<->leader delay and loss; "
                                    "hierarchical vs flat DARP (swarm runs)",
                                    m.cover_experiment);
  m.mapf_live_exp = add_task_experiment(experiment, "mapf-live",
                                        "Live MAPF makespan and conflicts vs member<->leader delay and robots; "
                                        "ECBS vs LaCAM (swarm runs)",
                                        m.mapf_live_experiment);
}

OfflineCommands::~OfflineCommands() = default;

std::optional<int> OfflineCommands::run(std::ostream& out, std::ostream& err) const {
  const Impl& m = *impl_;
  if (m.tour_cmd->parsed()) return tour_command(m.tour, out, err);
  if (m.clean_cmd->parsed()) return clean_command(m.clean, out, err);
  if (m.tour_exp->parsed()) return tour_experiment(m.tour_experiment, out, err);
  if (m.clean_exp->parsed()) return clean_experiment(m.clean_experiment, out, err);
  if (m.cover_exp->parsed()) return task_experiment(m.cover_experiment, out, err);
  if (m.mapf_live_exp->parsed()) return task_experiment(m.mapf_live_experiment, out, err);
  return std::nullopt;
}

}  // namespace swarm::tools
