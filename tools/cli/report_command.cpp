// `swarm report DIR...`: the tables and plots of an experiment (or of plain run directories)
// rebuilt from what is on disk, without running anything. See experiment_command.hpp.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "format.hpp"
#include "experiment.hpp"
#include "experiment_command.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/record/metrics.hpp"
#include "run_launch.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;

constexpr const char* kWhatIsAccepted =
    "give one experiment directory (with experiment.json, written by `swarm experiment`), or run "
    "directories (with metrics.json, written by `swarm run`) and folders of run directories";

bool has_file(const fs::path& dir, const char* name) {
  std::error_code ec;
  return fs::is_regular_file(dir / name, ec);
}

// A run's mission kind: its phases in order ("explore", "explore,cover,mapf,collect").
std::string mission_of(const record::RunMetrics& m) {
  std::string out;
  for (const record::PhaseMetrics& p : m.phases) out += (out.empty() ? "" : ",") + p.name;
  return out.empty() ? "explore" : out;
}

std::string file_name_of(const std::string& mission) {
  std::string out = mission;
  std::replace(out.begin(), out.end(), ',', '-');
  return out;
}

// One table of runs of a mission kind other than exploration alone: per run and phase, the
// phase's ticks, whether it was done, the simulator's conflicts and the longest block.
std::string mission_table(const std::string& mission, const std::vector<std::pair<std::string, record::RunMetrics>>& runs,
                          std::string& csv) {
  TextTable t({"run", "map", "robots", "seed", "complete", "phase", "ticks", "done", "conflicts", "longest block"});
  csv = "run,map,robots,seed,complete,ended,phase,start_tick,end_tick,ticks,done,vertex_conflicts,edge_conflicts,"
        "blocked_moves,longest_blocked_ticks\n";
  for (const auto& [dir, m] : runs) {
    bool first = true;
    for (const record::PhaseMetrics& p : m.phases) {
      const std::string ticks = p.end_tick ? std::to_string(*p.end_tick - p.start_tick) : "-";
      const std::uint64_t conflicts = p.motion.vertex_conflict_events + p.motion.edge_conflict_events;
      t.add_row({first ? fs::path(dir).filename().string() : "", first ? map_label(m.map) : "",
                 first ? std::to_string(m.robots) : "", first ? std::to_string(m.seed) : "",
                 first ? std::string(m.complete ? "yes" : "no") : "", p.name, ticks, p.complete ? "yes" : "no",
                 std::to_string(conflicts), std::to_string(p.motion.total.longest_blocked_ticks)});
      csv += csv_escape(dir) + "," + csv_escape(m.map) + "," + std::to_string(m.robots) + "," + std::to_string(m.seed) +
             "," + (m.complete ? "true" : "false") + "," + csv_escape(m.ended) + "," + p.name + "," +
             std::to_string(p.start_tick) + "," + (p.end_tick ? std::to_string(*p.end_tick) : "") + "," +
             (p.end_tick ? ticks : "") + "," + (p.complete ? "true" : "false") + "," +
             std::to_string(p.motion.vertex_conflict_events) + "," + std::to_string(p.motion.edge_conflict_events) +
             "," + std::to_string(p.motion.total.blocked_moves) + "," +
             std::to_string(p.motion.total.longest_blocked_ticks) + "\n";
      first = false;
    }
  }
  return "Mission " + mission + " (" + std::to_string(runs.size()) + " run" + (runs.size() == 1 ? "" : "s") + ")\n" +
         t.render();
}

}  // namespace

int report_command(const ReportOptions& o, std::ostream& out, std::ostream& err) {
  const std::string me = "swarm report";
  if (o.dirs.empty()) {
    err << me << ": no directory given; " << kWhatIsAccepted << "\n";
    return 2;
  }
  std::vector<std::string> experiments, runs;
  std::set<std::string> seen;  // a directory given twice (or inside a folder also given) counts once
  const auto once = [&](const std::string& d) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(d, ec);
    return seen.insert(ec ? d : c.string()).second;
  };
  for (const std::string& d : o.dirs) {
    std::error_code ec;
    if (!fs::is_directory(d, ec)) {
      err << me << ": " << d << " is not a directory; " << kWhatIsAccepted << "\n";
      return 2;
    }
    if (has_file(d, kManifestFile)) {
      if (once(d)) experiments.push_back(d);
    } else if (has_file(d, "metrics.json")) {
      if (once(d)) runs.push_back(d);
    } else {
      std::vector<std::string> inside;
      for (const auto& entry : fs::directory_iterator(d, ec)) {
        if (entry.is_directory() && has_file(entry.path(), "metrics.json")) {
          inside.push_back(entry.path().string());
        }
      }
      if (inside.empty()) {
        err << me << ": " << d << " holds no runs; " << kWhatIsAccepted << "\n";
        return 2;
      }
      std::sort(inside.begin(), inside.end());
      for (const std::string& r : inside) {
        if (once(r)) runs.push_back(r);
      }
    }
  }
  if (experiments.size() > 1 || (!experiments.empty() && !runs.empty())) {
    err << me << ": cannot merge " << experiments.size() << " experiment director"
        << (experiments.size() == 1 ? "y" : "ies") << (runs.empty() ? "" : " and run directories")
        << "; " << kWhatIsAccepted << "\n";
    return 2;
  }

  ExperimentPlan plan;
  std::vector<RunRow> rows;
  std::map<std::string, std::vector<std::pair<std::string, record::RunMetrics>>> by_mission;
  std::string dir = o.out_dir;
  try {
    if (!experiments.empty()) {
      plan = read_manifest(experiments.front());
      if (plan.runs.empty()) {
        err << me << ": " << experiments.front() << "/" << kManifestFile << " lists no runs; "
            << kWhatIsAccepted << "\n";
        return 2;
      }
      rows = load_rows(experiments.front(), plan);
      if (dir.empty()) dir = experiments.front();
    } else {
      // Exploration alone goes into the exploration tables; every other mission kind (its phase
      // list) gets a table of its own, so that unlike runs are never pooled.
      std::vector<std::string> explore_runs;
      for (const std::string& r : runs) {
        record::RunMetrics m;
        try {
          m = record::read_metrics((fs::path(r) / "metrics.json").string());
        } catch (const record::PartialMetricsError& e) {
          // A run stopped before the GCS wrote its metrics: nothing to table, and said so.
          err << me << ": skipped " << e.what() << "\n";
          continue;
        } catch (const record::MetricsError& e) {
          throw swarm::config::ConfigError(r + " is not a usable run directory: " + e.what());
        }
        const std::string mission = mission_of(m);
        if (mission == "explore") {
          explore_runs.push_back(r);
        } else {
          by_mission[mission].emplace_back(r, std::move(m));
        }
      }
      if (!explore_runs.empty()) {
        plan = plan_from_run_dirs(explore_runs);
        rows = load_rows("", plan);
      }
      if (explore_runs.empty() && by_mission.empty()) {
        err << me << ": no run there has whole metrics (every one ended early); " << kWhatIsAccepted << "\n";
        return 2;
      }
      if (dir.empty()) dir = "runs/report-" + local_timestamp(std::time(nullptr));
    }
  } catch (const swarm::config::ConfigError& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }

  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    err << me << ": cannot create the output directory " << dir << " (" << ec.message()
        << "); choose a writable one with --out DIR\n";
    return 2;
  }
  std::vector<std::string> written;
  try {
    if (!plan.runs.empty()) {
      const ExperimentOutputs outputs = analyze_experiment(plan, rows);
      written = write_outputs(dir, outputs);
      out << outputs.table << "\n";
    }
    for (const auto& [mission, mission_runs] : by_mission) {
      std::string csv;
      const std::string table = mission_table(mission, mission_runs, csv);
      const std::string stem = (fs::path(dir) / ("mission-" + file_name_of(mission))).string();
      write_file(stem + ".txt", table);
      write_file(stem + ".csv", csv);
      written.push_back(stem + ".txt");
      written.push_back(stem + ".csv");
      out << table << "\n";
    }
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "; choose a writable output directory with --out DIR\n";
    return 2;
  }
  for (const std::string& f : written) out << "wrote " << f << "\n";
  return 0;
}

}  // namespace swarm::tools
