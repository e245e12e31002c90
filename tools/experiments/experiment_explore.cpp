// `swarm experiment explore`: the paper's Table 2 (docs/papers.md section 1): steps and planning
// rounds of group-frontier, baseline and ideal on each map, mean ± std over seeds, the percent
// change against the baseline, and the checks the paper's results imply.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "experiment_analysis.hpp"
#include "run_command.hpp"
#include "text_table.hpp"

namespace swarm::tools::analysis {
namespace {

using nlohmann::json;

bool has(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

struct MetricRow {
  Metric metric;
  const char* title;
  const char* key;
  int decimals;
  bool compare;  // percent changes against the baseline (and ideal)
};

constexpr MetricRow kMetrics[] = {
    {Metric::kSteps, "steps (until the GCS declared the map complete)", "steps", 1, true},
    {Metric::kRounds, "planning rounds", "planning_rounds", 1, true},
    {Metric::kStepsTo99, "steps to 99 % explored (ground truth)", "steps_to_99", 1, true},
    {Metric::kExploredPercent, "explored % (ground truth, at the end)", "explored_percent", 1,
     false},
};

// Whether `pred` holds for every value; nullopt when a value is missing (runs failed).
std::optional<bool> all_hold(const std::vector<std::optional<double>>& values,
                             const std::function<bool(double)>& pred) {
  if (values.empty()) return std::nullopt;
  for (const auto& v : values) {
    if (!v) return std::nullopt;
  }
  return std::all_of(values.begin(), values.end(), [&](const auto& v) { return pred(*v); });
}

std::string verdict(const std::optional<bool>& ok) {
  return !ok ? "cannot tell (runs missing)" : *ok ? "yes" : "NO";
}

nlohmann::json verdict_json(const std::optional<bool>& ok) {
  return ok ? nlohmann::json(*ok) : nlohmann::json(nullptr);
}

}  // namespace

void analyze_explore(const ExperimentPlan& plan, const std::vector<RunRow>& rows,
                     KindOutputs& out) {
  const RunSetting none{};
  std::vector<std::string> labels;
  for (const auto& m : plan.maps) labels.push_back(map_label(m));
  const bool with_baseline = has(plan.methods, "baseline");
  const bool with_ideal = has(plan.methods, "ideal");
  auto cell = [&](const std::string& map, const std::string& method) {
    return cell_of(rows, [&](const RunRow& r) {
      return r.run.map == map && r.run.method == method && r.run.setting == none;
    });
  };
  // Percent change of `method` against `reference` on each map, from the means.
  auto changes = [&](Metric m, const std::string& method, const std::string& reference) {
    std::vector<std::optional<double>> v;
    for (const auto& map : plan.maps) {
      v.push_back(percent_change(summary_of(cell(map, method), m).mean,
                                 summary_of(cell(map, reference), m).mean));
    }
    return v;
  };

  std::string text = "Exploration";
  const std::string team = team_text(rows);
  if (!team.empty()) text += ", " + team;
  text += ": mean ± std over " + seeds_text(rows) + "\n" + runs_text(rows) + "\n\n";

  std::vector<std::string> header = {""};
  for (const auto& l : labels) header.push_back(l);
  header.push_back("mean");
  TextTable t(header);
  for (const MetricRow& mr : kMetrics) {
    t.add_section(mr.title);
    for (const auto& method : plan.methods) {
      std::vector<std::string> cells = {"  " + method};
      for (const auto& map : plan.maps) {
        cells.push_back(format_cell(cell(map, method), mr.metric, mr.decimals));
      }
      t.add_row(cells);
    }
    if (!mr.compare) continue;
    // Per map, the mean paired difference over seeds with its 95 % interval ("(n.s.)": it
    // includes 0); the last column, the mean of the per-map changes.
    auto change_row = [&](const std::string& method, const std::string& reference) {
      std::vector<std::string> cells = {"  " + method + " vs " + reference};
      for (const auto& map : plan.maps) {
        cells.push_back(format_paired_pct(paired_of(cell(map, method), cell(map, reference), mr.metric)));
      }
      cells.push_back(format_percent_change(mean_of(changes(mr.metric, method, reference))));
      t.add_row(cells);
    };
    if (with_baseline) {
      for (const auto& method : plan.methods) {
        if (method != "baseline") change_row(method, "baseline");
      }
    }
    if (with_ideal) {
      for (const auto& method : plan.methods) {
        if (method != "ideal" && method != "baseline") change_row(method, "ideal");
      }
    }
  }
  t.add_section("complete runs");
  for (const auto& method : plan.methods) {
    std::vector<std::string> cells = {"  " + method};
    for (const auto& map : plan.maps) cells.push_back(completion_text(cell(map, method)));
    t.add_row(cells);
  }
  text += t.render();
  text += footnotes(rows);

  // Aggregates: one entry per (map, method).
  for (std::size_t i = 0; i < plan.maps.size(); ++i) {
    for (const auto& method : plan.methods) {
      const Cell c = cell(plan.maps[i], method);
      json a = {{"map", labels[i]}, {"method", method}, {"runs", cell_json(c)}};
      for (const MetricRow& mr : kMetrics) {
        a[mr.key] = summary_json(summary_of(c, mr.metric));
        if (mr.compare && with_baseline && method != "baseline") {
          a[std::string(mr.key) + "_change_vs_baseline_percent"] =
              optional_json(changes(mr.metric, method, "baseline")[i]);
          a[std::string(mr.key) + "_paired_vs_baseline"] =
              paired_json(paired_of(c, cell(plan.maps[i], "baseline"), mr.metric));
        }
      }
      out.aggregates.push_back(a);
    }
  }

  // The paper's expectations, checked.
  auto list = [&](const std::vector<std::optional<double>>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) {
      s += (i ? ", " : "") + labels[i] + " " + format_percent_change(v[i]);
    }
    return s;
  };
  const bool gf = has(plan.methods, "group-frontier");
  if (gf && (with_baseline || with_ideal)) {
    text += "\nchecks against the paper (Table 2: steps -16.8 / -41.2 / -14.3 %, rounds -35.7 / "
            "-45.2 / -28.2 % on open / maze1 / maze2):\n";
  }
  if (gf && with_baseline) {
    const auto steps = changes(Metric::kSteps, "group-frontier", "baseline");
    const auto rounds = changes(Metric::kRounds, "group-frontier", "baseline");
    const auto fewer_steps = all_hold(steps, [](double x) { return x < 0; });
    const auto fewer_rounds = all_hold(rounds, [](double x) { return x < 0; });
    text += "  group-frontier needs fewer steps than baseline on every map: " +
            verdict(fewer_steps) + " (" + list(steps) + ")\n";
    text += "  group-frontier needs fewer planning rounds than baseline on every map: " +
            verdict(fewer_rounds) + " (" + list(rounds) + "; mean " +
            format_percent_change(mean_of(rounds)) + ", paper -36.4 %)\n";
    out.findings["fewer_steps_than_baseline_on_every_map"] = verdict_json(fewer_steps);
    out.findings["fewer_rounds_than_baseline_on_every_map"] = verdict_json(fewer_rounds);
    out.findings["steps_change_vs_baseline_mean_percent"] = optional_json(mean_of(steps));
    out.findings["rounds_change_vs_baseline_mean_percent"] = optional_json(mean_of(rounds));
    std::vector<std::optional<double>> maze;
    std::string maze_names;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (labels[i].rfind("maze", 0) == 0) {
        maze.push_back(steps[i]);
        maze_names += (maze_names.empty() ? "" : ", ") + labels[i];
      }
    }
    if (!maze.empty()) {
      const auto m = all_hold(maze, [](double) { return true; }) ? mean_of(maze) : std::nullopt;
      const std::optional<bool> ok = m ? std::optional<bool>(*m <= -25.0) : std::nullopt;
      text += "  group-frontier needs >= 25 % fewer steps than baseline on the maze maps (" +
              maze_names + ", mean of the per-map changes): " + verdict(ok) + " (" +
              format_percent_change(m) + ")\n";
      out.findings["maze_steps_change_vs_baseline_percent"] = optional_json(m);
      out.findings["maze_at_least_25_percent_fewer_steps"] = verdict_json(ok);
    }
  }
  if (gf && with_ideal) {
    const auto v = changes(Metric::kSteps, "group-frontier", "ideal");
    const auto ok = all_hold(v, [](double x) { return x <= 15.0; });
    text += "  group-frontier within 15 % of ideal (no map-fusion delay) steps on every map: " +
            verdict(ok) + " (" + list(v) + ")\n";
    out.findings["within_15_percent_of_ideal_on_every_map"] = verdict_json(ok);
  }
  out.table = text;

  // table2.png: steps and planning rounds, grouped by map, one bar per method.
  auto panel = [&](Metric m, const std::string& title, const std::string& y) {
    BarPanel p;
    p.title = title;
    p.y_label = y;
    p.groups = labels;
    p.x_label = "map";
    for (std::size_t k = 0; k < plan.methods.size(); ++k) {
      PlotSeries s;
      s.name = plan.methods[k];
      s.colour = method_colour(plan.methods[k], static_cast<int>(k));
      for (const auto& map : plan.maps) {
        const Summary sm = summary_of(cell(map, plan.methods[k]), m);
        s.values.push_back(sm.mean);
        s.errors.push_back(sm.std);
      }
      p.series.push_back(s);
    }
    return p;
  };
  Figure f = seed_stats_figure("Exploration", rows);
  if (!team.empty()) f.title += ", " + team;
  f.panels.push_back(panel(Metric::kSteps, "Steps until the map is complete", "steps"));
  f.panels.push_back(panel(Metric::kRounds, "Planning rounds", "planning rounds"));
  out.figures.emplace_back("table2.png", f);
}

}  // namespace swarm::tools::analysis
