// `swarm experiment latency`: how exploration degrades as the links get slower. Two sweeps that
// share their zero point: the leader<->GCS delay (0, 1/2, 1, 2 and 4 planning intervals) with
// member<->leader at 0, and the member<->leader delay (0, 1, 5, 10 ticks) with leader<->GCS at 0.
#include <cstdio>

#include "experiment_analysis.hpp"
#include "run_command.hpp"

namespace swarm::tools::analysis {
namespace {

std::string intervals(std::uint32_t ticks, std::uint32_t interval) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", interval ? static_cast<double>(ticks) / interval : 0.0);
  return buf;
}

struct LinkSweep {
  std::string link;  // "leader_gcs" | "member_leader"
  Sweep sweep;
  LinePanel panel;
  std::vector<std::uint32_t> delays;
};

std::vector<LinkSweep> link_sweeps(const ExperimentPlan& plan) {
  const std::uint32_t interval = plan.planning_interval_ticks;
  LinkSweep lg;
  lg.link = "leader_gcs";
  lg.sweep.heading = "leader↔GCS delay, ticks (planning intervals)";
  lg.sweep.reference_name = "no delay";
  lg.panel.title = "Leader<->GCS link delay";
  lg.panel.x_label = "delay in planning intervals (" + std::to_string(interval) + " ticks each)";
  for (auto d : plan.leader_gcs_delays_ticks) {
    lg.sweep.settings.push_back(RunSetting::delays(d, 0));
    lg.sweep.columns.push_back(std::to_string(d) + " (" + intervals(d, interval) + ")");
    lg.panel.x_ticks.push_back(intervals(d, interval));
    lg.delays.push_back(d);
  }
  LinkSweep ml;
  ml.link = "member_leader";
  ml.sweep.heading = "member↔leader delay, ticks";
  ml.sweep.reference_name = "no delay";
  ml.panel.title = "Member<->leader link delay";
  ml.panel.x_label = "delay in ticks";
  for (auto d : plan.member_leader_delays_ticks) {
    ml.sweep.settings.push_back(RunSetting::delays(0, d));
    ml.sweep.columns.push_back(std::to_string(d));
    ml.panel.x_ticks.push_back(std::to_string(d));
    ml.delays.push_back(d);
  }
  return {lg, ml};
}

}  // namespace

void analyze_latency(const ExperimentPlan& plan, const std::vector<RunRow>& rows,
                     KindOutputs& out) {
  std::vector<LinkSweep> sweeps = link_sweeps(plan);
  std::string text = "Link latency";
  const std::string team = team_text(rows);
  if (!team.empty()) text += ", " + team;
  text += ": mean ± std over " + seeds_text(rows) + "\n" + runs_text(rows) + "\n";

  for (const std::string& map : plan.maps) {
    const std::string label = map_label(map);
    for (LinkSweep& ls : sweeps) {
      Sweep sw = ls.sweep;
      sw.heading += ", " + label;
      text += "\n" + sweep_table(sw, plan, rows, map, false);
      for (std::size_t mi = 0; mi < plan.methods.size(); ++mi) {
        const std::string& method = plan.methods[mi];
        const std::string name = plan.maps.size() > 1 ? method + " (" + label + ")" : method;
        ls.panel.series.push_back(sweep_series(sw, rows, map, method,
                                               method_colour(method, static_cast<int>(mi)), name,
                                               Metric::kSteps));
        for (std::size_t i = 0; i < sw.settings.size(); ++i) {
          const Cell c = cell_of(rows, map, method, sw.settings[i]);
          out.aggregates.push_back(
              {{"map", label},
               {"method", method},
               {"link", ls.link},
               {"delay_ticks", ls.delays[i]},
               {"runs", cell_json(c)},
               {"steps", summary_json(summary_of(c, Metric::kSteps))},
               {"steps_vs_no_delay", paired_json(paired_of(c, cell_of(rows, map, method, sw.settings[sw.reference]), Metric::kSteps))},
               {"planning_rounds", summary_json(summary_of(c, Metric::kRounds))}});
        }
      }
    }
  }
  text += footnotes(rows);
  out.table = text;
  out.findings["planning_interval_ticks"] = plan.planning_interval_ticks;

  Figure f = seed_stats_figure("Steps vs link delay", rows);
  for (LinkSweep& ls : sweeps) {
    ls.panel.y_label = "steps";
    f.panels.push_back(ls.panel);
  }
  out.figures.emplace_back("latency.png", f);
}

}  // namespace swarm::tools::analysis
