#include "experiment_darp.hpp"

#include "format.hpp"

#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "darp_command.hpp"
#include "swarm/planner/coverage/placement.hpp"
#include "experiment.hpp"
#include "plot.hpp"
#include "stats.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using planner::Cell;
using planner::DarpConfig;
using planner::DarpInit;
using planner::DarpResult;
using planner::DarpStatus;

const std::vector<std::string> kConditions = {"bottleneck", "entrance", "far", "near"};
const std::vector<std::string> kMethods = {"standalone", "random", "kmeans", "bfs-kmeans", "selective"};
// The paper's Tables 3 and 4 (rectangle, iterations; -1 = Failed).
const std::vector<double> kPaperFar = {0, 11, 41, 77, 154, 198, 351, 597, 676, 832};
const std::vector<double> kPaperClose = {0, 168, 225, 378, 1161, 1964, 2416, 4237, -1, -1};

struct MapInfo {
  std::string name;
  LoadedMap loaded;
  std::optional<Cell> entrance, bottleneck;  // grid cells
  long free = 0;
};

// Named places of the built-in maps (maps/generate.py): the entrance (the middle of the hall's
// bottom wall, or of the rectangle's) and the narrowest passage (a security passage; the gap
// between the rectangle's two central pillars).
MapInfo map_info(const std::string& name) {
  MapInfo m;
  m.name = name;
  m.loaded = load_darp_map(name);
  const planner::OccupancyGrid& g = m.loaded.grid;
  m.free = std::count(g.data().begin(), g.data().end(), planner::CellState::Free);
  if (name == "terminal") m.entrance = Cell{70, 5}, m.bottleneck = Cell{39, 19};
  if (name == "rectangle") m.entrance = Cell{40, 1}, m.bottleneck = Cell{39, 28};
  if (!m.entrance) {  // any other map: the free cell nearest the middle of the bottom row
    double best = 1e300;
    for (const Cell& c : planner::largest_piece(g)) {
      const double d = planner::euclidean_distance(c, {g.width() / 2, 0});
      if (d < best) best = d, m.entrance = c;
    }
  }
  return m;
}

struct Job {
  bool sweep = false;
  int map = 0;
  std::string condition;
  int robots = 0;
  int seed = 0;
  std::string method;
};

struct Outcome {
  DarpStatus status = DarpStatus::BadInput;
  int iterations = 0;
  double alpha0 = NAN, alpha1 = NAN, final_imbalance = NAN, max_deviation = NAN;
  int split = 0;
  bool repaired = false;  // the repair finished the division (DivisionMethod::Auto)
  int repair_moves = 0;
  double seconds = 0;
  std::string error;
  std::vector<Cell> robots;                // kept for the pictures (seed 1, first robot count)
  std::shared_ptr<const DarpResult> kept;  // idem
};

std::vector<Cell> starts_for(const MapInfo& m, const std::string& condition, int n, int seed, int map_index) {
  std::uint64_t tag = std::find(kConditions.begin(), kConditions.end(), condition) - kConditions.begin();
  planner::Rng rng(planner::mix_seed(seed, tag, n, map_index));
  const planner::OccupancyGrid& g = m.loaded.grid;
  if (condition == "bottleneck") return planner::cells_near(g, n, *m.bottleneck, 8, rng);
  if (condition == "entrance") return planner::bunched_cells(g, n, m.entrance, 3, rng);
  if (condition == "far") return planner::spread_cells(g, n, rng);
  return planner::bunched_cells(g, n, std::nullopt, 0, rng);
}

DarpConfig config_for(const std::string& method, const DarpExperimentOptions& o, int seed) {
  DarpConfig c;
  c.method = *planner::parse_division_method(o.division);
  c.max_iterations = o.max_iterations;
  c.distance = *planner::parse_darp_distance(o.distance);
  c.seed = planner::mix_seed(seed, 0xda49);
  if (method == "random") c.init = DarpInit::Random;
  if (method == "kmeans") c.init = DarpInit::KMeans;
  if (method == "bfs-kmeans" || method == "selective") c.init = DarpInit::BfsKMeans;
  c.reinit_always = method == "bfs-kmeans";
  return c;
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

Outcome run_job(const Job& job, const std::vector<MapInfo>& maps, const DarpExperimentOptions& o, bool keep) {
  Outcome out;
  const MapInfo& m = maps[job.map];
  planner::DarpRequest req;
  req.robots = starts_for(m, job.condition, job.robots, job.seed, job.map);
  if (static_cast<int>(req.robots.size()) < job.robots) {
    out.error = "only " + std::to_string(req.robots.size()) + " start cells";
    return out;
  }
  const double t0 = thread_seconds();
  const DarpResult r = planner::divide_areas(m.loaded.grid, req, config_for(job.method, o, job.seed));
  out.seconds = thread_seconds() - t0;
  out.status = r.status;
  out.error = r.message;
  out.iterations = r.iterations;
  out.alpha0 = r.alpha0;
  out.alpha1 = r.alpha_reinit.empty() ? NAN : r.alpha_reinit.front();
  out.final_imbalance = r.final_imbalance;
  out.max_deviation = r.max_deviation;
  out.split = r.split_regions;
  out.repaired = r.finished_by == "repair";
  out.repair_moves = r.repair_moves;
  if (keep) {
    out.robots = req.robots;
    out.kept = std::make_shared<const DarpResult>(r);
  }
  return out;
}

Colour method_colour(const std::string& m) {
  if (m == "standalone") return {213, 94, 0};
  if (m == "random") return {120, 120, 120};
  if (m == "kmeans") return {230, 159, 0};
  if (m == "bfs-kmeans") return {0, 114, 178};
  return {0, 158, 115};
}

// Per (map, condition, method): what the table shows.
struct Cellwise {
  std::vector<double> iterations;  // failed runs at I_max
  int failed = 0, runs = 0, repaired = 0;
  std::vector<double> imbalance, alpha0, alpha1, seconds;
};

std::vector<std::string> checked_list(const std::vector<std::string>& given, const std::vector<std::string>& dflt,
                                      const std::vector<std::string>& known, const std::string& flag) {
  const std::vector<std::string>& list = given.empty() ? dflt : given;
  for (const std::string& v : list) {
    if (std::find(known.begin(), known.end(), v) == known.end()) {
      std::string accepted;
      for (const std::string& k : known) accepted += (accepted.empty() ? "" : ", ") + k;
      throw DarpInputError(flag + ": unknown \"" + v + "\"; accepted: " + accepted);
    }
  }
  return list;
}

}  // namespace

int experiment_darp_command(const DarpExperimentOptions& opt, std::ostream& out, std::ostream& err) {
  DarpExperimentOptions o = opt;
  std::vector<MapInfo> maps;
  std::vector<std::string> conditions, methods;
  std::string dir = o.out_dir;
  try {
    if (o.full) {
      if (o.robots.empty()) o.robots = {6, 7, 8};
      if (!o.seeds) o.seeds = 10;
      if (!o.sweep_seeds) o.sweep_seeds = 10;
    }
    if (o.robots.empty()) o.robots = {6};
    if (!o.seeds) o.seeds = 5;
    if (!o.sweep_seeds) o.sweep_seeds = 5;
    if (*o.seeds < 1) throw DarpInputError("--seeds must be >= 1");
    if (*o.sweep_seeds < 1) throw DarpInputError("--sweep-seeds must be >= 1");
    if (o.sweep_max < 0 || o.sweep_max > 50) throw DarpInputError("--sweep-max must be 0..50");
    if (o.max_iterations < 1) throw DarpInputError("--max-iterations must be >= 1");
    for (int n : o.robots) {
      if (n < 1) throw DarpInputError("--robots: robot counts must be >= 1");
    }
    if (!planner::parse_division_method(o.division)) {
      throw DarpInputError("--division \"" + o.division + "\": expected auto or darp");
    }
    if (!planner::parse_darp_distance(o.distance)) {
      throw DarpInputError("--distance \"" + o.distance + "\": expected euclidean or geodesic");
    }
    conditions = checked_list(o.conditions, kConditions, kConditions, "--conditions");
    methods = checked_list(o.methods, {"standalone", "kmeans", "bfs-kmeans", "selective"}, kMethods, "--methods");
    for (const std::string& name : o.maps.empty() ? std::vector<std::string>{"terminal", "rectangle"} : o.maps) {
      maps.push_back(map_info(name));
      if (!maps.back().bottleneck && std::count(conditions.begin(), conditions.end(), "bottleneck")) {
        throw DarpInputError("--maps " + name + ": the bottleneck condition needs a map with a known narrowest "
                             "passage (terminal, rectangle); leave it out with --conditions");
      }
    }
    if (o.sweep_max > 0) maps.push_back(map_info("rectangle"));  // the sweep's map (last)
    if (o.jobs <= 0) o.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (dir.empty()) dir = "runs/experiment-darp-" + local_timestamp(std::time(nullptr));
    std::error_code ec;
    fs::create_directories(fs::path(dir) / "pictures", ec);
    if (ec) throw DarpInputError("--out " + dir + ": cannot create the directory (" + ec.message() + ")");
  } catch (const DarpInputError& e) {
    err << "swarm experiment darp: " << e.what() << "\n";
    return 2;
  }
  const int main_maps = static_cast<int>(maps.size()) - (o.sweep_max > 0 ? 1 : 0);

  // The plan: every method on the same starts; then the sweep.
  std::vector<Job> jobs;
  std::map<std::string, std::pair<int, int>> groups;  // group key -> (jobs, done)
  auto group_of = [&](const Job& j) {
    return (j.sweep ? "sweep " : maps[j.map].name + " ") + j.condition + " n=" + std::to_string(j.robots);
  };
  for (int m = 0; m < main_maps; ++m) {
    for (const std::string& c : conditions) {
      for (int n : o.robots) {
        for (int s = 1; s <= *o.seeds; ++s) {
          for (const std::string& method : methods) jobs.push_back({false, m, c, n, s, method});
        }
      }
    }
  }
  if (o.sweep_max > 0) {
    for (int n = 1; n <= o.sweep_max; ++n) {
      for (const std::string c : {"far", "near"}) {
        for (int s = 1; s <= *o.sweep_seeds; ++s) jobs.push_back({true, main_maps, c, n, s, "standalone"});
      }
    }
  }
  std::vector<std::string> order;
  for (const Job& j : jobs) {
    auto& g = groups[group_of(j)];
    if (g.first++ == 0) order.push_back(group_of(j));
  }
  out << "swarm experiment darp: " << jobs.size() << " runs (" << main_maps << " maps x " << conditions.size()
      << " conditions x " << o.robots.size() << " robot counts x " << *o.seeds << " seeds x " << methods.size()
      << " methods" << (o.sweep_max > 0 ? " + sweep" : "") << "), division " << o.division << ", " << o.distance
      << ", I_max " << o.max_iterations
      << ", " << o.jobs << " at once -> " << dir << "\n";

  // Run, o.jobs at once; a line per finished group.
  std::vector<Outcome> outcomes(jobs.size());
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  int groups_done = 0;
  const auto t_start = std::chrono::steady_clock::now();
  auto worker = [&] {
    for (;;) {
      const std::size_t i = next++;
      if (i >= jobs.size()) return;
      outcomes[i] = run_job(jobs[i], maps, o, !jobs[i].sweep && jobs[i].seed == 1 && jobs[i].robots == o.robots.front());
      std::lock_guard<std::mutex> lock(mutex);
      auto& g = groups[group_of(jobs[i])];
      if (++g.second < g.first) continue;
      std::ostringstream line;
      line << "[" << ++groups_done << "/" << groups.size() << "] " << group_of(jobs[i]) << ":";
      for (const std::string& method : jobs[i].sweep ? std::vector<std::string>{"standalone"} : methods) {
        std::vector<double> it;
        int failed = 0;
        for (std::size_t k = 0; k < jobs.size(); ++k) {
          if (group_of(jobs[k]) != group_of(jobs[i]) || jobs[k].method != method) continue;
          it.push_back(outcomes[k].iterations);
          failed += outcomes[k].status != DarpStatus::Converged;
        }
        line << " " << method << " " << format_mean_std(summarize(it), 0);
        if (failed > 0) line << " (" << failed << " failed)";
      }
      line << "  [" << fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count(), 0)
           << " s]";
      out << line.str() << "\n" << std::flush;
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < o.jobs; ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();

  // Aggregates.
  std::map<std::tuple<int, std::string, std::string>, Cellwise> cellwise;  // (map, condition, method)
  std::map<std::pair<std::string, int>, Cellwise> sweep;                   // (condition, n)
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& j = jobs[i];
    const Outcome& r = outcomes[i];
    Cellwise& c = j.sweep ? sweep[{j.condition, j.robots}] : cellwise[{j.map, j.condition, j.method}];
    const bool ok = r.status == DarpStatus::Converged;
    ++c.runs;
    c.failed += !ok;
    c.repaired += r.repaired;
    c.iterations.push_back(ok ? r.iterations : o.max_iterations);
    if (ok) c.imbalance.push_back(r.final_imbalance);
    c.alpha0.push_back(r.alpha0);
    if (std::isfinite(r.alpha1)) c.alpha1.push_back(r.alpha1);
    c.seconds.push_back(r.seconds);
  }
  auto mean = [](const std::vector<double>& v) { return summarize(v).mean; };
  auto pooled = [&](int m, const std::string& method) {
    Cellwise all;
    for (const std::string& c : conditions) {
      const Cellwise& x = cellwise[{m, c, method}];
      all.iterations.insert(all.iterations.end(), x.iterations.begin(), x.iterations.end());
      all.failed += x.failed;
      all.runs += x.runs;
      all.repaired += x.repaired;
      all.imbalance.insert(all.imbalance.end(), x.imbalance.begin(), x.imbalance.end());
      all.alpha0.insert(all.alpha0.end(), x.alpha0.begin(), x.alpha0.end());
      all.alpha1.insert(all.alpha1.end(), x.alpha1.begin(), x.alpha1.end());
      all.seconds.insert(all.seconds.end(), x.seconds.begin(), x.seconds.end());
    }
    return all;
  };

  std::ostringstream table;
  nlohmann::json checks = nlohmann::json::array();
  std::string robots_text;
  for (int n : o.robots) {
    if (!robots_text.empty()) robots_text += ",";
    robots_text += std::to_string(n);
  }
  for (int m = 0; m < main_maps; ++m) {
    std::vector<std::string> header{""};
    header.insert(header.end(), methods.begin(), methods.end());
    TextTable t(header);
    t.add_section("iterations, mean ± std [failed runs] (a failed run counts " + std::to_string(o.max_iterations) + ")");
    auto iter_cell = [&](const Cellwise& x) {
      std::string s = format_mean_std(summarize(x.iterations), 0);
      if (x.failed > 0) s += " [" + std::to_string(x.failed) + "]";
      return s;
    };
    for (const std::string& c : conditions) {
      std::vector<std::string> row{"  " + c};
      for (const std::string& method : methods) row.push_back(iter_cell(cellwise[{m, c, method}]));
      t.add_row(row);
    }
    std::vector<std::string> all_row{"  all"}, change_row{"  change vs standalone"}, imb_row{"  final imbalance"},
        a0_row{"  alpha0"}, a1_row{"  alpha after re-init"}, sec_row{"  seconds"},
        repaired_row{"  finished by the repair"};
    const double base = mean(pooled(m, "standalone").iterations);
    for (const std::string& method : methods) {
      const Cellwise all = pooled(m, method);
      all_row.push_back(iter_cell(all));
      change_row.push_back(method == "standalone" || !std::isfinite(base) ? "" : format_percent_change(percent_change(mean(all.iterations), base)));
      imb_row.push_back(fixed(mean(all.imbalance), 4));
      a0_row.push_back(fixed(mean(all.alpha0), 3));
      a1_row.push_back(fixed(mean(all.alpha1), 3));
      sec_row.push_back(fixed(mean(all.seconds), 4));
      repaired_row.push_back(std::to_string(all.repaired) + " of " + std::to_string(all.runs));
    }
    t.add_row(all_row);
    if (std::count(methods.begin(), methods.end(), "standalone")) t.add_row(change_row);
    t.add_section("over all conditions (final imbalance of converged runs)");
    t.add_row(imb_row);
    t.add_row(a0_row);
    t.add_row(a1_row);
    t.add_row(sec_row);
    if (o.division == "auto") t.add_row(repaired_row);
    table << maps[m].name << " (" << maps[m].free << " free cells), " << o.distance << " distances, robots " << robots_text
          << ", " << *o.seeds << " seeds per condition:\n"
          << t.render();
    if (o.division == "auto") {
      table << "(division auto: DARP runs at most " << DarpConfig{}.auto_darp_iterations
            << " iterations, then the repair finishes; the paper's comparison of iterations needs --division darp)\n";
    } else if (std::count(methods.begin(), methods.end(), "standalone") &&
               std::count(methods.begin(), methods.end(), "bfs-kmeans")) {
      const auto pct = percent_change(mean(pooled(m, "bfs-kmeans").iterations), base);
      const double paper = maps[m].name == "terminal" ? -75.0 : -59.9;
      const bool yes = pct && *pct <= -50.0;
      table << "check: BFS + K-Means (always) needs >= 50 % fewer iterations than standalone on " << maps[m].name
            << ": " << (yes ? "yes" : "NO") << " (" << format_percent_change(pct) << "; paper "
            << format_percent_change(paper) << " on its " << (maps[m].name == "terminal" ? "complex" : "normal")
            << " map)\n";
      checks.push_back({{"map", maps[m].name}, {"check", "bfs-kmeans >= 50 % fewer iterations than standalone"},
                        {"change_percent", pct ? nlohmann::json(*pct) : nlohmann::json()},
                        {"paper_percent", paper}, {"holds", yes}});
    }
    table << "\n";
  }
  if (o.sweep_max > 0) {
    TextTable t({"n", "far: alpha0", "far: iterations", "far: failed", "paper far", "close: alpha0", "close: iterations",
                 "close: failed", "paper close"});
    for (int n = 1; n <= o.sweep_max; ++n) {
      std::vector<std::string> row{std::to_string(n)};
      for (const std::string c : {"far", "near"}) {
        const Cellwise& x = sweep[{c, n}];
        const std::vector<double>& paper = c == std::string("far") ? kPaperFar : kPaperClose;
        row.push_back(fixed(mean(x.alpha0), 2));
        row.push_back(format_mean_std(summarize(x.iterations), 0));
        row.push_back(std::to_string(x.failed) + "/" + std::to_string(x.runs));
        row.push_back(n <= static_cast<int>(paper.size()) ? (paper[n - 1] < 0 ? "Failed" : fixed(paper[n - 1], 0)) : "");
      }
      t.add_row(row);
    }
    table << "rectangle sweep: standalone DARP, far (spread) vs close (bunched) starts, " << *o.sweep_seeds
          << " seeds, " << o.distance << " (paper: Tables 3 and 4):\n"
          << t.render() << "\n";
  }
  int not_converged = 0;
  double slowest = 0;
  for (const Outcome& r : outcomes) {
    not_converged += r.status != DarpStatus::Converged;
    slowest = std::max(slowest, r.seconds);
  }
  table << "division " << o.division << ": " << not_converged << " of " << outcomes.size()
        << " runs did not converge; slowest division " << fixed(slowest, 3) << " s (thread CPU)\n";
  out << "\n" << table.str();

  // Files: table, CSV, JSON, plots, pictures.
  try {
    std::ofstream(fs::path(dir) / "table.txt") << table.str();
    std::ofstream csv(fs::path(dir) / "results.csv");
    csv << "part,map,condition,robots,seed,method,division,status,finished_by,iterations,repair_moves,alpha0,"
           "alpha_reinit,final_imbalance,max_deviation,split_regions,seconds\n";
    nlohmann::json runs = nlohmann::json::array();
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      const Job& j = jobs[i];
      const Outcome& r = outcomes[i];
      csv << (j.sweep ? "sweep" : "methods") << "," << maps[j.map].name << "," << j.condition << "," << j.robots << ","
          << j.seed << "," << j.method << "," << o.division << "," << planner::to_string(r.status) << ","
          << (r.repaired ? "repair" : "darp") << "," << r.iterations << "," << r.repair_moves << ","
          << fixed(r.alpha0, 6) << "," << fixed(r.alpha1, 6) << "," << fixed(r.final_imbalance, 6) << ","
          << fixed(r.max_deviation, 2) << "," << r.split << "," << fixed(r.seconds, 6) << "\n";
      auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
      runs.push_back({{"part", j.sweep ? "sweep" : "methods"}, {"map", maps[j.map].name}, {"condition", j.condition},
                      {"robots", j.robots}, {"seed", j.seed}, {"method", j.method},
                      {"status", planner::to_string(r.status)}, {"iterations", r.iterations},
                      {"finished_by", r.repaired ? "repair" : "darp"}, {"repair_moves", r.repair_moves},
                      {"alpha0", num(r.alpha0)}, {"alpha_reinit", num(r.alpha1)},
                      {"final_imbalance", num(r.final_imbalance)}, {"max_deviation", num(r.max_deviation)},
                      {"split_regions", r.split}, {"seconds", r.seconds}, {"error", r.error}});
    }
    nlohmann::json aggregates = nlohmann::json::object();
    for (const auto& [key, x] : cellwise) {
      const auto& [m, c, method] = key;
      const Summary s = summarize(x.iterations);
      aggregates[maps[m].name][c][method] = {{"iterations_mean", s.mean}, {"iterations_std", s.std},
                                             {"failed", x.failed}, {"runs", x.runs}, {"repaired", x.repaired},
                                             {"final_imbalance_mean", mean(x.imbalance)},
                                             {"alpha0_mean", mean(x.alpha0)}, {"seconds_mean", mean(x.seconds)}};
    }
    nlohmann::json sweep_json = nlohmann::json::array();
    for (const auto& [key, x] : sweep) {
      const Summary s = summarize(x.iterations);
      sweep_json.push_back({{"condition", key.first}, {"robots", key.second}, {"iterations_mean", s.mean},
                            {"iterations_std", s.std}, {"failed", x.failed}, {"runs", x.runs},
                            {"alpha0_mean", mean(x.alpha0)}});
    }
    nlohmann::json j = {{"parameters", {{"seeds", *o.seeds}, {"robots", o.robots}, {"conditions", conditions},
                                        {"methods", methods}, {"division", o.division}, {"distance", o.distance},
                                        {"max_iterations", o.max_iterations}, {"sweep_max", o.sweep_max},
                                        {"sweep_seeds", *o.sweep_seeds}}},
                        {"runs", runs}, {"aggregates", aggregates}, {"sweep", sweep_json}, {"checks", checks}};
    std::ofstream(fs::path(dir) / "results.json") << j.dump(1) << "\n";

    Figure box{"DARP iterations per start condition (" + o.distance + ", robots " + robots_text + ", " +
                   std::to_string(*o.seeds) + " seeds; failed runs at " + std::to_string(o.max_iterations) + ")",
               {},
               640,
               480,
               "boxes: quartiles, median; whiskers: 1.5 boxes"};
    for (int m = 0; m < main_maps; ++m) {
      BoxPanel p{maps[m].name, "iterations", conditions, {}, "start condition"};
      for (const std::string& method : methods) {
        BoxSeries s{method, method_colour(method), {}};
        for (const std::string& c : conditions) s.samples.push_back(cellwise[{m, c, method}].iterations);
        p.series.push_back(s);
      }
      box.panels.push_back(p);
    }
    if (!box.panels.empty()) write_figure_png(box, (fs::path(dir) / "darp_boxplot.png").string());
    if (o.sweep_max > 0) {
      LinePanel p{"rectangle: iterations vs robots", "iterations", {}, {}, "robots"};
      PlotSeries far{"far (ours)", {0, 114, 178}, {}, {}}, close{"close (ours)", {213, 94, 0}, {}, {}};
      PlotSeries paper_far{"far (paper)", {86, 180, 233}, {}, {}}, paper_close{"close (paper)", {230, 159, 0}, {}, {}};
      for (int n = 1; n <= o.sweep_max; ++n) {
        p.x_ticks.push_back(std::to_string(n));
        const Summary f = summarize(sweep[{"far", n}].iterations), c = summarize(sweep[{"near", n}].iterations);
        far.values.push_back(f.mean);
        far.errors.push_back(f.std);
        close.values.push_back(c.mean);
        close.errors.push_back(c.std);
        auto paper_at = [&](const std::vector<double>& v) { return n <= static_cast<int>(v.size()) && v[n - 1] >= 0 ? v[n - 1] : NAN; };
        paper_far.values.push_back(paper_at(kPaperFar));
        paper_close.values.push_back(paper_at(kPaperClose));
      }
      p.series = {far, close, paper_far, paper_close};
      Figure f{"DARP on the rectangle: far vs close starts (" + o.distance + ", " + std::to_string(*o.sweep_seeds) +
                   " seeds; failed runs at " + std::to_string(o.max_iterations) + ")",
               {p},
               640,
               480,
               "error bars: std; paper: Tables 3, 4"};
      write_figure_png(f, (fs::path(dir) / "darp_sweep.png").string());
    }
    // Pictures: seed 1, the first robot count, every condition and method.
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      const Job& j = jobs[i];
      const Outcome& r = outcomes[i];
      if (!r.kept) continue;
      const planner::OccupancyGrid& g = maps[j.map].loaded.grid;
      const auto plans = planner::plan_coverage(g, *r.kept, r.robots);
      draw_division(g, r.robots, *r.kept, plans,
                    maps[j.map].name + " " + j.condition + ", " + j.method + ", " + std::to_string(j.robots) +
                        " robots: " + planner::to_string(r.status) + " after " + std::to_string(r.iterations) +
                        " iterations",
                    (fs::path(dir) / "pictures" / (maps[j.map].name + "-" + j.condition + "-" + j.method + ".png")).string());
    }
  } catch (const std::exception& e) {
    err << "swarm experiment darp: " << e.what() << "\n";
    return 1;
  }
  out << "wrote " << dir << "/{table.txt, results.csv, results.json, darp_boxplot.png"
      << (o.sweep_max > 0 ? ", darp_sweep.png" : "") << ", pictures/}\n";
  return 0;
}

}  // namespace swarm::tools
