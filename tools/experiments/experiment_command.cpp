#include "experiment_command.hpp"

#include "format.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

#include "experiment_analysis.hpp"
#include "experiment_runner.hpp"
#include "run_command.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/tasks/registry.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
namespace cfg = swarm::config;

// Thrown for bad input; becomes exit status 2.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string join(const std::vector<std::string>& v, const std::string& sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

bool is_builtin(const std::string& map) {
  const auto names = cfg::builtin_map_names();
  return std::find(names.begin(), names.end(), map) != names.end();
}

// Built-in names stay; a map_server YAML path becomes absolute. Duplicates are dropped.
std::vector<std::string> check_maps(const std::vector<std::string>& maps) {
  std::vector<std::string> out;
  for (const std::string& m : maps) {
    std::string map = m;
    if (!is_builtin(m)) {
      const std::string ext = fs::path(m).extension().string();
      std::error_code ec;
      if ((ext != ".yaml" && ext != ".yml") || !fs::is_regular_file(m, ec)) {
        throw BadInput("unknown map '" + m + "'; accepted: the built-in maps " +
                       join(cfg::builtin_map_names()) + ", or a map_server YAML file (.yaml)");
      }
      map = fs::absolute(m).lexically_normal().string();
    }
    if (std::find(out.begin(), out.end(), map) == out.end()) out.push_back(map);
  }
  if (out.empty()) throw BadInput("--maps is empty; accepted: " + join(cfg::builtin_map_names()));
  return out;
}

std::vector<std::string> check_methods(const std::vector<std::string>& methods) {
  std::vector<std::string> out;
  for (const std::string& m : methods) {
    std::string name;
    try {
      name = cfg::mode_name(cfg::parse_mode(m));
    } catch (const cfg::ConfigError&) {
      throw BadInput("unknown method '" + m + "'; accepted: " + join(known_methods()));
    }
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  if (out.empty()) throw BadInput("--methods is empty; accepted: " + join(known_methods()));
  return out;
}

// The bandwidth flags, checked: names known, shares above 0, caps not negative.
SweepChoices sweep_choices(const ExperimentOptions& o) {
  SweepChoices c;
  for (const std::string& e : o.encodings) {
    swarm::scenario::MapEncoding v{};
    if (!swarm::scenario::MapEncoding_Parse(e, &v)) {
      throw BadInput("--encodings: unknown map encoding '" + e + "'; accepted: RAW_CELLS, RUN_LENGTH, ZSTD_RUN_LENGTH");
    }
    c.encodings.push_back(v);
  }
  const auto names = [](const std::vector<std::string>& given, const auto& known, const std::string& flag) {
    for (const std::string& v : given) {
      if (std::find(std::begin(known), std::end(known), v) == std::end(known)) {
        std::vector<std::string> k(std::begin(known), std::end(known));
        throw BadInput(flag + ": unknown '" + v + "'; accepted: " + join(k));
      }
    }
    return given;
  };
  c.cap_links = names(o.cap_links, kCappedLinks, "--cap-links");
  c.cap_bases = names(o.cap_bases, kDemandBases, "--cap-bases");
  for (const double f : o.cap_fractions) {
    if (!std::isfinite(f) || f <= 0 || f > 1e6) {
      throw BadInput("--cap-fractions " + analysis::format_number(f, 3) + ": a share of the demand must be above 0");
    }
  }
  c.cap_fractions = o.cap_fractions;
  for (const double b : o.caps) {
    if (!std::isfinite(b) || b < 0) throw BadInput("--caps " + analysis::format_number(b, 0) + ": bytes per second, 0 = unlimited");
  }
  c.leader_gcs_caps_bytes_per_s = o.caps;
  return c;
}

// "lg-delay 10 ticks" etc.: the setting of a run for the progress lines.
std::string setting_text(ExperimentKind kind, const RunSetting& s) {
  switch (kind) {
    case ExperimentKind::kLatency:
      return "leader-gcs delay " + std::to_string(s.leader_gcs_delay_ticks.value_or(0)) +
             ", member-leader delay " + std::to_string(s.member_leader_delay_ticks.value_or(0));
    case ExperimentKind::kBandwidth: {
      const std::string e = s.map_encoding ? analysis::encoding_name(*s.map_encoding) : std::string("?");
      if (s.demand) {
        const double cap = (s.demand->link == "leader_gcs" ? s.leader_gcs_bandwidth_bytes_per_s
                                                           : s.member_leader_bandwidth_bytes_per_s).value_or(0);
        return e + ", " + s.demand->link + " cap " + analysis::format_number(s.demand->fraction, 3) + " x " +
               s.demand->basis + " = " + analysis::format_rate(cap);
      }
      return e + ", leader-gcs cap " + analysis::format_rate(s.leader_gcs_bandwidth_bytes_per_s.value_or(0));
    }
    case ExperimentKind::kLoss:
      return "loss " + analysis::format_number(100.0 * s.loss.value_or(0), 0) + " %";
    case ExperimentKind::kExplore:
      break;
  }
  return "";
}

std::string progress_line(const ExperimentPlan& plan, const ExperimentRun& run,
                          const RunOutcome& o) {
  std::string line = map_label(run.map) + " " + run.method;
  const std::string setting = setting_text(plan.kind, run.setting);
  if (!setting.empty()) line += ", " + setting;
  line += ", seed " + std::to_string(run.seed) + ": ";
  if (!o.ok) {
    line += "FAILED: " + o.message;
    if (!o.log_path.empty()) line += "; log: " + o.log_path;
    return line;
  }
  std::string why;
  const auto n = load_run_numbers(o.run_dir, why);
  if (!n) return line + "FAILED: " + why;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s%.0f steps, %.0f rounds",
                n->ended_early() ? "ENDED EARLY (the GCS declared it complete), "
                : n->complete    ? ""
                                 : "INCOMPLETE, ",
                n->steps, n->planning_rounds);
  line += buf;
  if (n->steps_to_99) {
    std::snprintf(buf, sizeof buf, ", 99 %% at %.0f", *n->steps_to_99);
    line += buf;
  }
  std::snprintf(buf, sizeof buf, ", %.1f %% explored, %.1f s", 100.0 * n->explored_fraction,
                o.wall_seconds);
  line += buf;
  if (plan.kind == ExperimentKind::kBandwidth) {
    line += ", map traffic " + format_bytes(n->map_bytes);
  }
  if (!o.picture_error.empty()) line += " (picture failed: " + o.picture_error + ")";
  return line;
}

std::string duration_text(double seconds) {
  const long s = std::lround(seconds);
  char buf[64];
  if (s >= 60) {
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ld s", s);
  }
  return buf;
}

std::string plan_text(const ExperimentPlan& p) {
  const std::size_t settings = analysis::settings_of(p).size();
  std::string s = std::to_string(p.runs.size()) + " runs (" + std::to_string(p.maps.size()) +
                  (p.maps.size() == 1 ? " map" : " maps") + " x " +
                  std::to_string(p.methods.size()) +
                  (p.methods.size() == 1 ? " method" : " methods");
  if (settings > 1) s += " x " + std::to_string(settings) + " settings";
  s += " x " + std::to_string(p.seeds) + (p.seeds == 1 ? " seed" : " seeds") + ")";
  return s;
}

// "demand per sender, measured uncapped on maze1 (3 runs): leader_gcs mean 0.21 kB/s, peak 1.9 kB/s; ..."
std::string demand_text(const ExperimentPlan& plan) {
  std::string s;
  for (const auto& [map, links] : plan.demand) {
    s += "demand per sender, measured uncapped on " + map + ":";
    std::string sep = " ";
    for (const auto& [link, d] : links) {
      s += sep + link + " mean " + analysis::format_rate(d.mean_bytes_per_s) + ", peak " +
           analysis::format_rate(d.peak_bytes_per_s);
      if (!d.busiest_sender.empty()) {
        s += ", busiest sender (" + d.busiest_sender_text() + ") mean " + analysis::format_rate(d.busiest_mean_bytes_per_s);
      }
      s += " (" + std::to_string(d.runs) + " runs)";
      sep = "; ";
    }
    s += "\n";
  }
  return s;
}

// Copies a run's pictures to DIR/pictures/<map>-<method>-<file>.
void collect_pictures(const std::string& dir, const ExperimentRun& run, const RunOutcome& o) {
  std::error_code ec;
  const fs::path pictures = fs::path(dir) / "pictures";
  fs::create_directories(pictures, ec);
  for (const std::string& p : o.pictures) {
    const fs::path to = pictures / (map_label(run.map) + "-" + run.method + "-" +
                                    fs::path(p).filename().string());
    fs::copy_file(p, to, fs::copy_options::overwrite_existing, ec);
  }
}

}  // namespace

int experiment_command(const ExperimentOptions& o, std::ostream& out, std::ostream& err) {
  const std::string me = "swarm experiment " + kind_name(o.kind);
  ExperimentPlan plan;
  std::string dir;
  const std::string bin_dir = o.bin_dir.empty() ? executable_dir() : o.bin_dir;
  try {
    const auto maps = check_maps(o.maps.empty() ? default_maps(o.kind) : o.maps);
    const auto methods = check_methods(o.methods.empty() ? default_methods(o.kind) : o.methods);
    const std::int64_t seeds = o.seeds.value_or(default_seeds(o.kind));
    if (seeds < 1 || seeds > 10000) {
      throw BadInput("--seeds " + std::to_string(seeds) +
                     ": the number of seeds must be between 1 and 10000 (seeds 1..N are run)");
    }
    if (o.jobs && (*o.jobs < 1 || *o.jobs > 64)) {
      throw BadInput("--jobs " + std::to_string(*o.jobs) +
                     ": runs at once must be between 1 and 64 (default: the core count)");
    }
    // The base scenario and every map must work before anything runs.
    const std::string scenario_path =
        o.scenario_path.empty()
            ? (fs::path(cfg::data_dir()) / "scenarios" / "default.pbtxt").string()
            : o.scenario_path;
    swarm::scenario::Scenario base;
    try {
      base = cfg::load_scenario(scenario_path);
      for (const std::string& map : maps) {
        swarm::scenario::Scenario s = base;
        RunOverrides ov;
        ov.map = map;
        ov.mission = o.mission;
        apply_overrides(s, ov);
        cfg::World world = cfg::resolve_world(s, fs::absolute(scenario_path).parent_path().string(), scenario_path);
        swarm::tasks::resolve_mission(world, scenario_path);
      }
    } catch (const cfg::ConfigError& e) {
      throw BadInput(e.what());
    }
    plan = make_plan(o.kind, maps, methods, static_cast<std::uint32_t>(seeds), base,
                     o.scenario_path.empty() ? "" : fs::absolute(o.scenario_path).string(), sweep_choices(o));
    plan.mission = o.mission;

    dir = o.out_dir.empty() ? "runs/experiment-" + kind_name(o.kind) + "-" +
                                  local_timestamp(std::time(nullptr))
                            : o.out_dir;
    dir = fs::absolute(dir).lexically_normal().string();
    if (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    std::error_code ec;
    if (fs::exists(fs::path(dir) / kManifestFile, ec)) {
      throw BadInput(dir + " already holds an experiment; choose another --out DIR (`swarm " +
                     "report " + dir + "` redraws its tables)");
    }
    fs::create_directories(dir, ec);
    if (ec) {
      throw BadInput("cannot create the output directory " + dir + " (" + ec.message() +
                     "); choose a writable one with --out DIR");
    }
    try {
      write_manifest(dir, plan);
    } catch (const std::exception& e) {
      throw BadInput(std::string(e.what()) + "; choose a writable output directory with --out DIR");
    }
  } catch (const BadInput& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }
  for (const char* exe : {"swarm-sim", "swarm-gcs", "swarm-leader", "swarm-member"}) {
    const std::string path = (fs::path(bin_dir) / exe).string();
    if (::access(path.c_str(), X_OK) != 0) {
      err << me << ": cannot run " << path << " (" << std::strerror(errno)
          << "); the role binaries must sit beside `swarm` (build them all: cmake --build build)\n";
      return 1;
    }
  }

  const auto job_of = [&](const ExperimentRun& r) {
    RunJob j;
    j.options.scenario_path = plan.scenario;
    j.options.overrides.map = r.map;
    j.options.overrides.mode = r.method;
    j.options.overrides.seed = r.seed;
    j.options.overrides.mission = plan.mission;
    j.options.out_dir = (fs::path(dir) / r.dir).string();
    j.options.timeout = o.timeout;
    j.options.bin_dir = bin_dir;
    const RunSetting setting = r.setting;
    j.options.customize = [setting](swarm::scenario::Scenario& s) { setting.apply(s); };
    j.pictures = r.pictures;
    return j;
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  RunnerOptions ro;
  ro.jobs = static_cast<int>(o.jobs.value_or(cores));
  ro.first_domain = domain_id_for(::getpid());
  out << me << ": " << plan_text(plan) << ", " << ro.jobs << " at a time, into " << dir << "\n";
  out.flush();

  const auto start = std::chrono::steady_clock::now();
  std::size_t finished = 0;
  const int width = static_cast<int>(std::to_string(plan.runs.size()).size());
  // Runs the plan's runs `which`, ro.jobs at a time; false when interrupted.
  const auto run_batch = [&](const std::vector<std::size_t>& which) {
    std::vector<RunJob> jobs;
    for (const std::size_t i : which) jobs.push_back(job_of(plan.runs[i]));
    ro.on_finished = [&](std::size_t k, const RunOutcome& outcome) {
      ExperimentRun& run = plan.runs[which[k]];
      if (outcome.interrupted) return;  // stays pending
      ++finished;
      run.status = outcome.ok ? RunStatus::kOk : RunStatus::kFailed;
      run.failure = outcome.ok ? "" : outcome.message;
      run.log = outcome.log_path.empty() ? "" : fs::relative(outcome.log_path, dir).string();
      if (!outcome.pictures.empty()) collect_pictures(dir, run, outcome);
      try {
        write_manifest(dir, plan);
      } catch (const std::exception& e) {
        err << me << ": " << e.what() << "\n";
      }
      char head[32];
      std::snprintf(head, sizeof head, "[%*zu/%zu] ", width, finished, plan.runs.size());
      out << head << progress_line(plan, run, outcome) << "\n";
      out.flush();
    };
    const std::vector<RunOutcome> outcomes = run_jobs(jobs, ro);
    return std::none_of(outcomes.begin(), outcomes.end(), [](const RunOutcome& x) { return x.interrupted; });
  };
  // First every run whose setting is known; then (bandwidth) the caps set from the demand those
  // measured.
  std::vector<std::size_t> now, later;
  for (std::size_t i = 0; i < plan.runs.size(); ++i) (plan.runs[i].setting.waits_for_demand() ? later : now).push_back(i);
  bool whole = run_batch(now);
  if (whole && !later.empty()) {
    const std::vector<std::string> missing = resolve_demand(plan, load_rows(dir, plan));
    out << demand_text(plan);
    std::vector<std::size_t> ready;
    for (const std::size_t i : later) {
      ExperimentRun& run = plan.runs[i];
      if (!run.setting.waits_for_demand()) {
        ready.push_back(i);
        continue;
      }
      run.status = RunStatus::kFailed;
      run.failure = "not run: no demand measured on " + map_label(run.map) +
                    " (every uncapped run failed, ended early or left no traffic.csv)";
    }
    if (!missing.empty()) err << me << ": no demand measured on " << join(missing) << "; their capped runs are not run\n";
    try {
      write_manifest(dir, plan);
    } catch (const std::exception& e) {
      err << me << ": " << e.what() << "\n";
    }
    whole = run_batch(ready);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!whole) {
    err << me << ": interrupted after " << finished << " of " << plan.runs.size()
        << " runs; `swarm report " << dir << "` tables the finished ones\n";
    return 130;
  }
  const std::vector<RunRow> rows = load_rows(dir, plan);
  const auto failed =
      std::count_if(rows.begin(), rows.end(), [](const RunRow& r) { return !r.numbers; });
  const auto early = std::count_if(rows.begin(), rows.end(), [](const RunRow& r) {
    return r.numbers && r.numbers->ended_early();
  });
  out << plan.runs.size() << " runs in " << duration_text(seconds) << " (" << failed << " failed";
  if (early > 0) out << ", " << early << " ended early";
  out << ")\n\n";

  const ExperimentOutputs outputs = analyze_experiment(plan, rows);
  out << outputs.table << "\n";
  try {
    for (const std::string& f : write_outputs(dir, outputs)) out << "wrote " << f << "\n";
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return 1;
  }
  if (fs::exists(fs::path(dir) / "pictures")) {
    out << "pictures (map and mid-run frontier snapshot of seed 1 of every map and method): "
        << (fs::path(dir) / "pictures").string() << "\n";
  }
  return failed > 0 || early > 0 ? 1 : 0;
}

}  // namespace swarm::tools
