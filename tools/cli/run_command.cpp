#include "run_command.hpp"

#include "live_run_view.hpp"
#include "traffic_over_time.hpp"
#include "mcap_export.hpp"

#include "run_end.hpp"

#include "format.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <regex>
#include <nlohmann/json.hpp>
#include <sstream>

#include "swarm/record/metrics.hpp"
#include "swarm/record/record.hpp"
#include "swarm/record/render.hpp"

namespace swarm::tools {

namespace fs = std::filesystem;
namespace cfg = swarm::config;

std::string format_bytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 4) {
    bytes /= 1000.0;
    ++u;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.2f %s", bytes, units[u]);
  return buf;
}

std::vector<std::string> last_lines(const std::string& path, int n) {
  std::ifstream in(path, std::ios::binary);
  std::deque<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    while (!line.empty() && line.back() == '\r') line.pop_back();
    // A progress bar redraws with '\r': keep what the terminal would show last.
    const auto cr = line.rfind('\r');
    if (cr != std::string::npos) line = line.substr(cr + 1);
    lines.push_back(line);
    if (static_cast<int>(lines.size()) > n) lines.pop_front();
  }
  return {lines.begin(), lines.end()};
}

std::string summarize_metrics(const std::string& path) {
  const swarm::record::RunMetrics m = swarm::record::read_metrics(path);  // throws, naming the key
  std::ostringstream o;
  char buf[200];
  std::string why = "stopped at --max-ticks";
  for (const auto& p : m.phases) {
    if (p.gave_up) why = "phase " + p.name + " given up: " + *p.gave_up;
    if (p.disagreement) why = "phase " + p.name + ": " + *p.disagreement;
  }
  o << (m.complete ? "  complete: the mission's every phase is done\n" : "  INCOMPLETE: " + why + "\n");
  std::snprintf(buf, sizeof buf, "  steps            %u", m.steps);
  o << buf;
  if (m.steps_to_99) {
    std::snprintf(buf, sizeof buf, " (99 %% explored at step %u)", *m.steps_to_99);
    o << buf;
  }
  o << "\n";
  for (const auto& p : m.phases) {
    std::snprintf(buf, sizeof buf, "  phase %-10s ticks %u-%s%s", p.name.c_str(), p.start_tick,
                  p.end_tick ? std::to_string(*p.end_tick).c_str() : "", p.complete ? "" : " (not complete)");
    o << buf;
    // The task's ground-truth headline, as the simulator judged it.
    if (p.task.contains("covered_fraction") && p.task["covered_fraction"].is_number()) {
      std::snprintf(buf, sizeof buf, ", covered %.1f %% (ground truth)", 100.0 * p.task["covered_fraction"].get<double>());
      o << buf;
    }
    if (p.task.contains("ground_truth_at_goal") && p.task["ground_truth_at_goal"].is_number() &&
        p.task.contains("ground_truth_living") &&
        p.task["ground_truth_living"].is_number()) {
      const int at = p.task["ground_truth_at_goal"].get<int>(), living = p.task["ground_truth_living"].get<int>();
      std::snprintf(buf, sizeof buf, ", %d/%d robots at goal (ground truth)", at, living);
      o << buf;
    }
    std::snprintf(buf, sizeof buf, ", %llu conflicts", static_cast<unsigned long long>(p.motion.vertex_conflict_events +
                                                                                       p.motion.edge_conflict_events));
    o << buf << "\n";
    if (p.disagreement) o << "    they disagree: " << *p.disagreement << "\n";
  }
  std::snprintf(buf, sizeof buf, "  planning rounds  %u\n", m.planning_rounds);
  o << buf;
  std::snprintf(buf, sizeof buf, "  explored         %.1f %%\n", 100.0 * m.explored_fraction);
  o << buf;
  std::snprintf(buf, sizeof buf, "  conflicts        %llu vertex, %llu edge, %llu blocked moves, %llu wall stops\n",
                static_cast<unsigned long long>(m.motion.vertex_conflict_events),
                static_cast<unsigned long long>(m.motion.edge_conflict_events),
                static_cast<unsigned long long>(m.motion.total.blocked_moves),
                static_cast<unsigned long long>(m.motion.total.wall_stops));
  o << buf;
  // The robot held up longest by another (the simulator's ground truth).
  const auto stuck = std::max_element(m.motion.per_robot.begin(), m.motion.per_robot.end(), [](const auto& a, const auto& b) {
    return a.second.longest_blocked_ticks < b.second.longest_blocked_ticks;
  });
  if (stuck != m.motion.per_robot.end() && stuck->second.longest_blocked_ticks > 0) {
    std::snprintf(buf, sizeof buf, "  longest block    %llu ticks in a row (%s)\n",
                  static_cast<unsigned long long>(stuck->second.longest_blocked_ticks), stuck->first.c_str());
    o << buf;
  }
  std::snprintf(buf, sizeof buf, "  wall time        %.1f s (%.1f ticks/s)\n", m.wall_seconds, m.ticks_per_second);
  o << buf;
  std::snprintf(buf, sizeof buf, " in %llu messages\n", static_cast<unsigned long long>(m.traffic.total_messages));
  o << "  traffic          " << format_bytes(static_cast<double>(m.traffic.total_bytes)) << buf;
  return o.str();
}

int check_run_command(const RunOptions& options, std::ostream& out, std::ostream& err) {
  try {
    const cfg::World w = resolve_run(options);
    const auto& s = w.scenario;
    std::string mission;
    for (const auto& ph : cfg::mission_phases(s)) mission += (mission.empty() ? "" : ",") + cfg::task_name(ph);
    out << "swarm run --check: would run " << map_label(s.map()) << " (" << w.truth.width() << " x "
        << w.truth.height() << " cells), " << s.groups() << " x " << s.robots_per_group() << " robots, mission "
        << mission << ", max_ticks " << s.max_ticks() << ", seed " << s.seed() << "; nothing was started\n";
    return 0;
  } catch (const cfg::ConfigError& e) {
    err << "swarm run: " << e.what() << "\n";
    return 2;
  }
}

int run_command(const RunOptions& options, std::ostream& out, std::ostream& err) {
  // Before anything is created: can the roles be started at all?
  const std::string bin_dir = options.bin_dir.empty() ? executable_dir() : options.bin_dir;
  for (const char* exe : {"swarm-sim", "swarm-gcs", "swarm-leader", "swarm-member"}) {
    const std::string path = (std::filesystem::path(bin_dir) / exe).string();
    if (::access(path.c_str(), X_OK) != 0) {
      err << "swarm run: cannot run " << path << " (" << std::strerror(errno)
          << "); the role binaries must sit beside `swarm` (build them all: cmake --build build)\n";
      return 1;
    }
  }
  if (!options.mcap_path.empty()) {
    const std::filesystem::path parent = std::filesystem::absolute(options.mcap_path).parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(parent, ec)) {
      err << "swarm run: --mcap " << options.mcap_path << ": the folder " << parent.string() << " does not exist\n";
      return 2;
    }
  }
  PreparedRun run;
  try {
    run = prepare_run(options);
  } catch (const cfg::ConfigError& e) {
    err << "swarm run: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // the machine's, not the user's: no free domain, no certificates
    err << "swarm run: " << e.what() << "\n";
    return 1;
  }
  const RunLaunch& l = run.launch;
  const std::vector<ProcessSpec> procs = build_run_processes(l, run.world.scenario);

  LiveRunView view;
  if (options.view) {
    const int status = view.start(options, run, out, err);
    if (status != 0) return status;
  }
  const SupervisorResult r = run_processes(procs, options.timeout);
  view.stop();
  const std::string logs = (std::filesystem::path(l.run_dir) / "logs").string();
  if (!r.ok) {
    // What the run did up to its stop, and why it stopped, in metrics.json.
    const std::string not_written = record_early_end(l.run_dir, run.world.scenario, early_end_reason(r));
    if (!not_written.empty()) err << "swarm run: no metrics.json: " << not_written << "\n";
  }
  const std::string metrics_note =
      "swarm run: what the run did up to the stop, and why it stopped: " + l.run_dir + "/metrics.json\n";
  if (r.interrupted) {
    err << "swarm run: interrupted; every process was stopped (logs: " << logs << ")\n" << metrics_note;
    return 130;
  }
  if (r.timed_out) {
    err << "swarm run: " << r.message << " (--timeout " << options.timeout.count()
        << "); every process was stopped (logs: " << logs << ")\n" << metrics_note;
    return 1;
  }
  if (!r.ok) {
    err << "swarm run: " << r.message;
    if (!r.log_path.empty()) {
      err << "; its log: " << r.log_path << "\n";
      for (const std::string& line : last_lines(r.log_path, 10)) err << "  | " << line << "\n";
    } else {
      err << "\n";
    }
    err << metrics_note;
    return 1;
  }

  const std::string record = swarm::record::run_record_path(l.run_dir);
  const std::string metrics = (std::filesystem::path(l.run_dir) / "metrics.json").string();
  const std::string png = (std::filesystem::path(l.run_dir) / "map.png").string();
  std::vector<swarm::record::Frame> frames;
  try {
    frames = swarm::record::read_record(record);
    swarm::record::render_map_png(frames, png);
  } catch (const std::exception& e) {
    err << "swarm run: every process exited normally, but the map picture failed: " << e.what()
        << "\n";
    return 1;
  }
  const std::string traffic_png = (std::filesystem::path(l.run_dir) / "traffic.png").string();
  try {
    write_traffic_files(frames, l.run_dir);
  } catch (const std::exception& e) {
    err << "swarm run: every process exited normally, but the traffic over time failed: " << e.what() << "\n";
    return 1;
  }
  if (!options.mcap_path.empty()) {
    try {
      (void)export_mcap(frames, &run.world, options.mcap_path);
    } catch (const std::exception& e) {
      err << "swarm run: every process exited normally, but the MCAP file failed: " << e.what() << "\n";
      return 1;
    }
  }
  std::string summary;
  bool complete = false;
  try {
    summary = summarize_metrics(metrics);
    complete = swarm::record::read_metrics(metrics).complete;
  } catch (const std::exception& e) {
    err << "swarm run: every process exited normally, but " << e.what() << "\n";
    return 1;
  }
  const auto& s = run.world.scenario;
  out << "run finished: " << map_label(s.map()) << ", " << cfg::mode_name(s.explore().mode())
      << ", " << s.groups() << " x " << s.robots_per_group() << " robots, seed " << s.seed()
      << "\n"
      << summary << "  map picture      " << png << "\n"
      << "  traffic / s      " << traffic_png << " (and traffic.csv)\n"
      << (options.mcap_path.empty() ? std::string() : "  mcap             " + options.mcap_path + "\n")
      << "run dir: " << l.run_dir << "\n";
  if (!complete) {
    err << "swarm run: the mission is incomplete (exit " << kExitIncomplete << "); metrics.json says why\n";
    return kExitIncomplete;
  }
  return 0;
}

}  // namespace swarm::tools
