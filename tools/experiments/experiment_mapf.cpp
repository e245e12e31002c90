#include "experiment_mapf.hpp"

#include "format.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "mapf_maps.hpp"
#include "plot.hpp"
#include "stats.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm/planner/mapf/warehouse.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
namespace pm = swarm::planner::mapf;

struct Run {
  std::string part;    // "paper" or "movingai"
  std::string map;
  std::string solver;
  int agents = 0;
  int instance = 0;    // (a) 0-based run index; (b) scenario number 1..N
  // results
  std::string status;
  long long soc = -1, lb = -1;
  int makespan = -1, collisions = 0;
  double work = NAN, stop = NAN, seconds = 0;
};

Colour solver_colour(const std::string& s) {
  if (s == "cbs") return {0, 114, 178};
  if (s == "ga") return {213, 94, 0};
  if (s == "ga1") return {230, 159, 0};
  if (s == "ecbs") return {0, 158, 115};
  if (s == "lacam") return {204, 121, 167};
  return {120, 120, 120};
}

std::string solver_label(const std::string& s) {
  if (s == "ga") return "GA two-stage";
  if (s == "ga1") return "GA single-stage";
  if (s == "cbs") return "CBS";
  if (s == "ecbs") return "ECBS";
  if (s == "lacam") return "LaCAM*";
  return s;
}

pm::SolverConfig config_for(const MapfExperimentOptions& o, const std::string& solver, bool paper, int instance) {
  pm::SolverConfig cfg;
  (void)pm::parse_solver(solver, cfg.kind);
  cfg.ecbs.w = o.w;
  if (paper) cfg.cbs.timeout_plan = cfg.ecbs.timeout_plan = pm::TimeoutPlan::LastExpanded;  // the paper's rule
  cfg.ga.seed = cfg.lacam.seed = o.seed + static_cast<std::uint64_t>(instance);
  if (o.ga_population > 0) cfg.ga.population = o.ga_population;
  if (o.ga_generations1 >= 0) cfg.ga.stage1_generations = o.ga_generations1;
  if (o.ga_generations2 >= 0) cfg.ga.stage2_generations = o.ga_generations2;
  if (o.ga_elite >= 0) cfg.ga.elite = o.ga_elite;
  if (o.ga_initial_idle >= 0) cfg.ga.max_initial_idle = o.ga_initial_idle;
  if (o.ga_crossover >= 0) cfg.ga.crossover_rate = o.ga_crossover;
  if (o.ga_mutation >= 0) cfg.ga.mutation_rate = o.ga_mutation;
  return cfg;
}

void record(Run& run, const pm::Instance& in, const pm::Result& r) {
  run.status = pm::to_string(r.status);
  run.soc = r.soc;
  run.lb = r.lower_bound;
  run.makespan = r.makespan;
  run.collisions = r.conflicts;
  run.seconds = r.seconds;
  if (!r.paths.empty()) {
    double work = 0, stop = 0;
    for (int a = 0; a < in.agents(); ++a) {
      work += pm::path_cost(in, a, r.paths[static_cast<std::size_t>(a)]);
      stop += pm::idle_steps(in, a, r.paths[static_cast<std::size_t>(a)]);
    }
    run.work = work / in.agents();
    run.stop = stop / in.agents();
  }
}

// Runs `runs[first..]` on `jobs` threads; `solve_one` fills one run. Progress under a lock.
template <class F>
void run_parallel(std::vector<Run>& runs, std::size_t first, int jobs, std::size_t& finished, std::size_t total,
                  std::ostream& out, F solve_one) {
  std::atomic<std::size_t> next{first};
  std::mutex lock;
  std::vector<std::thread> pool;
  for (int j = 0; j < std::max(1, jobs); ++j) {
    pool.emplace_back([&] {
      for (std::size_t i = next++; i < runs.size(); i = next++) {
        solve_one(runs[i]);
        std::lock_guard<std::mutex> g(lock);
        ++finished;
        const Run& r = runs[i];
        out << "[" << finished << "/" << total << "] " << r.map << " " << r.solver << " " << r.agents << " agents #"
            << r.instance << ": " << r.status << ", " << r.collisions << " collisions, soc " << r.soc << ", "
            << fixed(r.seconds, 2) << " s\n"
            << std::flush;
      }
    });
  }
  for (auto& t : pool) t.join();
}

Summary summarize_runs(const std::vector<Run>& runs, const std::string& part, const std::string& map,
                       const std::string& solver, int agents, double Run::*field) {
  std::vector<double> v;
  for (const Run& r : runs) {
    if (r.part == part && r.map == map && r.solver == solver && r.agents == agents && std::isfinite(r.*field)) v.push_back(r.*field);
  }
  return summarize(v);
}

}  // namespace

int experiment_mapf_command(const MapfExperimentOptions& o, std::ostream& out, std::ostream& err) {
  const auto bad = [&](const std::string& m) {
    err << "swarm experiment mapf: " << m << "\n";
    return 2;
  };
  if (o.part != "paper" && o.part != "movingai" && o.part != "all") return bad("--part: expected paper, movingai or all (got '" + o.part + "')");
  for (const auto& lists : {o.paper_solvers, o.movingai_solvers}) {
    for (const std::string& s : lists) {
      pm::SolverKind k;
      if (!pm::parse_solver(s, k)) return bad("--solvers: unknown solver '" + s + "' (expected cbs, ecbs, lacam, ga, ga1)");
    }
  }
  if (o.runs < 1 || o.scenarios < 1 || o.jobs < 1) return bad("--runs, --scenarios and --jobs must be at least 1");
  const bool do_paper = o.part != "movingai";
  const bool do_movingai = o.part != "paper";
  const auto wsize = pm::parse_warehouse_name(o.warehouse);
  if (do_paper && !wsize) return bad("--world: expected warehouse-RxC, e.g. warehouse-5x8 (got '" + o.warehouse + "')");
  std::vector<std::string> maps = o.maps;
  if (do_movingai) {
    if (!fs::is_directory(o.movingai_dir)) {
      return bad("--movingai: no folder " + o.movingai_dir + " (give the folder of the MovingAI .map and .scen files)");
    }
    if (maps.empty()) {
      for (const auto& e : fs::directory_iterator(o.movingai_dir)) {
        if (e.path().extension() == ".map") maps.push_back(e.path().stem().string());
      }
      std::sort(maps.begin(), maps.end());
    }
    for (const std::string& m : maps) {
      if (!fs::is_regular_file(fs::path(o.movingai_dir) / (m + ".map"))) return bad("--maps: no file " + m + ".map in " + o.movingai_dir);
    }
  }
  const std::string dir = o.out_dir.empty() ? "runs/experiment-mapf-" + local_timestamp() : o.out_dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) return bad("--out: cannot create the directory " + dir);

  std::vector<Run> runs;
  std::size_t finished = 0;
  std::string table_text;

  // ---- (a) the paper's Tables 1 and 2 --------------------------------------------------------------
  if (do_paper) {
    for (int k : o.robots) {
      for (int r = 0; r < o.runs; ++r) {
        for (const std::string& s : o.paper_solvers) runs.push_back({"paper", o.warehouse, s, k, r});
      }
    }
    out << "(a) the paper's world " << o.warehouse << ": " << runs.size() << " runs, limit " << fixed(o.cbs_limit_s, 0)
        << " s each, " << o.jobs << " at a time\n" << std::flush;
    run_parallel(runs, 0, o.jobs, finished, runs.size(), out, [&](Run& run) {
      const pm::Instance in = pm::random_warehouse_instance(wsize->rows, wsize->cols, run.agents,
                                                           o.seed + static_cast<std::uint64_t>(run.instance));
      record(run, in, pm::solve(in, config_for(o, run.solver, true, run.instance), pm::StopCondition::after(o.cbs_limit_s)));
    });

    std::vector<std::string> header{""};
    for (int k : o.robots) header.push_back(std::to_string(k));
    TextTable t(header);
    // The summaries read a double field: collisions go through a copy whose `seconds` holds them.
    std::vector<Run> as_collisions = runs;
    for (Run& r : as_collisions) r.seconds = r.collisions;
    const auto section_from = [&](const std::vector<Run>& source, const std::string& title, double Run::*field, int decimals) {
      t.add_section(title);
      for (const std::string& s : o.paper_solvers) {
        std::vector<std::string> row{"  " + solver_label(s)};
        for (int k : o.robots) row.push_back(fixed(summarize_runs(source, "paper", o.warehouse, s, k, field).mean, decimals));
        t.add_row(row);
      }
    };
    section_from(as_collisions, "collisions per run (paper, Table 2: CBS 0, 0, 1.18, 7.79, 26.31; two-stage GA 0.01, 0.03, 0.19, 1.14, 1.60; Table 1 single-stage 0.01, 0.04, 0.22, 1.37, 2.18)", &Run::seconds, 2);
    section_from(runs, "work time per robot, time steps (paper: CBS 8.62 .. 9.00; two-stage 8.99, 8.96, 10.20, 10.92, 11.79; single 8.99, 9.07, 10.90, 11.74, 14.48)", &Run::work, 2);
    section_from(runs, "stop time per robot, time steps (paper: CBS 0.05 .. 0.27; two-stage 0.08, 0.51, 1.34, 2.14, 3.16; single 0.08, 0.62, 2.04, 2.96, 5.85)", &Run::stop, 2);
    section_from(runs, "compute time, s (paper, MATLAB: CBS 0.1, 1.3, 72.1, 360.3, 574.0; GA 1.3, 3.5, 17.1, 24.8, 105.6)", &Run::seconds, 3);
    std::vector<Run> as_timeouts = runs;
    for (Run& r : as_timeouts) r.seconds = r.status == "solved" ? 0.0 : 1.0;
    t.add_section("runs not solved (timeout or collisions left), of " + std::to_string(o.runs));
    for (const std::string& s : o.paper_solvers) {
      std::vector<std::string> row{"  " + solver_label(s)};
      for (int k : o.robots) {
        const Summary sm = summarize_runs(as_timeouts, "paper", o.warehouse, s, k, &Run::seconds);
        row.push_back(std::to_string(static_cast<int>(std::lround(sm.mean * static_cast<double>(sm.n)))));
      }
      t.add_row(row);
    }
    table_text += "(a) The paper's Tables 1 and 2 on " + o.warehouse + ", " + std::to_string(o.runs) +
                  " random instances per robot count, every solver limited to " + fixed(o.cbs_limit_s, 0) +
                  " s (a timed-out CBS returns its last CT node)\n" + t.render();

    // The paper's claims, checked.
    const auto mean_of_runs = [&](const std::vector<Run>& src, const std::string& s, int k, double Run::*f) {
      return summarize_runs(src, "paper", o.warehouse, s, k, f).mean;
    };
    const bool have = [&] {
      const auto has = [&](const char* s) { return std::find(o.paper_solvers.begin(), o.paper_solvers.end(), s) != o.paper_solvers.end(); };
      return has("ga") && has("ga1") && has("cbs");
    }();
    if (have) {
      std::string claims = "\nThe paper's claims on our runs:\n";
      bool fewer_collisions = true, fewer_stops = true, cbs_worse = true;
      std::string detail_c, detail_s, detail_cbs;
      for (int k : o.robots) {
        if (k <= 5) continue;
        const double c2 = mean_of_runs(as_collisions, "ga", k, &Run::seconds), c1 = mean_of_runs(as_collisions, "ga1", k, &Run::seconds);
        const double s2 = mean_of_runs(runs, "ga", k, &Run::stop), s1 = mean_of_runs(runs, "ga1", k, &Run::stop);
        fewer_collisions = fewer_collisions && c2 <= c1;
        fewer_stops = fewer_stops && s2 <= s1;
        detail_c += " " + std::to_string(k) + ": " + fixed(c2, 2) + " vs " + fixed(c1, 2) + ";";
        detail_s += " " + std::to_string(k) + ": " + fixed(s2, 2) + " vs " + fixed(s1, 2) + ";";
        if (k >= 20) {
          const double cc = mean_of_runs(as_collisions, "cbs", k, &Run::seconds);
          cbs_worse = cbs_worse && cc > c2;
          detail_cbs += " " + std::to_string(k) + ": CBS " + fixed(cc, 2) + " vs GA " + fixed(c2, 2) + ";";
        }
      }
      claims += std::string("  two-stage GA has no more collisions than single-stage (robots > 5): ") + (fewer_collisions ? "yes" : "NO") +
                " (two vs single," + detail_c + ")\n";
      claims += std::string("  two-stage GA stops less than single-stage (robots > 5): ") + (fewer_stops ? "yes" : "NO") + " (" +
                detail_s + ")\n";
      if (!detail_cbs.empty()) {
        claims += std::string("  CBS's time-outs leave more collisions than the two-stage GA at 20+ robots: ") +
                  (cbs_worse ? "yes" : "NO") + " (" + detail_cbs + ")\n";
      }
      table_text += claims;
    }

    Figure f;
    f.title = "The paper's world " + o.warehouse + ": mean over " + std::to_string(o.runs) + " instances";
    f.panel_width = 480;
    f.panel_height = 400;
    std::vector<std::string> ticks;
    for (int k : o.robots) ticks.push_back(std::to_string(k));
    const auto panel = [&](const std::vector<Run>& src, const std::string& title, const std::string& y, double Run::*field) {
      LinePanel p{title, y, ticks, {}, "robots"};
      for (const std::string& s : o.paper_solvers) {
        PlotSeries ser{solver_label(s), solver_colour(s), {}, {}};
        for (int k : o.robots) ser.values.push_back(summarize_runs(src, "paper", o.warehouse, s, k, field).mean);
        p.series.push_back(ser);
      }
      return p;
    };
    f.panels.push_back(panel(as_collisions, "Collisions", "collisions", &Run::seconds));
    f.panels.push_back(panel(runs, "Work time per robot", "time steps", &Run::work));
    f.panels.push_back(panel(runs, "Stop time per robot", "time steps", &Run::stop));
    f.panels.push_back(panel(runs, "Compute time", "s", &Run::seconds));
    write_figure_png(f, (fs::path(dir) / "paper.png").string());
  }

  // ---- (b) MovingAI: success rate and sum of costs / lower bound vs agents ---------------------------
  if (do_movingai) {
    const std::size_t first = runs.size();
    std::size_t planned = 0;
    for (std::size_t m = 0; m < maps.size(); ++m) planned += o.agents.size() * o.movingai_solvers.size() * static_cast<std::size_t>(o.scenarios);
    out << "(b) MovingAI maps (" << maps.size() << "), up to " << planned << " runs, limit " << fixed(o.time_limit_s, 0)
        << " s each; a solver stops at the first agent count it solves nowhere\n" << std::flush;
    std::map<std::string, MapfMap> loaded;
    std::map<std::string, std::vector<pm::Scenario>> scens;
    try {
      for (const std::string& m : maps) {
        loaded[m] = load_mapf_map((fs::path(o.movingai_dir) / (m + ".map")).string());
        for (int s = 1; s <= o.scenarios; ++s) {
          scens[m].push_back(pm::load_movingai_scen((fs::path(o.movingai_dir) / (m + "-random-" + std::to_string(s) + ".scen")).string()));
        }
      }
    } catch (const std::exception& e) {
      return bad(e.what());
    }
    std::map<std::pair<std::string, std::string>, bool> given_up;
    const std::size_t total = first + planned;
    for (int k : o.agents) {
      const std::size_t level = runs.size();
      for (const std::string& m : maps) {
        for (const std::string& s : o.movingai_solvers) {
          if (given_up[{m, s}]) continue;
          for (int sc = 1; sc <= o.scenarios; ++sc) {
            if (k > static_cast<int>(scens[m][static_cast<std::size_t>(sc - 1)].rows.size())) continue;
            runs.push_back({"movingai", m, s, k, sc});
          }
        }
      }
      run_parallel(runs, level, o.jobs, finished, total, out, [&](Run& run) {
        const MapfMap& mm = loaded[run.map];
        const pm::Instance in = pm::instance_from_scen(mm.grid, scens[run.map][static_cast<std::size_t>(run.instance - 1)], run.agents, mm.file);
        record(run, in, pm::solve(in, config_for(o, run.solver, false, run.instance), pm::StopCondition::after(o.time_limit_s)));
      });
      for (const std::string& m : maps) {
        for (const std::string& s : o.movingai_solvers) {
          int solved = 0, tried = 0;
          for (std::size_t i = level; i < runs.size(); ++i) {
            if (runs[i].map == m && runs[i].solver == s) {
              ++tried;
              solved += runs[i].status == "solved";
            }
          }
          if (tried > 0 && solved == 0) given_up[{m, s}] = true;
        }
      }
    }
    std::vector<Run> as_success = runs, as_ratio = runs;
    for (Run& r : as_success) r.seconds = r.status == "solved" ? 100.0 : 0.0;
    for (Run& r : as_ratio) r.seconds = r.status == "solved" && r.lb > 0 ? static_cast<double>(r.soc) / static_cast<double>(r.lb) : NAN;
    table_text += "\n(b) MovingAI maps: solved / " + std::to_string(o.scenarios) + " scenarios and mean sum of costs / lower bound of the solved, within " +
                  fixed(o.time_limit_s, 0) + " s (ecbs w = " + fixed(o.w, 2) + "; '-' = not run: none solved at a smaller count)\n";
    std::vector<std::string> header{""};
    for (int k : o.agents) header.push_back(std::to_string(k));
    for (const std::string& m : maps) {
      TextTable t(header);
      t.add_section(m);
      Figure f;
      f.title = "MovingAI " + m + ": " + std::to_string(o.scenarios) + " scenarios, " + fixed(o.time_limit_s, 0) + " s limit";
      f.panel_width = 520;
      f.panel_height = 400;
      std::vector<std::string> ticks(header.begin() + 1, header.end());
      LinePanel success{"Success rate", "% solved", ticks, {}, "agents", 100};
      LinePanel ratio{"Sum of costs / lower bound (solved)", "ratio", ticks, {}, "agents"};
      for (const std::string& s : o.movingai_solvers) {
        std::vector<std::string> row{"  " + solver_label(s)};
        PlotSeries sp{solver_label(s), solver_colour(s), {}, {}}, rp{solver_label(s), solver_colour(s), {}, {}};
        for (int k : o.agents) {
          const Summary ok = summarize_runs(as_success, "movingai", m, s, k, &Run::seconds);
          const Summary rr = summarize_runs(as_ratio, "movingai", m, s, k, &Run::seconds);
          if (ok.n == 0) {
            row.push_back("-");
          } else {
            const int n_ok = static_cast<int>(std::lround(ok.mean * static_cast<double>(ok.n) / 100.0));
            row.push_back(std::to_string(n_ok) + "/" + std::to_string(ok.n) + (rr.n > 0 ? " " + fixed(rr.mean, 2) : ""));
          }
          sp.values.push_back(ok.n == 0 ? NAN : ok.mean);
          rp.values.push_back(rr.n == 0 ? NAN : rr.mean);
        }
        t.add_row(row);
        success.series.push_back(sp);
        ratio.series.push_back(rp);
      }
      f.panels = {success, ratio};
      write_figure_png(f, (fs::path(dir) / ("movingai-" + m + ".png")).string());
      table_text += t.render();
    }
  }

  // ---- files ---------------------------------------------------------------------------------------
  {
    std::ofstream csv(fs::path(dir) / "results.csv");
    csv << "part,map,solver,agents,instance,status,soc,lower_bound,makespan,collisions,work_per_agent,stop_per_agent,seconds\n";
    for (const Run& r : runs) {
      csv << r.part << ',' << r.map << ',' << r.solver << ',' << r.agents << ',' << r.instance << ',' << r.status << ','
          << r.soc << ',' << r.lb << ',' << r.makespan << ',' << r.collisions << ',' << fixed(r.work, 4) << ','
          << fixed(r.stop, 4) << ',' << fixed(r.seconds, 4) << '\n';
    }
  }
  {
    nlohmann::json j;
    j["part"] = o.part;
    j["world"] = o.warehouse;
    j["robots"] = o.robots;
    j["runs_per_count"] = o.runs;
    j["paper_time_limit"] = o.cbs_limit_s;
    j["movingai_dir"] = o.movingai_dir;
    j["maps"] = maps;
    j["agents"] = o.agents;
    j["scenarios"] = o.scenarios;
    j["time_limit"] = o.time_limit_s;
    j["w"] = o.w;
    nlohmann::json arr = nlohmann::json::array();
    for (const Run& r : runs) {
      arr.push_back({{"part", r.part}, {"map", r.map}, {"solver", r.solver}, {"agents", r.agents}, {"instance", r.instance},
                     {"status", r.status}, {"soc", r.soc}, {"lower_bound", r.lb}, {"makespan", r.makespan},
                     {"collisions", r.collisions}, {"work_per_agent", std::isfinite(r.work) ? nlohmann::json(r.work) : nlohmann::json()},
                     {"stop_per_agent", std::isfinite(r.stop) ? nlohmann::json(r.stop) : nlohmann::json()}, {"seconds", r.seconds}});
    }
    j["runs"] = arr;
    std::ofstream(fs::path(dir) / "results.json") << j.dump(1) << "\n";
  }
  std::ofstream(fs::path(dir) / "table.txt") << table_text;
  out << "\n" << table_text << "\nwrote " << dir << "/table.txt, results.csv, results.json"
      << (do_paper ? ", paper.png" : "") << (do_movingai ? ", movingai-<map>.png" : "") << "\n";
  return 0;
}

}  // namespace swarm::tools
