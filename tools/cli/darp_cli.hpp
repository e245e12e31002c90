// The flags of `swarm darp` and `swarm experiment darp` (CLI11), kept beside their commands; the
// Commands are add_darp and add_experiment_darp (command.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include "cli_numbers.hpp"
#include "darp_command.hpp"
#include "experiment_darp.hpp"

namespace swarm::tools {

inline CLI::App* add_darp_flags(CLI::App& app, DarpOptions& o) {
  CLI::App* c = app.add_subcommand(
      "darp", "Divide a map among robots (DARP) and plan their coverage paths (STC): a picture and numbers");
  c->add_option("--map", o.map, "Built-in map, map_server YAML or MovingAI .map")->required();
  c->add_option("--robots", o.robots, "Robot cells \"x,y;x,y\" (x = column, y = row from the top)");
  c->add_option("--robots-file", o.robots_file, "One \"x y\" line per robot (as data/darp)");
  c->add_option("--count", o.count, "Place N robots (with --placement and --seed)");
  c->add_option("--placement", o.placement, "spread | bunched")->capture_default_str();
  c->add_option("--seed", o.seed, "Placement and DARP random factors")->capture_default_str();
  c->add_option("--weights", o.weights, "Portions \"1,2,1\" (one per robot); default equal");
  c->add_option("--method", o.method, "auto (DARP, then a repair when it does not converge) | darp (DARP alone)")
      ->capture_default_str();
  c->add_option("--init", o.init, "given | random | kmeans | bfs-kmeans")->capture_default_str();
  c->add_option("--reinit", o.reinit, "bfs-kmeans: selective (paper) | always (paper's tables)")->capture_default_str();
  c->add_option("--distance", o.distance, "euclidean (paper) | geodesic")->capture_default_str();
  c->add_option("--max-iterations", o.max_iterations, "DARP iterations at most")->capture_default_str();
  c->add_option("--time-limit", o.time_limit_s, "Stop DARP after S seconds (0 or inf = none)")
      ->capture_default_str()
      ->check(seconds_or_zero());
  c->add_option("--out", o.out_dir, "Output directory; default runs/darp-<time>");
  return c;
}

inline CLI::App* add_experiment_darp_flags(CLI::App& experiment, DarpExperimentOptions& o) {
  CLI::App* c = experiment.add_subcommand(
      "darp", "DARP initialisations compared (paper's Tables 6-11, Fig. 8/9) and the far-vs-close sweep, offline");
  c->add_option("--seeds", o.seeds, "Seeds (randomised starts) per condition (default 5; --full 10)");
  c->add_option("--robots", o.robots, "Robot counts, e.g. 6,8 (default 6; --full 6,7,8)")->delimiter(',');
  c->add_option("--maps", o.maps, "Maps (default terminal,rectangle)")->delimiter(',');
  c->add_option("--conditions", o.conditions, "bottleneck, entrance, far, near (default all)")->delimiter(',');
  c->add_option("--methods", o.methods, "standalone, random, kmeans, bfs-kmeans, selective "
                                         "(default standalone,kmeans,bfs-kmeans,selective)")->delimiter(',');
  c->add_option("--division", o.division, "auto (DARP, then the repair) | darp (DARP alone: the paper's figures)")
      ->capture_default_str();
  c->add_option("--distance", o.distance, "euclidean (paper) | geodesic")->capture_default_str();
  c->add_option("--max-iterations", o.max_iterations, "I_max")->capture_default_str();
  c->add_option("--sweep-max", o.sweep_max, "Sweep n = 1..N on the rectangle (0 = no sweep)")->capture_default_str();
  c->add_option("--sweep-seeds", o.sweep_seeds, "Seeds per sweep point (default 5; --full 10)");
  c->add_flag("--full", o.full, "The issue's full grid: 6, 7 and 8 robots, 10 seeds (about 30 min of CPU)");
  c->add_option("--jobs", o.jobs, "Runs at once; default the core count");
  c->add_option("--out", o.out_dir, "Experiment directory; default runs/experiment-darp-<time>");
  return c;
}

}  // namespace swarm::tools
