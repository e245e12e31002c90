// `swarm report DIR...`: the tables and plots of an experiment (or of plain run directories)
// rebuilt from what is on disk, without running anything. See experiment_command.hpp.
#include <algorithm>
#include <filesystem>

#include "format.hpp"
#include "experiment_command.hpp"
#include "swarm/config/scenario.hpp"

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

}  // namespace

int report_command(const ReportOptions& o, std::ostream& out, std::ostream& err) {
  const std::string me = "swarm report";
  if (o.dirs.empty()) {
    err << me << ": no directory given; " << kWhatIsAccepted << "\n";
    return 2;
  }
  std::vector<std::string> experiments, runs;
  for (const std::string& d : o.dirs) {
    std::error_code ec;
    if (!fs::is_directory(d, ec)) {
      err << me << ": " << d << " is not a directory; " << kWhatIsAccepted << "\n";
      return 2;
    }
    if (has_file(d, kManifestFile)) {
      experiments.push_back(d);
    } else if (has_file(d, "metrics.json")) {
      runs.push_back(d);
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
      runs.insert(runs.end(), inside.begin(), inside.end());
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
      plan = plan_from_run_dirs(runs);
      rows = load_rows("", plan);
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
  const ExperimentOutputs outputs = analyze_experiment(plan, rows);
  std::vector<std::string> written;
  try {
    written = write_outputs(dir, outputs);
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "; choose a writable output directory with --out DIR\n";
    return 2;
  }
  out << outputs.table << "\n";
  for (const std::string& f : written) out << "wrote " << f << "\n";
  return 0;
}

}  // namespace swarm::tools
