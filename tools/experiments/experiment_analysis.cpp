#include "experiment_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "run_command.hpp"
#include "text_table.hpp"

namespace swarm::tools::analysis {

std::vector<RunSetting> settings_of(const ExperimentPlan& p) {
  std::vector<RunSetting> out;
  auto add = [&](const RunSetting& s) {
    if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  };
  switch (p.kind) {
    case ExperimentKind::kExplore:
      add({});
      break;
    case ExperimentKind::kLatency:
      // Two sweeps that share their zero point: each link's delay with the other link at 0.
      for (auto d : p.leader_gcs_delays_ticks) add(RunSetting::delays(d, 0));
      for (auto d : p.member_leader_delays_ticks) add(RunSetting::delays(0, d));
      break;
    case ExperimentKind::kBandwidth:
      // The encodings without a cap, then the caps with cap_encoding (sharing "unlimited"):
      // absolute ones, or shares of each link's demand (their bytes per second unset here).
      for (auto e : p.encodings) add(RunSetting::encoding_and_cap(e, 0.0));
      add(RunSetting::encoding_and_cap(p.cap_encoding, 0.0));
      for (double c : p.leader_gcs_caps_bytes_per_s) {
        add(RunSetting::encoding_and_cap(p.cap_encoding, c));
      }
      if (p.leader_gcs_caps_bytes_per_s.empty()) {
        for (const std::string& link : p.cap_links) {
          for (const std::string& basis : p.cap_bases) {
            for (double f : p.cap_fractions) add(RunSetting::demand_cap(p.cap_encoding, {link, basis, f}));
          }
        }
      }
      break;
    case ExperimentKind::kLoss:
      for (double l : p.losses) add(RunSetting::every_link_loss(l));
      break;
  }
  return out;
}

Cell cell_of(const std::vector<RunRow>& rows, const std::function<bool(const RunRow&)>& in_cell) {
  Cell c;
  for (const RunRow& r : rows) {
    if (!in_cell(r)) continue;
    ++c.planned;
    if (!r.numbers) {
      ++c.failed;
      continue;
    }
    if (r.numbers->ended_early()) {
      ++c.ended_early;
      continue;
    }
    if (!r.numbers->complete) ++c.incomplete;
    c.ok.push_back(&r);
  }
  return c;
}

Cell cell_of(const std::vector<RunRow>& rows, const std::string& map, const std::string& method,
             const RunSetting& setting) {
  return cell_of(rows, [&](const RunRow& r) {
    return r.run.map == map && r.run.method == method && r.run.setting == setting;
  });
}

std::optional<double> value_of(const RunNumbers& n, Measure measure) {
  switch (measure.metric) {
    case Metric::kSteps: return n.steps;
    case Metric::kRounds: return n.planning_rounds;
    case Metric::kStepsTo99: return n.steps_to_99;
    case Metric::kExploredPercent: return 100.0 * n.explored_fraction;
    case Metric::kTrafficBytes: return n.traffic_bytes;
    case Metric::kRadioBytes: return n.radio_bytes();
    case Metric::kOnRobotBytes: return n.on_robot_bytes();
    case Metric::kConflicts: return n.conflicts;
    case Metric::kDelivered: return n.delivered;
    case Metric::kMapBytes: return n.map_bytes;
    case Metric::kMapBytesPerRobotSecond: return n.map_bytes_per_robot_second();
    case Metric::kPhaseTicks:
      if (measure.phase < n.phase_ticks.size()) return n.phase_ticks[measure.phase];
      return std::nullopt;
  }
  return std::nullopt;
}

Summary summary_of(const Cell& c, Measure m) {
  std::vector<double> v;
  for (const RunRow* r : c.ok) {
    if (const auto x = value_of(*r->numbers, m)) v.push_back(*x);
  }
  return summarize(v);
}

PairedDifference paired_of(const Cell& c, const Cell& reference, Measure m) {
  std::vector<double> values, refs;
  for (const RunRow* r : c.ok) {
    const auto x = value_of(*r->numbers, m);
    if (!x) continue;
    for (const RunRow* q : reference.ok) {
      if (q->run.seed != r->run.seed) continue;
      if (const auto y = value_of(*q->numbers, m)) {
        values.push_back(*x);
        refs.push_back(*y);
      }
      break;
    }
  }
  return paired_difference(values, refs);
}

nlohmann::json paired_json(const PairedDifference& d) {
  if (d.n < 2 || !std::isfinite(d.low)) return {{"pairs", d.n}, {"mean", nullptr}};
  return {{"pairs", d.n},
          {"mean", d.mean},
          {"ci95", {d.low, d.high}},
          {"mean_percent", optional_json(d.mean_pct)},
          {"ci95_percent", {optional_json(d.low_pct), optional_json(d.high_pct)}},
          {"significant", d.significant}};
}

std::string format_cell(const Cell& c, Measure measure, int decimals) {
  std::string s = format_mean_std(summary_of(c, measure), decimals);
  if (c.failed > 0) s += "*";
  if (c.ended_early > 0) s += "!";
  // Steps of a run stopped at max_ticks are a lower bound; 99 % may never have been reached.
  const Metric m = measure.metric;
  if (c.incomplete > 0 && m != Metric::kTrafficBytes && m != Metric::kRadioBytes && m != Metric::kOnRobotBytes &&
      m != Metric::kMapBytes &&
      m != Metric::kMapBytesPerRobotSecond) {
    s += "+";
  }
  return s;
}

std::string completion_text(const Cell& c) {
  std::string s = std::to_string(c.complete()) + "/" + std::to_string(c.planned);
  std::string why;
  if (c.failed > 0) why = std::to_string(c.failed) + " failed";
  if (c.ended_early > 0) {
    why += (why.empty() ? "" : ", ") + std::to_string(c.ended_early) + " ended early";
  }
  return why.empty() ? s : s + " (" + why + ")";
}

nlohmann::json summary_json(const Summary& s) {
  nlohmann::json j = {{"n", s.n}};
  j["mean"] = std::isfinite(s.mean) ? nlohmann::json(s.mean) : nlohmann::json(nullptr);
  j["std"] = std::isfinite(s.std) ? nlohmann::json(s.std) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json cell_json(const Cell& c) {
  return {{"runs", c.planned},
          {"ok", c.ok.size()},
          {"failed", c.failed},
          {"ended_early", c.ended_early},
          {"complete", c.complete()}};
}

nlohmann::json optional_json(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::vector<std::string> row_over(const std::string& label, const std::vector<RunSetting>& settings,
                                  const std::function<std::string(const RunSetting&)>& f) {
  std::vector<std::string> cells = {label};
  for (const RunSetting& s : settings) cells.push_back(f(s));
  return cells;
}

std::string sweep_table(const Sweep& sw, const ExperimentPlan& plan,
                        const std::vector<RunRow>& rows, const std::string& map,
                        bool with_steps_to_99) {
  std::vector<std::string> header = {sw.heading};
  header.insert(header.end(), sw.columns.begin(), sw.columns.end());
  TextTable t(header);
  const bool with_baseline =
      std::find(plan.methods.begin(), plan.methods.end(), "baseline") != plan.methods.end();
  auto metric_rows = [&](Measure m, const std::string& title, bool compare) {
    t.add_section(title);
    for (const auto& method : plan.methods) {
      t.add_row(row_over("  " + method, sw.settings, [&](const RunSetting& s) {
        return format_cell(cell_of(rows, map, method, s), m, 1);
      }));
    }
    if (!compare || sw.settings.empty()) return;
    // Each change as the mean of the paired differences (same seeds) with its 95 % interval.
    for (const auto& method : plan.methods) {
      const Cell reference = cell_of(rows, map, method, sw.settings[sw.reference]);
      t.add_row(row_over("  " + method + " vs " + sw.reference_name, sw.settings,
                         [&](const RunSetting& s) {
                           return s == sw.settings[sw.reference]
                                      ? std::string("ref")
                                      : format_paired_pct(paired_of(cell_of(rows, map, method, s), reference, m));
                         }));
    }
    if (!with_baseline) return;
    for (const auto& method : plan.methods) {
      if (method == "baseline") continue;
      t.add_row(row_over("  " + method + " vs baseline", sw.settings, [&](const RunSetting& s) {
        return format_paired_pct(paired_of(cell_of(rows, map, method, s), cell_of(rows, map, "baseline", s), m));
      }));
    }
  };
  const bool chained = !plan.mission.empty();
  metric_rows(Metric::kSteps, chained ? "ticks (the whole mission)" : "steps", true);
  // A chained mission's makespan phase by phase (a phase a run never reached has no value there).
  for (std::size_t i = 0; chained && plan.mission.size() > 1 && i < plan.mission.size(); ++i) {
    metric_rows(Measure::phase_ticks(i), "ticks in phase " + std::to_string(i + 1) + ", " + plan.mission[i], true);
  }
  metric_rows(Metric::kRounds, "planning rounds", true);
  if (with_steps_to_99) metric_rows(Metric::kStepsTo99, "steps to 99 % explored", false);
  if (chained) {
    metric_rows(Metric::kConflicts, "conflicts (vertex + edge, ground truth)", false);
    if (std::find(plan.mission.begin(), plan.mission.end(), "collect") != plan.mission.end()) {
      metric_rows(Metric::kDelivered, "objects delivered", false);
    }
  }
  t.add_section("complete runs");
  for (const auto& method : plan.methods) {
    t.add_row(row_over("  " + method, sw.settings, [&](const RunSetting& s) {
      return completion_text(cell_of(rows, map, method, s));
    }));
  }
  return t.render();
}

PlotSeries sweep_series(const Sweep& sw, const std::vector<RunRow>& rows, const std::string& map,
                        const std::string& method, Colour colour, const std::string& name,
                        Measure m) {
  PlotSeries series{name, colour, {}, {}};
  for (const RunSetting& s : sw.settings) {
    const Summary v = summary_of(cell_of(rows, map, method, s), m);
    series.values.push_back(v.mean);
    series.errors.push_back(v.std);
  }
  return series;
}

std::string footnotes(const std::vector<RunRow>& rows) {
  std::string out;
  const bool any_failed =
      std::any_of(rows.begin(), rows.end(), [](const RunRow& r) { return !r.numbers; });
  const bool any_incomplete = std::any_of(rows.begin(), rows.end(), [](const RunRow& r) {
    return r.numbers && !r.numbers->complete;
  });
  const bool any_early = std::any_of(rows.begin(), rows.end(), [](const RunRow& r) {
    return r.numbers && r.numbers->ended_early();
  });
  if (any_failed) out += "* some runs of this cell failed and are left out (listed below)\n";
  if (any_early) {
    out += "! some runs of this cell ended early: the GCS declared the map complete with less "
           "than " + format_number(100.0 * kCompleteExploredFraction, 0) +
           " % explored (ground truth); they are left out (listed below)\n";
  }
  if (any_incomplete) {
    out += "+ some runs of this cell ended incomplete, at max_ticks or ended as stalled (no progress in "
           "stall_ticks): their steps count as the tick they ended at (a lower bound)\n";
  }
  for (const RunRow& r : rows) {
    if (r.numbers && r.numbers->ended_early()) {
      out += "ENDED EARLY " + r.run.dir + ": complete at step " +
             format_number(r.numbers->steps, 0) + " with " +
             format_number(100.0 * r.numbers->explored_fraction, 1) + " % explored\n";
    }
    if (r.numbers) continue;
    out += "FAILED " + r.run.dir + ": " + r.run.failure;
    if (!r.run.log.empty()) out += " (log: " + r.run.log + ")";
    out += "\n";
  }
  return out;
}

std::string seeds_text(const std::vector<RunRow>& rows) {
  std::set<std::uint64_t> seeds;
  for (const RunRow& r : rows) seeds.insert(r.run.seed);
  if (seeds.empty()) return "no seeds";
  const bool contiguous = *seeds.rbegin() - *seeds.begin() + 1 == seeds.size();
  if (seeds.size() == 1) return "seed " + std::to_string(*seeds.begin());
  if (contiguous) {
    return "seeds " + std::to_string(*seeds.begin()) + "-" + std::to_string(*seeds.rbegin());
  }
  std::string s = "seeds ";
  bool first = true;
  for (auto v : seeds) {
    s += (first ? "" : ", ") + std::to_string(v);
    first = false;
  }
  return s;
}

Figure seed_stats_figure(const std::string& subject, const std::vector<RunRow>& rows) {
  Figure f;
  f.title = subject + ": mean +/- std over " + seeds_text(rows);
  f.note = "error bars: standard deviation over seeds";
  return f;
}

std::string team_text(const std::vector<RunRow>& rows) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> teams;
  for (const RunRow& r : rows) {
    if (r.numbers) teams.insert({r.numbers->groups, r.numbers->robots_per_group});
  }
  if (teams.size() != 1) return teams.empty() ? "" : "mixed team sizes";
  const auto [g, n] = *teams.begin();
  return std::to_string(g) + (g == 1 ? " group" : " groups") + " x " + std::to_string(n) +
         (n == 1 ? " robot" : " robots");
}

std::string runs_text(const std::vector<RunRow>& rows) {
  int ok = 0, failed = 0, complete = 0, early = 0;
  for (const RunRow& r : rows) {
    if (!r.numbers) {
      ++failed;
    } else if (r.numbers->ended_early()) {
      ++early;
    } else {
      ++ok;
      if (r.numbers->complete) ++complete;
    }
  }
  return std::to_string(rows.size()) + " runs: " + std::to_string(ok) + " ok (" +
         std::to_string(complete) + " complete), " + std::to_string(failed) + " failed" +
         (early > 0 ? ", " + std::to_string(early) + " ended early" : "");
}

Colour method_colour(const std::string& method, int index) {
  if (method == "group-frontier") return {0, 114, 178};
  if (method == "baseline") return {213, 94, 0};
  if (method == "ideal") return {0, 158, 115};
  static const Colour others[] = {{230, 159, 0}, {204, 121, 167}, {86, 180, 233}, {120, 120, 120}};
  return others[static_cast<std::size_t>(index) % 4];
}

std::string format_number(double v, int decimals) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  // Never print "-0".
  const double r = std::fabs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v;
  std::snprintf(buf, sizeof buf, "%.*f", decimals, r);
  return buf;
}

std::string format_rate(double bytes_per_s) {
  if (bytes_per_s <= 0) return "unlimited";
  char buf[32];
  if (bytes_per_s >= 1000) {
    std::snprintf(buf, sizeof buf, "%.3g kB/s", bytes_per_s / 1000.0);
  } else {
    std::snprintf(buf, sizeof buf, "%.3g B/s", bytes_per_s);
  }
  return buf;
}


std::string encoding_name(swarm::scenario::MapEncoding e) {
  return swarm::scenario::MapEncoding_Name(e);
}

}  // namespace swarm::tools::analysis
