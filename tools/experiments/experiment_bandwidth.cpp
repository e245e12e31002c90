// `swarm experiment bandwidth`: (1) the map-change encodings (scenario map_encoding) compared by
// the bytes of the map topics (patch_up, patch_down, patch_gcs, round) per run and per
// robot-second, and by steps, with no bandwidth cap; (2) a leader<->GCS bandwidth cap swept with
// the base scenario's encoding, steps vs cap. Recommends the smallest encoding that does not slow
// the run.
#include <cmath>

#include "experiment_analysis.hpp"
#include "run_command.hpp"
#include "text_table.hpp"

namespace swarm::tools::analysis {
namespace {

using swarm::scenario::MapEncoding;

// An encoding "slows the run" when, for some map and method, its mean steps exceed the fastest
// encoding's by more than this.
constexpr double kSlowerPercent = 2.0;

RunSetting uncapped(MapEncoding e) { return RunSetting::encoding_and_cap(e, 0.0); }

std::string kilo(const Summary& s) {
  Summary k = s;
  k.mean /= 1000.0;
  k.std /= 1000.0;
  return format_mean_std(k, 1);
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// Part 1's table for one map.
std::string encodings_table(const ExperimentPlan& plan, const std::vector<RunRow>& rows,
                            const std::string& map, KindOutputs& out) {
  const std::string first = plan.encodings.empty() ? "" : encoding_name(plan.encodings.front());
  TextTable t({"map encoding, no cap, " + map_label(map), "map kB / run", "map B / robot-s",
               "vs " + first, "all traffic kB / run", "steps", "complete"});
  for (const auto& method : plan.methods) {
    t.add_section(method);
    const double reference =
        plan.encodings.empty()
            ? NAN
            : summary_of(cell_of(rows, map, method, uncapped(plan.encodings.front())),
                         Metric::kMapBytesPerRobotSecond)
                  .mean;
    for (MapEncoding e : plan.encodings) {
      const Cell c = cell_of(rows, map, method, uncapped(e));
      const Summary per_rs = summary_of(c, Metric::kMapBytesPerRobotSecond);
      t.add_row({"  " + encoding_name(e), kilo(summary_of(c, Metric::kMapBytes)),
                 format_cell(c, Metric::kMapBytesPerRobotSecond, 1),
                 format_percent_change(percent_change(per_rs.mean, reference)),
                 kilo(summary_of(c, Metric::kTrafficBytes)), format_cell(c, Metric::kSteps, 1),
                 completion_text(c)});
      out.aggregates.push_back(
          {{"part", "encoding"},
           {"map", map_label(map)},
           {"method", method},
           {"map_encoding", encoding_name(e)},
           {"runs", cell_json(c)},
           {"map_bytes", summary_json(summary_of(c, Metric::kMapBytes))},
           {"map_bytes_per_robot_second", summary_json(per_rs)},
           {"traffic_bytes", summary_json(summary_of(c, Metric::kTrafficBytes))},
           {"steps", summary_json(summary_of(c, Metric::kSteps))}});
    }
  }
  return t.render();
}

// The smallest mean map traffic per robot-second (over every map and method) among the encodings
// that slow no (map, method) by more than kSlowerPercent and leave no run failed or incomplete.
std::string recommendation(const ExperimentPlan& plan, const std::vector<RunRow>& rows,
                           KindOutputs& out) {
  std::vector<std::string> slow;
  std::optional<MapEncoding> best;
  double best_bytes = 0;
  std::vector<double> means;
  for (MapEncoding e : plan.encodings) {
    bool slower = false;
    std::vector<double> bytes;
    for (const std::string& map : plan.maps) {
      for (const auto& method : plan.methods) {
        double fastest = INFINITY;
        for (MapEncoding other : plan.encodings) {
          const double s =
              summary_of(cell_of(rows, map, method, uncapped(other)), Metric::kSteps).mean;
          if (std::isfinite(s)) fastest = std::min(fastest, s);
        }
        const Cell c = cell_of(rows, map, method, uncapped(e));
        const double steps = summary_of(c, Metric::kSteps).mean;
        if (!std::isfinite(steps) || c.incomplete > 0 || c.failed > 0 || c.ended_early > 0 ||
            steps > fastest * (1.0 + kSlowerPercent / 100.0)) {
          slower = true;
        }
        for (const RunRow* r : c.ok) bytes.push_back(r->numbers->map_bytes_per_robot_second());
      }
    }
    const double mean_bytes = summarize(bytes).mean;
    means.push_back(mean_bytes);
    if (slower) {
      slow.push_back(encoding_name(e));
    } else if (!best || mean_bytes < best_bytes) {
      best = e;
      best_bytes = mean_bytes;
    }
  }
  std::string text;
  if (best) {
    text = "recommended default map_encoding: " + encoding_name(*best) +
           " (the smallest map traffic, " + format_number(best_bytes, 1) +
           " B per robot-second, of the encodings that do not slow the run by more than " +
           format_number(kSlowerPercent, 0) + " % in steps" +
           (slow.empty() ? "" : "; slower, failed or incomplete: " + join(slow)) + ")\n";
    out.findings["recommended_map_encoding"] = encoding_name(*best);
    out.findings["recommended_map_bytes_per_robot_second"] = best_bytes;
  } else {
    text = "no recommended map_encoding: every encoding slowed a run or left runs failed or "
           "incomplete\n";
    out.findings["recommended_map_encoding"] = nullptr;
  }
  const bool all_same = means.size() > 1 && std::isfinite(means.front()) &&
                        std::all_of(means.begin(), means.end(),
                                    [&](double m) { return m == means.front(); });
  if (all_same) {
    text += "note: every encoding sent exactly the same map bytes; does this build implement "
            "map_encoding?\n";
  }
  out.findings["slower_encodings"] = slow;
  out.findings["slower_threshold_percent"] = kSlowerPercent;
  return text;
}

}  // namespace

void analyze_bandwidth(const ExperimentPlan& plan, const std::vector<RunRow>& rows,
                       KindOutputs& out) {
  std::string text = "Bandwidth";
  const std::string team = team_text(rows);
  if (!team.empty()) text += ", " + team;
  text += ": mean ± std over " + seeds_text(rows) + "\n" + runs_text(rows) + "\n" +
          "map traffic = bytes sent on patch_up, patch_down, patch_gcs and round; per "
          "robot-second = / (robots x ticks run x tick_seconds)\n";
  for (const std::string& map : plan.maps) text += "\n" + encodings_table(plan, rows, map, out);
  text += "\n" + recommendation(plan, rows, out);

  // Part 2: the cap sweep, "unlimited" (0) as the reference.
  Sweep sw;
  sw.reference_name = "unlimited";
  for (double c : plan.leader_gcs_caps_bytes_per_s) {
    if (c <= 0) sw.reference = sw.settings.size();
    sw.settings.push_back(RunSetting::encoding_and_cap(plan.cap_encoding, c));
    sw.columns.push_back(format_rate(c));
  }
  LinePanel caps;
  caps.title = "Steps vs leader<->GCS bandwidth cap";
  caps.y_label = "steps";
  caps.x_ticks = sw.columns;
  caps.x_label = "leader<->GCS cap (" + encoding_name(plan.cap_encoding) + ")";
  BarPanel bytes;
  bytes.title = "Map traffic by encoding (no cap)";
  bytes.y_label = "map bytes per robot-second";
  bytes.x_label = "map_encoding";
  for (MapEncoding e : plan.encodings) bytes.groups.push_back(encoding_name(e));
  Sweep by_encoding;
  for (MapEncoding e : plan.encodings) by_encoding.settings.push_back(uncapped(e));

  for (const std::string& map : plan.maps) {
    const std::string label = map_label(map);
    Sweep table = sw;
    table.heading = "leader↔GCS cap, " + encoding_name(plan.cap_encoding) + ", " + label;
    text += "\n" + sweep_table(table, plan, rows, map, false);
    for (std::size_t mi = 0; mi < plan.methods.size(); ++mi) {
      const std::string& method = plan.methods[mi];
      const std::string name = plan.maps.size() > 1 ? method + " (" + label + ")" : method;
      const Colour colour = method_colour(method, static_cast<int>(mi));
      caps.series.push_back(sweep_series(sw, rows, map, method, colour, name, Metric::kSteps));
      bytes.series.push_back(sweep_series(by_encoding, rows, map, method, colour, name,
                                          Metric::kMapBytesPerRobotSecond));
      for (const RunSetting& s : sw.settings) {
        const Cell c = cell_of(rows, map, method, s);
        out.aggregates.push_back(
            {{"part", "cap"},
             {"map", label},
             {"method", method},
             {"map_encoding", encoding_name(plan.cap_encoding)},
             {"leader_gcs_bandwidth_bytes_per_s", *s.leader_gcs_bandwidth_bytes_per_s},
             {"runs", cell_json(c)},
             {"steps", summary_json(summary_of(c, Metric::kSteps))},
             {"planning_rounds", summary_json(summary_of(c, Metric::kRounds))}});
      }
    }
  }
  text += footnotes(rows);
  out.table = text;
  Figure f = seed_stats_figure("Bandwidth", rows);
  f.panels.push_back(bytes);
  f.panels.push_back(caps);
  out.figures.emplace_back("bandwidth.png", f);
}

}  // namespace swarm::tools::analysis
