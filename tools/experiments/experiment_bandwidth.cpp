// `swarm experiment bandwidth`: (1) the map-change encodings (scenario map_encoding) compared by
// the bytes of the map topics (patch_up, patch_down, patch_gcs, round) per run and per
// robot-second, and by steps, with no bandwidth cap; recommends the smallest encoding that does not
// slow the run. (2) Caps with the base scenario's encoding: by default on each radio link class
// (leader<->GCS, member<->leader) in turn, at shares of what that class carried per sender in the
// uncapped runs, over the run (mean) and in its busiest second (peak); each cap's steps against
// the uncapped runs of the same seeds with a 95 % interval, what the cap did to the messages (ticks
// queued, median and 95th percentile; messages lost), and the knee: the smallest cap whose steps
// stay within 5 % of uncapped. With absolute caps (leader_gcs_caps_bytes_per_s), the older sweep
// of the leader<->GCS link alone.
#include <algorithm>
#include <cmath>
#include <functional>

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
               "vs " + first, "radio kB / run", "on-robot sensing kB / run", "steps", "complete"});
  for (const auto& method : plan.methods) {
    t.add_section(method);
    const Cell reference = plan.encodings.empty() ? Cell{} : cell_of(rows, map, method, uncapped(plan.encodings.front()));
    for (MapEncoding e : plan.encodings) {
      const Cell c = cell_of(rows, map, method, uncapped(e));
      const Summary per_rs = summary_of(c, Metric::kMapBytesPerRobotSecond);
      // Paired over seeds, with its 95 % interval.
      const PairedDifference vs = paired_of(c, reference, Metric::kMapBytesPerRobotSecond);
      t.add_row({"  " + encoding_name(e), kilo(summary_of(c, Metric::kMapBytes)),
                 format_cell(c, Metric::kMapBytesPerRobotSecond, 1),
                 e == plan.encodings.front() ? std::string("ref") : format_paired_pct(vs),
                 kilo(summary_of(c, Metric::kRadioBytes)), kilo(summary_of(c, Metric::kOnRobotBytes)),
                 format_cell(c, Metric::kSteps, 1),
                 completion_text(c)});
      out.aggregates.push_back(
          {{"part", "encoding"},
           {"map", map_label(map)},
           {"method", method},
           {"map_encoding", encoding_name(e)},
           {"runs", cell_json(c)},
           {"map_bytes", summary_json(summary_of(c, Metric::kMapBytes))},
           {"map_bytes_per_robot_second", summary_json(per_rs)},
           {"map_bytes_per_robot_second_vs_first", paired_json(vs)},
           {"traffic_bytes", summary_json(summary_of(c, Metric::kTrafficBytes))},
           {"radio_bytes", summary_json(summary_of(c, Metric::kRadioBytes))},
           {"sim_robot_on_robot_bytes", summary_json(summary_of(c, Metric::kOnRobotBytes))},
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

// Map bytes per robot-second by encoding, uncapped: a bar per (map, method) in each encoding's group.
BarPanel encodings_panel(const ExperimentPlan& plan, const std::vector<RunRow>& rows) {
  BarPanel bytes;
  bytes.title = "Map traffic by encoding (no cap)";
  bytes.y_label = "map bytes per robot-second";
  bytes.x_label = "map_encoding";
  for (MapEncoding e : plan.encodings) bytes.groups.push_back(encoding_name(e));
  Sweep by_encoding;
  for (MapEncoding e : plan.encodings) by_encoding.settings.push_back(uncapped(e));
  for (const std::string& map : plan.maps) {
    for (std::size_t mi = 0; mi < plan.methods.size(); ++mi) {
      const std::string& method = plan.methods[mi];
      const std::string name = plan.maps.size() > 1 ? method + " (" + map_label(map) + ")" : method;
      bytes.series.push_back(sweep_series(by_encoding, rows, map, method, method_colour(method, static_cast<int>(mi)), name,
                                          Metric::kMapBytesPerRobotSecond));
    }
  }
  return bytes;
}

// The knee's tolerance: a cap "does not slow the run" while its mean steps stay within this of
// the uncapped runs' (and all its runs complete).
constexpr double kKneePercent = 5.0;

// "x2", "x1", "x1/2", ...: a share of the demand as the table's header says it.
std::string share_label(double f) {
  if (f >= 1) return "x" + format_number(f, f == std::floor(f) ? 0 : 2);
  const double inverse = 1 / f;
  if (std::fabs(inverse - std::round(inverse)) < 1e-9) return "x1/" + format_number(inverse, 0);
  return "x" + format_number(f, 3);
}

double cap_of(const RunSetting& s) {
  return (s.demand && s.demand->link == "member_leader" ? s.member_leader_bandwidth_bytes_per_s
                                                        : s.leader_gcs_bandwidth_bytes_per_s)
      .value_or(0);
}

// The mean over a cell's runs of one link's queue or loss number (nullopt: no run has it).
std::optional<double> link_mean(const Cell& c, const std::string& link,
                                const std::function<std::optional<double>(const RunNumbers::Link&)>& f) {
  std::vector<double> v;
  for (const RunRow* r : c.ok) {
    const auto l = r->numbers->links.find(link);
    if (l == r->numbers->links.end()) continue;
    if (const auto x = f(l->second)) v.push_back(*x);
  }
  if (v.empty()) return std::nullopt;
  return summarize(v).mean;
}

}  // namespace

std::optional<Knee> knee_of(const std::vector<KneePoint>& points, double uncapped_steps, double tolerance_percent) {
  std::vector<KneePoint> sorted = points;
  std::sort(sorted.begin(), sorted.end(), [](const KneePoint& a, const KneePoint& b) { return a.cap > b.cap; });
  std::optional<Knee> knee;
  std::optional<double> uncertain_at;
  for (const KneePoint& p : sorted) {
    const bool has_interval = std::isfinite(p.low_pct) && std::isfinite(p.high_pct);
    const bool within_on_average = p.steps <= uncapped_steps * (1 + tolerance_percent / 100.0);
    const bool slower = has_interval ? p.low_pct > tolerance_percent : !within_on_average;
    if (!p.all_complete || slower) break;
    if (has_interval && p.high_pct > tolerance_percent && !uncertain_at) uncertain_at = p.cap;
    if (within_on_average) knee = Knee{p.cap, uncertain_at};
  }
  return knee;
}

namespace {

// Part 2 by default: each capped link class, caps at shares of its demand on `map`.
std::string demand_caps_text(const ExperimentPlan& plan, const std::vector<RunRow>& rows, const std::string& map,
                             KindOutputs& out, Figure& figure) {
  const std::string label = map_label(map);
  const RunSetting uncapped_setting = uncapped(plan.cap_encoding);
  std::string text;
  for (const std::string& link : plan.cap_links) {
    const auto demand = plan.demand.count(label) && plan.demand.at(label).count(link)
                            ? std::optional<ExperimentPlan::Demand>(plan.demand.at(label).at(link))
                            : std::nullopt;
    LinePanel panel;
    panel.title = link + " cap, " + label;
    panel.y_label = "steps";
    panel.x_label = "share of the demand per sender (" + encoding_name(plan.cap_encoding) + ")";
    for (double f : plan.cap_fractions) panel.x_ticks.push_back(share_label(f));
    for (const std::string& method : plan.methods) {
      const Cell reference = cell_of(rows, map, method, uncapped_setting);
      const double uncapped_steps = summary_of(reference, Metric::kSteps).mean;
      std::vector<KneePoint> points;
      for (std::size_t bi = 0; bi < plan.cap_bases.size(); ++bi) {
        const std::string& basis = plan.cap_bases[bi];
        std::vector<std::string> header = {link + " cap, " + basis + " x, " + label + ", " + method, "uncapped"};
        std::vector<Cell> cells;
        std::vector<RunSetting> settings;
        for (double f : plan.cap_fractions) {
          header.push_back(share_label(f));
          // The runs of this share (their cap in bytes per second is the plan's, per map).
          const auto in_cell = [&](const RunRow& r) {
            return r.run.map == map && r.run.method == method && r.run.setting.demand &&
                   *r.run.setting.demand == DemandCap{link, basis, f};
          };
          cells.push_back(cell_of(rows, in_cell));
          const auto any = std::find_if(rows.begin(), rows.end(), in_cell);
          settings.push_back(any == rows.end() ? RunSetting{} : any->run.setting);
        }
        TextTable t(header);
        std::vector<std::string> caps = {"  cap per sender", "-"}, steps = {"  steps", format_cell(reference, Metric::kSteps, 1)},
                                 change = {"  vs uncapped (95 % CI)", "ref"}, queue = {"  queued ticks, median / p95", "-"},
                                 lost = {"  messages lost", "-"}, complete = {"  complete runs", completion_text(reference)};
        // Okabe-Ito blue for shares of the mean, vermillion for shares of the peak.
        const Colour colour = basis == "mean" ? Colour{0, 114, 178} : Colour{213, 94, 0};
        PlotSeries series{plan.methods.size() > 1 ? basis + " (" + method + ")" : basis, colour, {}, {}};
        for (std::size_t k = 0; k < cells.size(); ++k) {
          const Cell& c = cells[k];
          const double cap = cap_of(settings[k]);
          caps.push_back(cap > 0 ? format_rate(cap) : "-");
          steps.push_back(format_cell(c, Metric::kSteps, 1));
          const PairedDifference d = paired_of(c, reference, Metric::kSteps);
          change.push_back(format_paired_pct(d));
          const auto median = link_mean(c, link, [](const RunNumbers::Link& l) { return l.queue_median_ticks; });
          const auto p95 = link_mean(c, link, [](const RunNumbers::Link& l) { return l.queue_p95_ticks; });
          queue.push_back(median && p95 ? format_number(*median, 1) + " / " + format_number(*p95, 1) : "-");
          const auto dropped = link_mean(c, link, [](const RunNumbers::Link& l) { return std::optional<double>(l.dropped_messages); });
          lost.push_back(dropped ? format_number(*dropped, 1) : "-");
          complete.push_back(completion_text(c));
          const Summary st = summary_of(c, Metric::kSteps);
          series.values.push_back(st.mean);
          series.errors.push_back(st.std);
          if (cap > 0 && !c.ok.empty()) points.push_back({cap, st.mean, c.complete() == c.planned, d.low_pct, d.high_pct});
          out.aggregates.push_back({{"part", "demand_cap"},
                                    {"map", label},
                                    {"method", method},
                                    {"map_encoding", encoding_name(plan.cap_encoding)},
                                    {"link", link},
                                    {"basis", basis},
                                    {"fraction", plan.cap_fractions[k]},
                                    {"cap_bytes_per_s_per_sender", cap},
                                    {"runs", cell_json(c)},
                                    {"steps", summary_json(st)},
                                    {"steps_vs_uncapped", paired_json(d)},
                                    {"queue_median_ticks", optional_json(median)},
                                    {"queue_p95_ticks", optional_json(p95)},
                                    {"messages_lost", optional_json(dropped)}});
        }
        for (const auto* row : {&caps, &steps, &change, &queue, &lost, &complete}) t.add_row(*row);
        text += "\n" + t.render();
        panel.series.push_back(series);
      }
      const std::optional<Knee> knee = knee_of(points, uncapped_steps, kKneePercent);
      std::string line = "knee, " + link + ", " + label + ", " + method + ", " + encoding_name(plan.cap_encoding) + ": ";
      if (!std::isfinite(uncapped_steps)) {
        line += "none (no uncapped run to compare with)";
      } else if (!knee) {
        line += "none: even the largest cap slowed the run by more than " + format_number(kKneePercent, 0) + " %";
      } else {
        line += format_rate(knee->cap) + " per sender is the smallest cap within " + format_number(kKneePercent, 0) +
                " % of uncapped steps";
        if (demand) {
          line += " (" + format_number(knee->cap / demand->mean_bytes_per_s, 2) + " x its mean demand, " +
                  format_number(knee->cap / demand->peak_bytes_per_s, 2) + " x its peak";
          if (demand->busiest_mean_bytes_per_s > 0) {
            line += ", " + format_number(knee->cap / demand->busiest_mean_bytes_per_s, 2) + " x the busiest sender's mean";
          }
          line += ")";
        }
        const double smallest = points.empty() ? 0 : std::min_element(points.begin(), points.end(), [](auto& a, auto& b) { return a.cap < b.cap; })->cap;
        if (knee->cap <= smallest) line += "; no cap tried slowed it: the knee lies lower";
        if (knee->uncertain_at) {
          line += "; uncertain: the 95 % interval at " + format_rate(*knee->uncertain_at) + " reaches past " +
                  format_number(kKneePercent, 0) + " %, more seeds would tell";
        }
      }
      text += line + "\n";
      out.findings["knee"][label][link][method] = knee ? nlohmann::json(knee->cap) : nlohmann::json(nullptr);
      out.findings["knee_uncertain_at"][label][link][method] =
          knee && knee->uncertain_at ? nlohmann::json(*knee->uncertain_at) : nlohmann::json(nullptr);
    }
    if (demand) {
      text += "  (" + link + " demand per sender uncapped: mean " + format_rate(demand->mean_bytes_per_s) + ", peak " +
              format_rate(demand->peak_bytes_per_s);
      if (!demand->busiest_sender.empty()) {
        text += "; the busiest sender, " + demand->busiest_sender_text() + ", alone: mean " +
                format_rate(demand->busiest_mean_bytes_per_s);
      }
      text += ", over " + std::to_string(demand->runs) + " runs)\n";
    }
    figure.panels.push_back(panel);
  }
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

  if (plan.leader_gcs_caps_bytes_per_s.empty()) {
    Figure f = seed_stats_figure("Bandwidth", rows);
    f.panels.push_back(encodings_panel(plan, rows));
    text += "\ncaps per sender (comm/link.hpp: one token bucket per sender and link class) at shares of the "
            "link's demand, measured on the uncapped runs; the on-robot sim_robot link is never capped\n";
    for (const std::string& map : plan.maps) text += demand_caps_text(plan, rows, map, out, f);
    text += footnotes(rows);
    out.table = text;
    f.panel_width = 560;
    out.figures.emplace_back("bandwidth.png", f);
    return;
  }

  // Part 2 with absolute caps: the leader<->GCS sweep, "unlimited" (0) as the reference.
  Sweep sw;
  sw.reference_name = "unlimited";
  std::vector<double> absolute = plan.leader_gcs_caps_bytes_per_s;
  if (std::none_of(absolute.begin(), absolute.end(), [](double c) { return c <= 0; })) absolute.push_back(0);
  for (double c : absolute) {
    if (c <= 0) sw.reference = sw.settings.size();
    sw.settings.push_back(RunSetting::encoding_and_cap(plan.cap_encoding, c));
    sw.columns.push_back(format_rate(c));
  }
  LinePanel caps;
  caps.title = "Steps vs leader<->GCS bandwidth cap";
  caps.y_label = "steps";
  caps.x_ticks = sw.columns;
  caps.x_label = "leader<->GCS cap (" + encoding_name(plan.cap_encoding) + ")";

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
  f.panels.push_back(encodings_panel(plan, rows));
  f.panels.push_back(caps);
  out.figures.emplace_back("bandwidth.png", f);
}

}  // namespace swarm::tools::analysis
