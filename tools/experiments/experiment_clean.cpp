// `swarm experiment clean`: plowing against Group-k (Jeon, Jo & Noh 2006) on the cluttered and the
// empty room, from several starts.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "clean_report.hpp"
#include "experiment.hpp"
#include "named_map.hpp"
#include "offline_common.hpp"
#include "offline_experiments.hpp"
#include "stats.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Job {
  std::size_t map = 0;
  std::uint64_t seed = 1;
  CleanRun run;
  double largest_gap = 0;  // max over time of |plowing - Group-k| clean fraction
};

// Seed 1: the paper's start; others: a free cell drawn by the seed.
planner::Cell start_for(const planner::OccupancyGrid& map, std::uint64_t seed) {
  if (seed == 1) return *top_left_start(map);
  std::vector<planner::Cell> free;
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (map.at(i) == planner::CellState::Free) free.push_back(map.cell_of(i));
  }
  planner::Rng rng(planner::mix_seed(0xc1ea, seed));
  return free[rng.below(free.size())];
}

double largest_gap(const CleanRun& r) {
  double gap = 0;
  for (const auto* curve : {&r.plow_curve, &r.group_k_curve}) {
    for (const auto& s : curve->samples) {
      gap = std::max(gap, std::abs(r.plow_curve.fraction_at(s.time_s) - r.group_k_curve.fraction_at(s.time_s)));
    }
  }
  return gap;
}

}  // namespace

int clean_experiment(const CleanExperimentOptions& o, std::ostream& out, std::ostream& err) {
  const char* me = "swarm experiment clean";
  const std::vector<std::string> names = o.maps.empty() ? std::vector<std::string>{"clutter", "empty"} : o.maps;
  std::vector<planner::OccupancyGrid> maps;
  std::string dir;
  try {
    if (o.seeds < 1) throw OfflineBadInput("--seeds must be at least 1");
    if (o.jobs < 0) throw OfflineBadInput("--jobs must be at least 1");
    if (!(o.k > 0 && o.k <= 1)) throw OfflineBadInput("--k must be in (0, 1] (the paper: 0.5)");
    if (o.margin < 0) throw OfflineBadInput("--margin must be 0 or more cells");
    for (const std::string& n : names) {
      try {
        maps.push_back(load_named_map(n));
      } catch (const std::runtime_error& e) {
        throw OfflineBadInput(e.what());
      }
      if (!top_left_start(maps.back())) throw OfflineBadInput("map '" + n + "' has no free cell");
    }
    dir = make_out_dir(o.out_dir, "experiment-clean");
  } catch (const OfflineBadInput& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }

  std::vector<Job> jobs;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    for (std::int64_t s = 1; s <= o.seeds; ++s) jobs.push_back({m, static_cast<std::uint64_t>(s), {}, 0});
  }
  const std::size_t threads = o.jobs > 0 ? static_cast<std::size_t>(o.jobs) : std::max(1u, std::thread::hardware_concurrency());
  out << me << ": " << maps.size() << " maps x " << o.seeds << " starts = " << jobs.size() << " jobs, " << threads << " threads\n";
  const auto t0 = std::chrono::steady_clock::now();
  run_jobs(
      jobs.size(), threads,
      [&](std::size_t i) {
        Job& j = jobs[i];
        const planner::OccupancyGrid& map = maps[j.map];
        planner::GroupKConfig config;
        config.k = o.k;
        config.seed = j.seed;
        config.area_margin = o.margin;
        planner::CoverageTimeModel model;
        model.cell_m = map.resolution();
        j.run = run_clean(map, start_for(map, j.seed), config, model);
        j.largest_gap = largest_gap(j.run);
      },
      [&](std::size_t i, std::size_t done) {
        const Job& j = jobs[i];
        out << "[" << done << "/" << jobs.size() << "] " << names[j.map] << " seed " << j.seed << " start ("
            << j.run.start.x << ", " << j.run.start.y << "): plowing " << fixed(j.run.plow_curve.total_time_s, 0)
            << " s, Group-k " << fixed(j.run.group_k_curve.total_time_s, 0) << " s, Group-k at plowing's 45 %: "
            << fixed(100 * j.run.group_k_when_plow_at(0.45).value_or(0), 1) << " %\n"
            << std::flush;
      });

  std::ostringstream table;
  std::ostringstream csv;
  csv << "map,seed,start_x,start_y,groups,grouped_percent,plow_time_s,group_k_time_s,plow_t50_s,group_k_t50_s,"
         "plow_t90_s,group_k_t90_s,group_k_at_plow_40,group_k_at_plow_45,group_k_at_plow_50,largest_gap_percent\n";
  json results{{"kind", "clean"}, {"seeds", o.seeds}, {"k", o.k}, {"maps", json::array()}};
  std::vector<std::pair<std::string, const CleanRun*>> seed_one;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    std::vector<double> plow_t, gk_t, finish, at40, at45, at50, grouped, groups, gap, plow50, gk50, slack45;
    for (const Job& j : jobs) {
      if (j.map != m) continue;
      const CleanRun& r = j.run;
      const double free = r.plow_curve.region_cells;
      plow_t.push_back(r.plow_curve.total_time_s);
      gk_t.push_back(r.group_k_curve.total_time_s);
      finish.push_back(100.0 * (r.group_k_curve.total_time_s / r.plow_curve.total_time_s - 1));
      at40.push_back(100 * r.group_k_when_plow_at(0.40).value_or(0));
      at45.push_back(100 * r.group_k_when_plow_at(0.45).value_or(0));
      at50.push_back(100 * r.group_k_when_plow_at(0.50).value_or(0));
      grouped.push_back(100.0 * r.grouped_cells / free);
      groups.push_back(static_cast<double>(r.grouping.groups.size()));
      gap.push_back(100 * j.largest_gap);
      plow50.push_back(r.plow_curve.time_to(0.5).value_or(0));
      // The fastest any robot can clean 45 %: one new cell per step, never turning.
      planner::CoverageTimeModel model;
      model.cell_m = maps[m].resolution();
      const double bound45 = (std::ceil(0.45 * free) - 1) * model.step_s();
      slack45.push_back(r.plow_curve.time_to(0.45).value_or(0) / bound45);
      gk50.push_back(r.group_k_curve.time_to(0.5).value_or(0));
      csv << names[m] << "," << j.seed << "," << r.start.x << "," << r.start.y << "," << r.grouping.groups.size() << ","
          << fixed(grouped.back(), 2) << "," << fixed(plow_t.back(), 2) << "," << fixed(gk_t.back(), 2) << ","
          << fixed(plow50.back(), 2) << "," << fixed(gk50.back(), 2) << "," << fixed(r.plow_curve.time_to(0.9).value_or(0), 2)
          << "," << fixed(r.group_k_curve.time_to(0.9).value_or(0), 2) << "," << fixed(at40.back(), 2) << ","
          << fixed(at45.back(), 2) << "," << fixed(at50.back(), 2) << "," << fixed(gap.back(), 2) << "\n";
      if (j.seed == 1) {
        seed_one.emplace_back(names[m], &j.run);
        table << names[m] << ", seed 1 (the paper's start):\n" << grouping_text(maps[m], r) << "\n";
        draw_groups_png(maps[m], r.grouping, r.grouping.groups, r.grouping.order,
                        names[m] + ": " + std::to_string(r.grouping.groups.size()) + " groups, #: cleaning order",
                        (fs::path(dir) / ("groups-" + names[m] + ".png")).string());
        draw_path_png(maps[m], r, true, (fs::path(dir) / ("group-k-" + names[m] + ".png")).string());
        draw_path_png(maps[m], r, false, (fs::path(dir) / ("plow-" + names[m] + ".png")).string());
      }
    }
    TextTable t({names[m] + " (" + std::to_string(o.seeds) + " starts)", "plowing", "Group-k"});
    t.add_row({"time to clean everything (s)", format_mean_std(summarize(plow_t), 1), format_mean_std(summarize(gk_t), 1)});
    t.add_row({"time to 50 % (s)", format_mean_std(summarize(plow50), 1), format_mean_std(summarize(gk50), 1)});
    t.add_row({"clean when plowing has 40 %", "40.0", format_mean_std(summarize(at40), 1)});
    t.add_row({"clean when plowing has 45 %", "45.0", format_mean_std(summarize(at45), 1)});
    t.add_row({"clean when plowing has 50 %", "50.0", format_mean_std(summarize(at50), 1)});
    t.add_row({"groups / free cells in groups (%)", "-", format_mean_std(summarize(groups), 1) + " / " + format_mean_std(summarize(grouped), 1)});
    table << t.render();
    const Summary s45 = summarize(at45), g = summarize(gap), f = summarize(finish);
    const bool has_groups = summarize(groups).mean > 0;
    table << "checks:\n";
    if (has_groups) {
      const bool clearly = summarize(at40).mean >= 50 && summarize(at50).mean >= 60;
      table << "  Group-k clearly ahead when plowing is at 40-50 % (>= 10 points; the paper: 80-90 %): "
            << (clearly ? "yes" : "NO") << " (" << format_mean_std(summarize(at40), 1) << " / " << format_mean_std(s45, 1)
            << " / " << format_mean_std(summarize(at50), 1) << " % at plowing's 40 / 45 / 50 %)\n"
            << "  Group-k finishes sooner (the paper's body: -19.66 %; its abstract: later): "
            << (f.mean < 0 ? "yes" : "NO") << " (" << format_mean_std(f, 1) << " % time)\n"
            << "  why: the final groups' areas hold " << format_mean_std(summarize(grouped), 1)
            << " % of the free cells (all that Group-k puts off);\n"
            << "       plowing reaches 45 % in " << format_mean_std(summarize(slack45), 2)
            << " x the least time any robot needs (one new cell per step, no turn), and for\n"
            << "       Group-k to be at 80 % by then it would have to be at least 80 / 45 = 1.78 x\n";
    } else {
      table << "  no obstacle groups: Group-k and plowing equal (the paper): " << (g.mean == 0 && g.std == 0 ? "yes" : "NO")
            << " (largest difference of the clean area at any time: " << fixed(std::max(g.mean, g.mean + g.std), 2) << " %)\n";
    }
    table << "\n";
    results["maps"].push_back({{"map", names[m]}, {"plow_time_s", summarize(plow_t).mean}, {"group_k_time_s", summarize(gk_t).mean},
                               {"group_k_vs_plow_time_percent", f.mean}, {"group_k_at_plow_40", summarize(at40).mean},
                               {"group_k_at_plow_45", s45.mean}, {"group_k_at_plow_50", summarize(at50).mean},
                               {"grouped_percent", summarize(grouped).mean}, {"groups", summarize(groups).mean},
                               {"largest_gap_percent", g.mean}, {"plow_time_to_45_over_least", summarize(slack45).mean}});
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  table << "time model: 0.17 m/s, a cell = the map's resolution, 90 deg turn 1 s, 180 deg 2 s; " << jobs.size()
        << " jobs in " << fixed(seconds, 1) << " s\n";
  ExperimentOutputs outputs;
  outputs.table = table.str();
  outputs.csv = csv.str();
  results["seconds"] = seconds;
  outputs.json = results.dump(2) + "\n";
  outputs.figures = {{"coverage.png", coverage_figure(seed_one, "Clean area over time, seed 1 (the paper's start)")}};
  return finish_experiment(dir, outputs, me, out, err);
}

}  // namespace swarm::tools
