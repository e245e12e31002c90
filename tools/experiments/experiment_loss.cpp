// `swarm experiment loss`: the same loss probability on every link (sim<->robot,
// member<->leader, leader<->GCS) swept over 0, 5 and 20 %: steps, planning rounds and how many
// runs still complete. Reliable topics retransmit lost messages; scans are best-effort
// (idl/scenario.proto, Link.retransmit_ticks).
#include "experiment_analysis.hpp"
#include "run_command.hpp"

namespace swarm::tools::analysis {

void analyze_loss(const ExperimentPlan& plan, const std::vector<RunRow>& rows, KindOutputs& out) {
  Sweep sw;
  sw.reference_name = "no loss";
  for (double l : plan.losses) {
    sw.settings.push_back(RunSetting::every_link_loss(l));
    sw.columns.push_back(format_number(100.0 * l, 0) + " %");
  }

  std::string text = "Message loss on every link";
  const std::string team = team_text(rows);
  if (!team.empty()) text += ", " + team;
  text += ": mean ± std over " + seeds_text(rows) + "\n" + runs_text(rows) + "\n";

  LinePanel steps_panel;
  steps_panel.title = "Steps vs message loss";
  steps_panel.y_label = "steps";
  steps_panel.x_ticks = sw.columns;
  steps_panel.x_label = "loss probability on every link";
  LinePanel complete_panel = steps_panel;
  complete_panel.title = "Runs that completed";
  complete_panel.y_label = "complete runs (%)";
  complete_panel.y_max = 110;  // ticks up to 100 %, a margin above

  for (const std::string& map : plan.maps) {
    const std::string label = map_label(map);
    Sweep table = sw;
    table.heading = "loss on every link, " + label;
    text += "\n" + sweep_table(table, plan, rows, map, true);
    for (std::size_t mi = 0; mi < plan.methods.size(); ++mi) {
      const std::string& method = plan.methods[mi];
      const std::string name = plan.maps.size() > 1 ? method + " (" + label + ")" : method;
      const Colour colour = method_colour(method, static_cast<int>(mi));
      steps_panel.series.push_back(
          sweep_series(sw, rows, map, method, colour, name, Metric::kSteps));
      PlotSeries complete{name, colour, {}, {}};
      for (std::size_t i = 0; i < sw.settings.size(); ++i) {
        const Cell c = cell_of(rows, map, method, sw.settings[i]);
        complete.values.push_back(c.planned > 0 ? 100.0 * c.complete() / c.planned : 0.0);
        out.aggregates.push_back(
            {{"map", label},
             {"method", method},
             {"loss", plan.losses[i]},
             {"runs", cell_json(c)},
             {"steps", summary_json(summary_of(c, Metric::kSteps))},
             {"steps_vs_no_loss", paired_json(paired_of(c, cell_of(rows, map, method, sw.settings[sw.reference]), Metric::kSteps))},
             {"planning_rounds", summary_json(summary_of(c, Metric::kRounds))},
             {"steps_to_99", summary_json(summary_of(c, Metric::kStepsTo99))}});
      }
      complete_panel.series.push_back(complete);
    }
  }
  text += footnotes(rows);
  out.table = text;
  Figure f = seed_stats_figure("Message loss", rows);
  f.panels.push_back(steps_panel);
  f.panels.push_back(complete_panel);
  out.figures.emplace_back("loss.png", f);
}

}  // namespace swarm::tools::analysis
