// The flags of `swarm mapf` and `swarm experiment mapf` (CLI11), kept beside their commands; the
// Commands are add_mapf and add_experiment_mapf (command.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <memory>

#include "cli_numbers.hpp"
#include "experiment_mapf.hpp"
#include "mapf_command.hpp"

namespace swarm::tools {

// GA flags shared by both commands (the parameters the paper does not give: ga.hpp); each sets
// its option only when given, so the options' own defaults stand otherwise.
struct GaFlags {
  int population = 0, g1 = 0, g2 = 0, elite = 0, idle = 0;
  double crossover = 0, mutation = 0;
  CLI::Option *pop_opt = nullptr, *g1_opt = nullptr, *g2_opt = nullptr, *elite_opt = nullptr, *idle_opt = nullptr,
              *cross_opt = nullptr, *mut_opt = nullptr;

  void add_to(CLI::App* c) {
    pop_opt = c->add_option("--ga-population", population, "GA: chromosomes per generation (default 100)")->check(number(config::kPositive));
    g1_opt = c->add_option("--ga-generations1", g1, "GA: stage-1 generations (paper: 500)")->check(number(config::kNonNegative));
    g2_opt = c->add_option("--ga-generations2", g2, "GA: stage-2 generations (paper: 500)")->check(number(config::kNonNegative));
    elite_opt = c->add_option("--ga-elite", elite, "GA: best chromosomes kept each generation (default 1)")->check(number(config::kNonNegative));
    idle_opt = c->add_option("--ga-initial-idle", idle, "GA: initial idle genes uniform in [0, N] (default 1)")->check(number(config::kNonNegative));
    cross_opt = c->add_option("--ga-crossover", crossover, "GA: crossover probability (default 0.9)")->check(number({0.0, 1.0}));
    mut_opt = c->add_option("--ga-mutation", mutation, "GA: mutation probability per child (default 0.2)")->check(number({0.0, 1.0}));
  }
  // MapfOptions or MapfExperimentOptions: their ga_* fields.
  template <class Options>
  void apply(Options& o) const {
    if (pop_opt->count()) o.ga_population = population;
    if (g1_opt->count()) o.ga_generations1 = g1;
    if (g2_opt->count()) o.ga_generations2 = g2;
    if (elite_opt->count()) o.ga_elite = elite;
    if (idle_opt->count()) o.ga_initial_idle = idle;
    if (cross_opt->count()) o.ga_crossover = crossover;
    if (mut_opt->count()) o.ga_mutation = mutation;
  }
};

struct MapfCli {
  MapfOptions options;
  CLI::App* command = nullptr;
  int agents = 0, random = 0;
  CLI::Option *agents_opt = nullptr, *random_opt = nullptr;
  GaFlags ga;

  [[nodiscard]] MapfOptions resolved() const {
    MapfOptions o = options;
    if (agents_opt->count()) o.agents = agents;
    if (random_opt->count()) o.random = random;
    ga.apply(o);
    return o;
  }
};

inline std::unique_ptr<MapfCli> add_mapf_cli(CLI::App& app) {
  auto cli = std::make_unique<MapfCli>();
  MapfOptions& o = cli->options;
  CLI::App* c = app.add_subcommand("mapf", "Multi-agent path finding on one instance: CBS, ECBS, LaCAM*, the paper's GA");
  cli->command = c;
  CLI::Option* map = c->add_option("--map", o.map, "MovingAI .map, map_server YAML, built-in name, or warehouse-RxC (the paper's 5x8 world: warehouse-5x8)");
  CLI::Option* scen = c->add_option("--scen", o.scen, "MovingAI .scen file (with --agents K: its first K rows)");
  cli->agents_opt = c->add_option("--agents", cli->agents, "Number of agents taken from --scen")->check(number(config::kPositive));
  cli->random_opt = c->add_option("--random", cli->random, "K random agents (distinct random free cells / intersections)")->check(number(config::kPositive));
  c->add_option("--graph", o.graph, "A graph and its agents instead of --map: lines `vertices N`, `edge U V`, `agent START GOAL` (planner/mapf/graph_file.hpp)")
      ->excludes(map)
      ->excludes(scen)
      ->excludes(cli->agents_opt)
      ->excludes(cli->random_opt);
  c->add_option("--seed", o.seed, "Seed of the random instance and of the solver")->capture_default_str();
  c->add_option("--solver", o.solver, "cbs | ecbs | lacam | ga | ga1 (single-stage GA)")->capture_default_str();
  c->add_option("--w", o.w, "ECBS suboptimality bound (>= 1)")->capture_default_str()->check(number({1.0}));
  c->add_option("--time-limit", o.time_limit_s, "Seconds before the solver stops with its best plan (inf: none)")
      ->capture_default_str()
      ->check(seconds());
  c->add_option("--out", o.out_dir, "Output directory; default runs/mapf-<time>");
  c->add_flag("--standard-rules", o.standard_rules, "On a warehouse map: MovingAI rules (stay on goals, wait anywhere) instead of the paper's");
  c->add_flag("--last-node-on-timeout", o.last_node_on_timeout, "CBS/ECBS: on timeout return the last CT node explored (the paper's rule)");
  c->add_flag("--refine", o.refine, "LaCAM*: improve the sum of costs until the time limit");
  c->add_option("--scale", o.scale, "Pixels per cell in pictures (default: fit ~900 pixels)")->check(number(config::kNonNegative));
  cli->ga.add_to(c);
  return cli;
}

struct ExperimentMapfCli {
  MapfExperimentOptions options;
  CLI::App* command = nullptr;
  GaFlags ga;

  [[nodiscard]] MapfExperimentOptions resolved() const {
    MapfExperimentOptions o = options;
    ga.apply(o);
    return o;
  }
};

inline std::unique_ptr<ExperimentMapfCli> add_experiment_mapf_cli(CLI::App* experiment) {
  auto cli = std::make_unique<ExperimentMapfCli>();
  MapfExperimentOptions& o = cli->options;
  CLI::App* c = experiment->add_subcommand(
      "mapf", "MAPF solvers offline: the paper's Tables 1-2 on warehouse-5x8, and success / cost vs agents on MovingAI maps");
  cli->command = c;
  c->add_option("--part", o.part, "paper | movingai | all")->capture_default_str();
  c->add_option("--world", o.warehouse, "(a) the paper's world, warehouse-RxC")->capture_default_str();
  c->add_option("--robots", o.robots, "(a) robot counts, comma-separated")->delimiter(',');
  c->add_option("--runs", o.runs, "(a) random instances per robot count (paper: 100)")->capture_default_str();
  c->add_option("--cbs-limit", o.cbs_limit_s, "(a) seconds per solve, CBS's limit (paper: 600)")->capture_default_str()->check(seconds());
  c->add_option("--paper-solvers", o.paper_solvers, "(a) solvers, comma-separated")->delimiter(',');
  c->add_option("--movingai", o.movingai_dir, "(b) folder of MovingAI .map and -random-N.scen files")->capture_default_str();
  c->add_option("--maps", o.maps, "(b) map names (file stems), comma-separated; default every .map there")->delimiter(',');
  c->add_option("--agents", o.agents, "(b) agent counts, comma-separated")->delimiter(',');
  c->add_option("--scenarios", o.scenarios, "(b) scenarios random-1..N per map")->capture_default_str();
  c->add_option("--time-limit", o.time_limit_s, "(b) seconds per solve")->capture_default_str()->check(seconds());
  c->add_option("--solvers", o.movingai_solvers, "(b) solvers, comma-separated")->delimiter(',');
  c->add_option("--w", o.w, "ECBS suboptimality bound")->capture_default_str()->check(number({1.0}));
  c->add_option("--jobs", o.jobs, "Solves at once (each on one core)")->capture_default_str();
  c->add_option("--seed", o.seed, "(a) instance r uses seed + r")->capture_default_str();
  c->add_option("--out", o.out_dir, "Output directory; default runs/experiment-mapf-<time>");
  cli->ga.add_to(c);
  return cli;
}

}  // namespace swarm::tools
