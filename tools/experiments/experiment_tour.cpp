// `swarm experiment tour`: the three variants of Kim & Lee 2025 on the paper's two scenarios (and
// re-scattered layouts of them), with the paper's GA and with the best order of every run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "experiment.hpp"
#include "offline_common.hpp"
#include "offline_experiments.hpp"
#include "stats.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "text_table.hpp"
#include "tour_file.hpp"
#include "tour_report.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using planner::TourVariant;

constexpr TourVariant kVariants[] = {TourVariant::kNna, TourVariant::kDistance, TourVariant::kDistanceAngle};

// One tour's numbers.
struct Tour {
  double length = 0;
  double rotation = 0;
  double best_length = 0;  // the best order of every run under the same rule (GA rows only)
  double best_rotation = 0;
};

// One job: a layout of a scenario and a GA seed; the best orders once per layout (seed 1).
struct Job {
  std::size_t scenario = 0;
  int layout = 0;
  std::uint64_t seed = 1;
  Tour ga[3];
  Tour best[3];
  std::vector<VariantPlan> plans;  // layout 0, seed 1: for the table and pictures
};

// The file's objects that are not `fixed` moved to other free cells the start can reach (none on
// the start, a destination or another object), drawn by `layout`. Layout 0 is the file itself.
TourFile scattered(const TourFile& file, int layout) {
  if (layout == 0) return file;
  TourFile f = file;
  const auto reach = planner::reachable_mask(f.map, {f.problem.start});
  std::vector<planner::Cell> taken{f.problem.start};
  taken.insert(taken.end(), f.problem.destinations.begin(), f.problem.destinations.end());
  for (std::size_t o = 0; o < f.problem.objects.size(); ++o) {
    if (f.fixed[o]) taken.push_back(f.problem.objects[o].cell);
  }
  std::vector<planner::Cell> cells;
  for (int i = 0; i < static_cast<int>(f.map.size()); ++i) {
    const planner::Cell c = f.map.cell_of(i);
    if (reach[static_cast<std::size_t>(i)] && std::find(taken.begin(), taken.end(), c) == taken.end()) cells.push_back(c);
  }
  planner::Rng rng(planner::mix_seed(0x70u, static_cast<std::uint64_t>(layout)));
  for (std::size_t k = cells.size(); k > 1; --k) std::swap(cells[k - 1], cells[rng.below(k)]);
  std::size_t next = 0;
  for (std::size_t o = 0; o < f.problem.objects.size(); ++o) {
    if (!f.fixed[o] && next < cells.size()) f.problem.objects[o].cell = cells[next++];
  }
  f.unreachable.clear();
  return f;
}

Tour tour_of(const planner::TourPlan& plan) {
  const TourTotals t = tour_totals(plan);
  return {t.length, t.rotation_rad, t.best_length, t.best_rotation_rad};
}

double pct(double v, double ref) { return ref != 0 ? 100.0 * (v / ref - 1) : 0.0; }

std::string mean_std(const std::vector<double>& v, int decimals, const std::string& unit = "") {
  return format_mean_std(summarize(v), decimals) + unit;
}

// Claims on a set of (NNA, distance + angle) pairs.
struct Claim {
  int n = 0;
  int longer = 0;          // distance + angle longer than NNA
  double worst = 0;        // largest length excess, %
  int less_rotation = 0, equal_rotation = 0, more_rotation = 0;
  std::vector<double> dl, dr;  // % vs NNA
  void add(const Tour& nna, const Tour& da) {
    ++n;
    dl.push_back(pct(da.length, nna.length));
    dr.push_back(pct(da.rotation, nna.rotation));
    if (da.length > nna.length + 1e-9) {
      ++longer;
      worst = std::max(worst, dl.back());
    }
    (da.rotation < nna.rotation - 1e-9 ? less_rotation : da.rotation > nna.rotation + 1e-9 ? more_rotation : equal_rotation)++;
  }
  [[nodiscard]] std::string never_longer() const {
    if (longer == 0) return "yes (never longer in " + std::to_string(n) + " tours)";
    return "NO (longer in " + std::to_string(longer) + " of " + std::to_string(n) + " tours, by up to " + fixed(worst, 2) + " %)";
  }
  [[nodiscard]] std::string less_turning() const {
    const Summary s = summarize(dr);
    return std::string(s.mean < 0 ? "yes" : "NO") + " (" + format_mean_std(s, 2) + " % on average; less in " +
           std::to_string(less_rotation) + ", equal in " + std::to_string(equal_rotation) + ", more in " +
           std::to_string(more_rotation) + " of " + std::to_string(n) + " tours)";
  }
  [[nodiscard]] json to_json() const {
    return json{{"tours", n}, {"longer", longer}, {"worst_length_excess_percent", worst},
                {"length_vs_nna_percent", summarize(dl).mean}, {"rotation_vs_nna_percent", summarize(dr).mean},
                {"less_rotation", less_rotation}, {"equal_rotation", equal_rotation}, {"more_rotation", more_rotation}};
  }
};

}  // namespace

int tour_experiment(const TourExperimentOptions& o, std::ostream& out, std::ostream& err) {
  const char* me = "swarm experiment tour";
  std::vector<std::string> paths = o.scenarios;
  if (paths.empty()) {
    for (const char* s : {"scenario1.tour", "scenario2.tour"}) {
      paths.push_back((fs::path(config::data_dir()) / "scenarios" / "tour" / s).string());
    }
  }
  std::vector<TourFile> files;
  std::string dir;
  try {
    if (o.seeds < 1 || o.layouts < 1) throw OfflineBadInput("--seeds and --layouts must be at least 1");
    if (o.jobs < 0) throw OfflineBadInput("--jobs must be at least 1");
    for (const std::string& p : paths) {
      try {
        files.push_back(load_tour_file(p));
      } catch (const TourFileError& e) {
        throw OfflineBadInput(e.what());
      }
      if (!files.back().unreachable.empty()) throw OfflineBadInput(files.back().unreachable.front());
    }
    dir = make_out_dir(o.out_dir, "experiment-tour");
  } catch (const OfflineBadInput& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }

  std::vector<Job> jobs;
  for (std::size_t s = 0; s < files.size(); ++s) {
    for (int l = 0; l < o.layouts; ++l) {
      for (std::int64_t seed = 1; seed <= o.seeds; ++seed) jobs.push_back({s, l, static_cast<std::uint64_t>(seed), {}, {}, {}});
    }
  }
  const std::size_t threads = o.jobs > 0 ? static_cast<std::size_t>(o.jobs) : std::max(1u, std::thread::hardware_concurrency());
  out << me << ": " << files.size() << " scenarios x " << o.layouts << " layouts x " << o.seeds << " GA seeds = "
      << jobs.size() << " jobs of 3 tours, " << threads << " threads\n";
  const auto start_time = std::chrono::steady_clock::now();
  const auto name_of = [&](std::size_t s) { return fs::path(paths[s]).stem().string(); };
  run_jobs(
      jobs.size(), threads,
      [&](std::size_t i) {
        Job& job = jobs[i];
        const TourFile f = scattered(files[job.scenario], job.layout);
        planner::TourOptions options;
        options.seed = job.seed;
        options.compute_reference = true;
        for (int v = 0; v < 3; ++v) {
          options.variant = kVariants[v];
          options.search = planner::TourOptions::Search::kGa;
          planner::TourPlan plan = planner::plan_tour(f.map, f.problem, options);
          job.ga[v] = tour_of(plan);
          if (job.layout == 0 && job.seed == 1) job.plans.push_back({kVariants[v], std::move(plan)});
          if (job.seed == 1) {
            options.search = planner::TourOptions::Search::kExact;
            job.best[v] = tour_of(planner::plan_tour(f.map, f.problem, options));
          }
        }
      },
      [&](std::size_t i, std::size_t done) {
        const Job& j = jobs[i];
        out << "[" << done << "/" << jobs.size() << "] " << name_of(j.scenario) << " layout " << j.layout << " seed "
            << j.seed << ":";
        for (int v = 0; v < 3; ++v) {
          out << " " << planner::variant_name(kVariants[v]) << " " << fixed(j.ga[v].length, 1) << " / "
              << fixed(j.ga[v].rotation, 2) << " rad" << (v < 2 ? "," : "");
        }
        out << "\n" << std::flush;
      });

  // Tables, checks, CSV, JSON.
  ExperimentOutputs outputs;
  std::ostringstream table;
  std::ostringstream csv;
  csv << "scenario,layout,seed,search,variant,length,rotation_rad,best_length,best_rotation_rad,gap_percent,"
         "length_vs_nna_percent,rotation_vs_nna_percent\n";
  json results{{"kind", "tour"}, {"seeds", o.seeds}, {"layouts", o.layouts}, {"scenarios", json::array()}};
  Figure reductions;
  reductions.title = "Collection tours: reduction vs the NNA method (mean ± std; higher is better)";
  reductions.note = "paper: 1.37 / 4.20 % (scenario 1), 1.54 / 5.30 % (scenario 2); below 0 is drawn at 0";
  Figure gaps;
  gaps.title = "The paper's GA: its tours' gap to the best order (mean ± std)";
  BarPanel gap_panel;
  gap_panel.title = "gap to the best order";
  gap_panel.y_label = "length above the best (%)";
  for (int v = 0; v < 3; ++v) gap_panel.series.push_back({variant_title(kVariants[v]), {}, {}, {}});
  const Colour colours[3] = {{213, 94, 0}, {0, 158, 115}, {0, 114, 178}};
  for (int v = 0; v < 3; ++v) gap_panel.series[static_cast<std::size_t>(v)].colour = colours[v];

  for (std::size_t s = 0; s < files.size(); ++s) {
    const TourFile& f = files[s];
    std::vector<const Job*> mine;
    for (const Job& j : jobs) {
      if (j.scenario == s) mine.push_back(&j);
    }
    table << name_of(s) << " (" << f.map_text << "; " << f.problem.objects.size() << " objects of " << f.type_names.size()
          << " types): " << o.layouts << " layouts x " << o.seeds << " GA seeds = " << mine.size() << " tours per variant\n";
    TextTable t({"", "length (cells)", "rotation (rad)", "length vs NNA", "rotation vs NNA", "gap to best", "best found"});
    Claim ga_claim, best_claim, ga_distance_claim;
    json scenario_json{{"file", paths[s]}, {"tours_per_variant", mine.size()}, {"variants", json::array()}};
    for (int search = 0; search < 2; ++search) {
      t.add_section(search == 0 ? "the paper's GA (N 50, G 1000, C 1.0, mu 0.05)" : "the best order of every run (per layout)");
      for (int v = 0; v < 3; ++v) {
        std::vector<double> len, rot, dl, dr, gap;
        int found = 0;
        for (const Job* j : mine) {
          if (search == 1 && j->seed != 1) continue;
          const Tour& tour = search == 0 ? j->ga[v] : j->best[v];
          const Tour& nna = search == 0 ? j->ga[0] : j->best[0];
          len.push_back(tour.length);
          rot.push_back(tour.rotation);
          dl.push_back(pct(tour.length, nna.length));
          dr.push_back(pct(tour.rotation, nna.rotation));
          gap.push_back(pct(tour.length, tour.best_length));
          found += search == 0 && tour.length <= tour.best_length + 1e-9;
          if (v == 2) (search == 0 ? ga_claim : best_claim).add(nna, tour);
          if (v == 1 && search == 0) ga_distance_claim.add(nna, tour);
          csv << name_of(s) << "," << j->layout << "," << (search == 0 ? std::to_string(j->seed) : "") << ","
              << (search == 0 ? "ga" : "exact") << "," << planner::variant_name(kVariants[v]) << "," << fixed(tour.length, 4)
              << "," << fixed(tour.rotation, 4) << "," << (search == 0 ? fixed(tour.best_length, 4) : "") << ","
              << (search == 0 ? fixed(gap.back(), 4) : "") << "," << fixed(dl.back(), 4) << "," << fixed(dr.back(), 4) << "\n";
        }
        const bool nna = v == 0;
        t.add_row({"  " + variant_title(kVariants[v]), mean_std(len, 2), mean_std(rot, 2), nna ? "-" : mean_std(dl, 2, " %"),
                   nna ? "-" : mean_std(dr, 2, " %"),
                   search == 0 ? mean_std(gap, 2, " %") : "-",
                   search == 0 ? std::to_string(found) + "/" + std::to_string(len.size()) : "-"});
        scenario_json["variants"].push_back({{"search", search == 0 ? "ga" : "exact"},
                                             {"variant", planner::variant_name(kVariants[v])},
                                             {"length", summarize(len).mean}, {"length_std", summarize(len).std},
                                             {"rotation_rad", summarize(rot).mean}, {"rotation_std", summarize(rot).std},
                                             {"length_vs_nna_percent", summarize(dl).mean},
                                             {"rotation_vs_nna_percent", summarize(dr).mean},
                                             {"gap_percent", search == 0 ? summarize(gap).mean : 0.0},
                                             {"best_found", found}});
        if (search == 0) {
          gap_panel.series[static_cast<std::size_t>(v)].values.push_back(summarize(gap).mean);
          gap_panel.series[static_cast<std::size_t>(v)].errors.push_back(summarize(gap).std);
        }
      }
    }
    table << t.render();
    table << "checks (the paper: distance + angle never longer than NNA and turning less;\n"
          << "        -1.37 % length / -4.20 % rotation in scenario 1, -1.54 % / -5.30 % in scenario 2):\n"
          << "  distance + angle never longer than NNA, paper's GA:  " << ga_claim.never_longer() << "\n"
          << "  distance never longer than NNA, paper's GA:          " << ga_distance_claim.never_longer() << "\n"
          << "  distance + angle turns less than NNA, paper's GA:    " << ga_claim.less_turning() << "\n"
          << "  distance + angle never longer than NNA, best orders: " << best_claim.never_longer() << "\n"
          << "  distance + angle turns less than NNA, best orders:   " << best_claim.less_turning() << "\n\n";
    scenario_json["checks"] = {{"ga", ga_claim.to_json()}, {"ga_distance", ga_distance_claim.to_json()}, {"best", best_claim.to_json()}};
    results["scenarios"].push_back(scenario_json);
    gap_panel.groups.push_back(name_of(s));

    BarPanel p;
    p.title = name_of(s);
    p.y_label = "reduction vs NNA (%)";
    p.groups = {"length", "rotation"};
    const auto reduction_series = [&](const std::string& label, const Claim& c, Colour colour) {
      const Summary l = summarize(c.dl), r = summarize(c.dr);
      p.series.push_back({label, colour, {-l.mean, -r.mean}, {l.std, r.std}});
    };
    reduction_series("distance (GA)", ga_distance_claim, colours[1]);
    reduction_series("distance + angle (GA)", ga_claim, colours[2]);
    reduction_series("distance + angle (best orders)", best_claim, {120, 60, 160});
    reductions.panels.push_back(p);

    // The paper's table for the file's own layout, GA seed 1, and its pictures.
    for (const Job& j : jobs) {
      if (j.scenario != s || j.layout != 0 || j.seed != 1) continue;
      table << name_of(s) << ", its own layout, GA seed 1 (the paper's Table " << (s == 0 ? 5 : 6) << " layout):\n"
            << leg_table(f, j.plans) << "\n";
      for (const VariantPlan& vp : j.plans) {
        draw_tour_png(f, vp, (fs::path(dir) / ("tour-" + name_of(s) + "-" + planner::variant_name(vp.variant) + ".png")).string());
      }
    }
  }
  gaps.panels.push_back(gap_panel);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  table << "lengths in cells (straight 1, diagonal sqrt 2); " << jobs.size() << " jobs in " << fixed(seconds, 1) << " s\n";
  outputs.table = table.str();
  outputs.csv = csv.str();
  results["seconds"] = seconds;
  outputs.json = results.dump(2) + "\n";
  outputs.figures = {{"tour.png", reductions}, {"tour-gap.png", gaps}};
  return finish_experiment(dir, outputs, me, out, err);
}

}  // namespace swarm::tools
