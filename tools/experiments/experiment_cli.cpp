// `swarm experiment KIND`: every experiment's flags and command (command.hpp: the pattern).
#include <CLI/CLI.hpp>

#include <array>
#include <memory>

#include "cli_numbers.hpp"
#include "command.hpp"
#include "darp_cli.hpp"
#include "experiment.hpp"
#include "experiment_command.hpp"
#include "experiment_mission.hpp"
#include "experiment_tasks.hpp"
#include "mapf_cli.hpp"
#include "offline_experiments.hpp"

namespace swarm::tools {

std::vector<Command> add_swarm_experiments(CLI::App& experiment) {
  // One subcommand per kind, the same flags on each; --seeds and --jobs count only when given.
  struct Flags {
    ExperimentOptions options;
    std::int64_t seeds = 0, jobs = 0;
    long timeout_s = 0;
    CLI::Option *seeds_opt = nullptr, *jobs_opt = nullptr;
  };
  const std::array<std::pair<ExperimentKind, const char*>, 4> kinds = {{
      {ExperimentKind::kExplore,
       "Paper's Table 2: group-frontier vs baseline vs ideal on open, maze1, maze2 (8 seeds)"},
      {ExperimentKind::kLatency,
       "Steps vs leader<->GCS and member<->leader link delay (maze1, 3 seeds)"},
      {ExperimentKind::kBandwidth,
       "Map-change encodings' bytes, and steps vs a leader<->GCS bandwidth cap (maze1, 3 seeds)"},
      {ExperimentKind::kLoss, "Steps and completion vs message loss on every link (maze1, 3 seeds)"},
  }};
  std::vector<Command> out;
  for (const auto& [kind, what] : kinds) {
    auto f = std::make_shared<Flags>();
    ExperimentOptions& e = f->options;
    e.kind = kind;
    f->timeout_s = static_cast<long>(e.timeout.count());
    CLI::App* c = experiment.add_subcommand(kind_name(e.kind), what);
    f->seeds_opt = c->add_option("--seeds", f->seeds,
                                 "Number of seeds (seeds 1..N); default " + std::to_string(default_seeds(e.kind)));
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
    f->jobs_opt = c->add_option("--jobs", f->jobs, "Runs at once; default the core count");
    c->add_option("--out", e.out_dir,
                  "Experiment directory; default runs/experiment-" + kind_name(e.kind) + "-<time>");
    c->add_option("--scenario", e.scenario_path,
                  "Base scenario file; default DATA/scenarios/default.pbtxt");
    c->add_option("--timeout", f->timeout_s,
                  "Wall-clock limit per run in seconds (0 = none); a stuck run fails")
        ->capture_default_str()
        ->check(wall_seconds());
    if (kind != ExperimentKind::kExplore) {
      c->add_option("--mission", e.mission,
                    "The phases every run drives, e.g. explore,cover,mapf,collect (default: the scenario's); the "
                    "tables then give the whole mission's ticks, conflicts and delivered objects")
          ->delimiter(',');
    }
    if (kind == ExperimentKind::kBandwidth) {
      c->add_option("--encodings", e.encodings, "Map encodings compared uncapped; default RAW_CELLS,RUN_LENGTH,ZSTD_RUN_LENGTH")
          ->delimiter(',');
      c->add_option("--cap-links", e.cap_links, "Link classes capped, one at a time; default leader_gcs,member_leader")
          ->delimiter(',');
      c->add_option("--cap-bases", e.cap_bases,
                    "What the caps are shares of: mean (over the run) and/or peak (busiest second); default mean,peak")
          ->delimiter(',');
      c->add_option("--cap-fractions", e.cap_fractions, "Shares of the demand per sender; default 2,1,0.5,0.25,0.125")
          ->delimiter(',');
      c->add_option("--caps", e.caps,
                    "Absolute leader<->GCS caps in bytes/s instead (0 = unlimited), e.g. 4000,16000,0")
          ->delimiter(',');
    }
    out.push_back({c, [f](std::ostream& o, std::ostream& err) {
                     ExperimentOptions e = f->options;
                     if (f->seeds_opt->count()) e.seeds = f->seeds;
                     if (f->jobs_opt->count()) e.jobs = f->jobs;
                     e.timeout = std::chrono::seconds(f->timeout_s);
                     return experiment_command(e, o, err);
                   }});
  }
  return out;
}

Command add_experiment_mapf(CLI::App& experiment) {
  std::shared_ptr<ExperimentMapfCli> cli = add_experiment_mapf_cli(&experiment);
  return {cli->command,
          [cli](std::ostream& out, std::ostream& err) { return experiment_mapf_command(cli->resolved(), out, err); }};
}

Command add_experiment_darp(CLI::App& experiment) {
  auto o = std::make_shared<DarpExperimentOptions>();
  CLI::App* c = add_experiment_darp_flags(experiment, *o);
  return {c, [o](std::ostream& out, std::ostream& err) { return experiment_darp_command(*o, out, err); }};
}

Command add_experiment_tour(CLI::App& experiment) {
  auto o = std::make_shared<TourExperimentOptions>();
  CLI::App* c = experiment.add_subcommand(
      "tour", "Collection tours: NNA vs distance vs distance + angle on the paper's scenarios (offline)");
  c->add_option("--scenarios", o->scenarios, "Tour files; default scenarios/tour/scenario1,2.tour")
      ->delimiter(',');
  c->add_option("--seeds", o->seeds, "GA seeds 1..N per layout")->capture_default_str();
  c->add_option("--layouts", o->layouts, "The file's layout and N - 1 re-scattered ones")->capture_default_str();
  c->add_option("--jobs", o->jobs, "Threads; default the core count");
  c->add_option("--out", o->out_dir, "Experiment directory; default runs/experiment-tour-<time>");
  return {c, [o](std::ostream& out, std::ostream& err) { return tour_experiment(*o, out, err); }};
}

Command add_experiment_clean(CLI::App& experiment) {
  auto o = std::make_shared<CleanExperimentOptions>();
  CLI::App* c = experiment.add_subcommand("clean", "Plowing vs Group-k: clean area over time (offline)");
  c->add_option("--maps", o->maps, "Maps; default clutter,empty")->delimiter(',');
  c->add_option("--seeds", o->seeds, "Starts: 1 = the paper's (1, 1), others random")->capture_default_str();
  c->add_option("--k", o->k, "Group-k's complexity threshold")->capture_default_str();
  c->add_option("--margin", o->margin, "Widen each group's area by M cells (not in the paper)")
      ->capture_default_str();
  c->add_option("--jobs", o->jobs, "Threads; default the core count");
  c->add_option("--out", o->out_dir, "Experiment directory; default runs/experiment-clean-<time>");
  return {c, [o](std::ostream& out, std::ostream& err) { return clean_experiment(*o, out, err); }};
}

Command add_task_experiment(CLI::App& experiment, const char* task, const char* what) {
  auto o = std::make_shared<TaskExperimentOptions>();
  o->task = task;
  CLI::App* c = experiment.add_subcommand(task, what);
  c->add_option("--map", o->map, "Built-in map or map_server YAML")->capture_default_str();
  c->add_option("--seeds", o->seeds, "Seeds 1..N per point and variant")->capture_default_str();
  c->add_option("--jobs", o->jobs, "Runs at once")->capture_default_str();
  c->add_option("--timeout", o->timeout_s, "Wall-clock limit per run in seconds")->capture_default_str()->check(wall_seconds());
  c->add_option("--out", o->out_dir, std::string("Experiment directory; default runs/experiment-") + task + "-<time>");
  c->add_flag("--quick", o->quick, "Only the first two points of the first sweep (a smoke test)");
  return {c, [o](std::ostream& out, std::ostream& err) { return task_experiment(*o, out, err); }};
}

Command add_experiment_mission(CLI::App& experiment) {
  auto o = std::make_shared<MissionExperimentOptions>();
  CLI::App* c = experiment.add_subcommand(
      "mission", "The chained mission on every built-in map: ticks, ratio to a bound, conflicts, blocks per phase "
                 "(swarm runs)");
  c->add_option("--maps", o->maps, "Built-in maps, map_server YAML or MovingAI .map files; default every built-in map")
      ->delimiter(',');
  c->add_option("--mission", o->mission, "The phases, in order")->delimiter(',')->capture_default_str();
  c->add_option("--links", o->links, "Link settings: base, delay (member<->leader 3 ± 2 ticks), loss (5 % everywhere)")
      ->delimiter(',')
      ->capture_default_str();
  c->add_option("--robots", o->robots, "Teams, GROUPSxROBOTS_PER_GROUP")->delimiter(',')->capture_default_str();
  c->add_option("--seeds", o->seeds, "Seeds 1..N per map, setting and team")->capture_default_str();
  c->add_option("--jobs", o->jobs, "Runs at once")->capture_default_str();
  c->add_option("--timeout", o->timeout_s, "Wall-clock limit per run in seconds")->capture_default_str()->check(wall_seconds());
  c->add_option("--out", o->out_dir, "Experiment directory; default runs/experiment-mission-<time>");
  c->add_flag("--quick", o->quick, "small, seed 1, exact links only (a smoke test)");
  return {c, [o](std::ostream& out, std::ostream& err) { return mission_experiment(*o, out, err); }};
}

}  // namespace swarm::tools
