#include "experiment_tasks.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "experiment.hpp"
#include "experiment_runner.hpp"
#include "offline_common.hpp"
#include "scenario_changes.hpp"
#include "stats.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/config/task_config.hpp"
#include "swarm/record/metrics.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Scenario = swarm::scenario::Scenario;
using Change = std::function<void(Scenario&)>;

struct Point {
  std::string x;  // the tick label
  Change apply;
};

struct Sweep {
  std::string name;     // "robots", "delay", "loss": run directory names and CSV
  std::string title;    // the panel's and the table's heading
  std::string x_label;
  std::vector<Point> points;
};

struct Variant {
  std::string name;
  Change apply;
  Colour colour;
  // Whether the variant can run at a sweep point (the scenario with the point applied); a
  // combination the scenario check would refuse is left out of the plan (n = 0/0 in the table).
  std::function<bool(const Scenario&)> applies = [](const Scenario&) { return true; };
};

// A number read from the task's phase in metrics.json.
struct Measure {
  std::string key;    // CSV column and results.json key
  std::string label;  // table heading
  std::function<double(const record::PhaseMetrics&)> read;
};

struct Spec {
  std::string task;           // "cover" | "mapf-live"
  std::string phase;          // the phase's name in metrics.json
  std::string scenario_file;  // in DATA/scenarios
  std::vector<Variant> variants;
  std::vector<Sweep> sweeps;
  std::vector<Measure> measures;
  std::size_t plotted = 0;    // the measure the figure shows (index into measures)
  std::string plot_title;
};

Change team(std::uint32_t groups, std::uint32_t robots_per_group) {
  return [=](Scenario& s) {
    s.set_groups(groups);
    s.set_robots_per_group(robots_per_group);
  };
}

// Applies `f` to every phase of the mission that runs task `task` (its registry name).
Change each_phase(const std::string& task, std::function<void(swarm::scenario::Phase&)> f) {
  return [=](Scenario& s) {
    for (auto& ph : *s.mutable_mission()->mutable_phase()) {
      if (config::task_name(ph) == task) f(ph);
    }
  };
}

Spec cover_spec() {
  Spec s;
  s.task = "cover";
  s.phase = "cover";
  s.scenario_file = "cover-given.pbtxt";
  s.variants = {{"hierarchical", each_phase("cover", [](auto& p) { p.mutable_cover()->set_hierarchical(true); }),
                 {0, 114, 178}},
                {"flat", each_phase("cover", [](auto& p) { p.mutable_cover()->set_hierarchical(false); }),
                 {213, 94, 0}}};
  Sweep robots{"robots", "Robots (groups of 3)", "robots", {}};
  for (std::uint32_t g : {1u, 2u, 3u, 4u}) robots.points.push_back({std::to_string(3 * g), team(g, 3)});
  Sweep delay{"delay", "Member<->leader delay", "delay, ticks", {}};
  for (std::uint32_t d : {0u, 2u, 5u, 10u}) delay.points.push_back({std::to_string(d), member_leader_delay(d, 0)});
  Sweep loss{"loss", "Loss on every link", "loss, %", {}};
  for (double l : {0.0, 0.05, 0.10}) loss.points.push_back({fixed(100 * l, 0), every_link_loss(l)});
  s.sweeps = {robots, delay, loss};
  s.measures = {
      {"makespan_ticks", "makespan", [](const auto& p) { return task_number(p, "makespan_ticks"); }},
      {"covered_percent", "covered %", [](const auto& p) { return 100 * task_number(p, "covered_fraction"); }},
      {"path_length", "cells driven", [](const auto& p) { return static_cast<double>(p.motion.total.moves); }},
      {"turns_90", "90° turns", [](const auto& p) { return p.motion.total.turn_eighths / 2.0; }},
  };
  s.plot_title = "Live coverage makespan (ticks until every reachable cell was covered)";
  return s;
}

Spec mapf_spec() {
  Spec s;
  s.task = "mapf-live";
  s.phase = "mapf";
  s.scenario_file = "mapf-small.pbtxt";
  const auto mapf = [](swarm::scenario::MapfSolver k, swarm::scenario::MapfExecution e) {
    return each_phase("mapf", [k, e](auto& p) {
      p.mutable_mapf()->set_solver(k);
      p.mutable_mapf()->set_execution(e);
    });
  };
  s.variants = {{"ecbs-adg", mapf(swarm::scenario::MAPF_ECBS, swarm::scenario::MAPF_EXECUTE_ADG), {0, 114, 178}},
                // Timed driving needs every route on time: not under loss (config::delivery_ticks_bounded).
                {"ecbs-timed", mapf(swarm::scenario::MAPF_ECBS, swarm::scenario::MAPF_EXECUTE_TIMED), {213, 94, 0},
                 [](const Scenario& sc) { return config::delivery_ticks_bounded(sc); }},
                {"lacam-adg", mapf(swarm::scenario::MAPF_LACAM, swarm::scenario::MAPF_EXECUTE_ADG), {0, 158, 115}}};
  Sweep delay{"delay", "Member<->leader delay (jitter: half of it)", "delay, ticks", {}};
  for (std::uint32_t d : {0u, 1u, 3u, 6u, 10u}) delay.points.push_back({std::to_string(d), member_leader_delay(d, d / 2)});
  Sweep loss{"loss", "Member<->leader loss", "loss, %", {}};
  for (double l : {0.0, 0.05, 0.20}) {
    loss.points.push_back({fixed(100 * l, 0), [l](Scenario& sc) { sc.mutable_links()->mutable_member_leader()->set_loss(l); }});
  }
  Sweep robots{"robots", "Robots", "robots (groups x robots)", {}};
  for (auto [g, r] : {std::pair{2u, 2u}, {2u, 3u}, {3u, 3u}, {3u, 4u}}) {
    robots.points.push_back({std::to_string(g * r), team(g, r)});
  }
  s.sweeps = {delay, loss, robots};
  s.measures = {
      {"driven_makespan_ticks", "makespan driven", [](const auto& p) { return task_number(p, "driven_makespan_ticks"); }},
      {"planned_makespan", "planned", [](const auto& p) { return task_number(p, "planned_makespan"); }},
      {"conflicts", "conflicts", [](const auto& p) { return task_number(p, "conflicts"); }},
      {"blocked_moves", "blocked", [](const auto& p) { return static_cast<double>(p.motion.total.blocked_moves); }},
  };
  s.plot_title = "Live MAPF: makespan driven (first move to last) vs planned";
  return s;
}

struct Job {
  std::size_t sweep = 0, point = 0, variant = 0;
  std::uint64_t seed = 1;
  std::string dir;  // relative to the experiment directory
};

struct Outcome {
  bool ok = false;
  bool complete = false;
  std::string failure;
  std::vector<double> values;  // per measure
};

Outcome read_outcome(const Spec& spec, const RunOutcome& run) {
  Outcome o;
  if (!run.ok) {
    o.failure = run.message;
    return o;
  }
  try {
    const record::RunMetrics m = record::read_metrics(run.run_dir + "/metrics.json");
    for (const auto& p : m.phases) {
      if (p.name != spec.phase) continue;
      o.ok = true;
      o.complete = p.complete;
      for (const Measure& x : spec.measures) o.values.push_back(x.read(p));
    }
    if (!o.ok) o.failure = "no " + spec.phase + " phase in metrics.json";
  } catch (const std::exception& e) {
    o.failure = e.what();
  }
  return o;
}

// The values of measure `k` over the seeds of one (sweep, point, variant); only complete runs.
Summary cell(const std::vector<Job>& jobs, const std::vector<Outcome>& outcomes, std::size_t sweep, std::size_t point,
             std::size_t variant, std::size_t k, int* complete = nullptr, int* planned = nullptr) {
  std::vector<double> v;
  int done = 0, all = 0;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& j = jobs[i];
    if (j.sweep != sweep || j.point != point || j.variant != variant) continue;
    ++all;
    if (!outcomes[i].ok || !outcomes[i].complete) continue;
    ++done;
    if (std::isfinite(outcomes[i].values[k])) v.push_back(outcomes[i].values[k]);
  }
  if (complete) *complete = done;
  if (planned) *planned = all;
  return summarize(v);
}

}  // namespace

int task_experiment(const TaskExperimentOptions& options, std::ostream& out, std::ostream& err) {
  const char* me = "swarm experiment";
  Spec spec;
  if (options.task == "cover") {
    spec = cover_spec();
  } else if (options.task == "mapf-live") {
    spec = mapf_spec();
  } else {
    err << me << ": unknown task experiment '" << options.task << "' (cover, mapf-live)\n";
    return 2;
  }
  if (options.seeds < 1 || options.jobs < 1) {
    err << me << " " << spec.task << ": --seeds and --jobs must be at least 1\n";
    return 2;
  }
  std::string dir;
  try {
    dir = make_out_dir(options.out_dir, "experiment-" + spec.task);
  } catch (const OfflineBadInput& e) {
    err << me << " " << spec.task << ": " << e.what() << "\n";
    return 2;
  }
  const std::string scenario = (fs::path(config::data_dir()) / "scenarios" / spec.scenario_file).string();

  std::vector<Job> jobs;
  std::vector<RunJob> runs;
  if (options.quick) {  // the first two points of the first sweep
    spec.sweeps.resize(1);
    spec.sweeps[0].points.resize(2);
  }
  for (std::size_t s = 0; s < spec.sweeps.size(); ++s) {
    for (std::size_t p = 0; p < spec.sweeps[s].points.size(); ++p) {
      for (std::size_t v = 0; v < spec.variants.size(); ++v) {
        Scenario at_point;
        spec.sweeps[s].points[p].apply(at_point);
        if (!spec.variants[v].applies(at_point)) continue;
        for (std::int64_t seed = 1; seed <= options.seeds; ++seed) {
          Job j{s, p, v, static_cast<std::uint64_t>(seed),
                "runs/" + spec.variants[v].name + "-" + spec.sweeps[s].name + spec.sweeps[s].points[p].x + "-s" +
                    std::to_string(seed)};
          RunJob r;
          r.options.scenario_path = scenario;
          r.options.overrides.map = options.map;
          r.options.overrides.seed = j.seed;
          r.options.out_dir = (fs::path(dir) / j.dir).string();
          r.options.timeout = std::chrono::seconds(options.timeout_s);
          const Change variant = spec.variants[v].apply, point = spec.sweeps[s].points[p].apply;
          r.options.customize = [variant, point](Scenario& sc) {
            point(sc);
            variant(sc);
          };
          jobs.push_back(j);
          runs.push_back(std::move(r));
        }
      }
    }
  }
  out << me << " " << spec.task << ": " << runs.size() << " runs on " << options.map << ", " << options.jobs
      << " at once, into " << dir << "\n";
  RunnerOptions ro;
  ro.jobs = static_cast<int>(options.jobs);
  ro.first_domain = domain_id_for(::getpid());
  std::size_t finished = 0;
  ro.on_finished = [&](std::size_t i, const RunOutcome& o) {
    ++finished;
    out << "[" << finished << "/" << runs.size() << "] " << jobs[i].dir << ": "
        << (o.ok ? "ok" : "FAILED " + o.message) << " (" << fixed(o.wall_seconds, 1) << " s)\n"
        << std::flush;
  };
  const std::vector<RunOutcome> raw = run_jobs(runs, ro);
  std::vector<Outcome> outcomes;
  for (const RunOutcome& o : raw) outcomes.push_back(read_outcome(spec, o));

  // Table: per sweep, one row per point, per variant the measures' mean ± std and how many of
  // the seeds completed.
  std::ostringstream table;
  table << "Live " << spec.task << " on " << options.map << ", mean ± std over seeds 1.." << options.seeds
        << " (complete runs only; n = complete/planned)\n";
  json aggregates = json::array();
  Figure figure{spec.plot_title, {}};
  figure.note = "error bars: std over seeds; base: 2 groups x 3 robots, no delay, no loss";
  for (std::size_t s = 0; s < spec.sweeps.size(); ++s) {
    const Sweep& sw = spec.sweeps[s];
    std::vector<std::string> header{sw.x_label};
    for (const Variant& v : spec.variants) {
      for (const Measure& m : spec.measures) header.push_back(v.name + " " + m.label);
      header.push_back("n");
    }
    TextTable t(header);
    t.add_section(sw.title);
    LinePanel panel{sw.title, spec.measures[spec.plotted].label + ", ticks", {}, {}, sw.x_label};
    for (const Point& p : sw.points) panel.x_ticks.push_back(p.x);
    for (std::size_t v = 0; v < spec.variants.size(); ++v) {
      PlotSeries series{spec.variants[v].name, spec.variants[v].colour, {}, {}};
      for (std::size_t p = 0; p < sw.points.size(); ++p) {
        const Summary m = cell(jobs, outcomes, s, p, v, spec.plotted);
        series.values.push_back(m.n ? m.mean : std::nan(""));
        series.errors.push_back(m.n ? m.std : 0.0);
      }
      panel.series.push_back(series);
    }
    figure.panels.push_back(panel);
    for (std::size_t p = 0; p < sw.points.size(); ++p) {
      std::vector<std::string> row{"  " + sw.points[p].x};
      for (std::size_t v = 0; v < spec.variants.size(); ++v) {
        int complete = 0, planned = 0;
        json entry = {{"sweep", sw.name}, {"x", sw.points[p].x}, {"variant", spec.variants[v].name}};
        for (std::size_t k = 0; k < spec.measures.size(); ++k) {
          const Summary m = cell(jobs, outcomes, s, p, v, k, &complete, &planned);
          row.push_back(format_mean_std(m, 1));
          entry[spec.measures[k].key] = {{"mean", m.n ? json(m.mean) : json(nullptr)},
                                         {"std", m.n ? json(m.std) : json(nullptr)}};
        }
        row.push_back(std::to_string(complete) + "/" + std::to_string(planned));
        entry["complete"] = complete;
        entry["planned"] = planned;
        aggregates.push_back(entry);
      }
      t.add_row(row);
    }
    table << "\n" << t.render();
  }

  std::ostringstream csv;
  csv << "run,variant,sweep,x,seed,status,complete";
  for (const Measure& m : spec.measures) csv << "," << m.key;
  csv << ",failure\n";
  json runs_json = json::array();
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& j = jobs[i];
    const Outcome& o = outcomes[i];
    csv << j.dir << "," << spec.variants[j.variant].name << "," << spec.sweeps[j.sweep].name << ","
        << spec.sweeps[j.sweep].points[j.point].x << "," << j.seed << "," << (o.ok ? "ok" : "failed") << ","
        << (o.complete ? "true" : "false");
    json r = {{"dir", j.dir},
              {"variant", spec.variants[j.variant].name},
              {"sweep", spec.sweeps[j.sweep].name},
              {"x", spec.sweeps[j.sweep].points[j.point].x},
              {"seed", j.seed},
              {"status", o.ok ? "ok" : "failed"},
              {"complete", o.complete}};
    for (std::size_t k = 0; k < spec.measures.size(); ++k) {
      const double v = o.ok ? o.values[k] : std::nan("");
      csv << "," << (std::isfinite(v) ? fixed(v, 2) : "");
      r[spec.measures[k].key] = std::isfinite(v) ? json(v) : json(nullptr);
    }
    std::string why = o.failure;
    for (char& c : why) c = c == ',' || c == '\n' ? ';' : c;
    csv << "," << why << "\n";
    if (!o.ok) r["failure"] = o.failure;
    runs_json.push_back(r);
  }
  ExperimentOutputs outputs;
  outputs.table = table.str();
  outputs.csv = csv.str();
  outputs.json = json({{"kind", spec.task},
                       {"map", options.map},
                       {"seeds", options.seeds},
                       {"runs", runs_json},
                       {"aggregates", aggregates}})
                     .dump(2) +
                 "\n";
  outputs.figures.emplace_back(spec.task + ".png", figure);
  return finish_experiment(dir, outputs, me, out, err);
}

}  // namespace swarm::tools
