#include "experiment_mission.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "experiment.hpp"
#include "experiment_runner.hpp"
#include "format.hpp"
#include "offline_common.hpp"
#include "plot.hpp"
#include "run_launch.hpp"
#include "scenario_changes.hpp"
#include "stats.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/record/metrics.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Scenario = swarm::scenario::Scenario;

struct Links {
  std::string name;
  std::string label;
  Colour colour;
  ScenarioChange apply;
};

// delay: 1 tick plus a jitter of 0-4 (link.hpp), so 1 to 5 ticks on top of every link's one, 3 ± 2.
const std::vector<Links>& all_links() {
  static const std::vector<Links> links = {
      {"base", "exact links", {0, 114, 178}, [](Scenario&) {}},
      {"delay", "member<->leader 3 ± 2 ticks", {213, 94, 0}, member_leader_delay(1, 4)},
      {"loss", "5 % loss on every link", {0, 158, 115}, every_link_loss(0.05)},
  };
  return links;
}

struct Team {
  std::string name;  // "3x3"
  std::uint32_t groups = 0, per_group = 0;
};

// "GxR" with both at least 1; none otherwise.
std::optional<Team> parse_team(const std::string& s) {
  const auto x = s.find('x');
  if (x == std::string::npos) return std::nullopt;
  try {
    std::size_t a = 0, b = 0;
    const long g = std::stol(s.substr(0, x), &a);
    const long r = std::stol(s.substr(x + 1), &b);
    if (a != x || b != s.size() - x - 1 || g < 1 || r < 1 || g > 1000 || r > 1000) return std::nullopt;
    return Team{s, static_cast<std::uint32_t>(g), static_cast<std::uint32_t>(r)};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

struct Job {
  std::size_t map = 0, links = 0, team = 0;
  std::uint64_t seed = 1;
  std::string dir;  // relative to the experiment directory
};

// One phase of one run, as the table reads it.
struct PhaseRow {
  bool complete = false;
  double ticks = std::nan("");
  double lower_bound = std::nan("");  // in the unit of `ticks`' ratio
  double ratio = std::nan("");
  // cover: the simulator's two other lower bounds in moves (planner/coverage/cover_bounds.hpp): to
  // the target cell farthest from every robot (reach_bound_moves), and enough landings on both
  // chessboard colours (colour_bound_moves); and the ratio to the largest of the three bounds
  double reach_bound = std::nan("");
  double colour_bound = std::nan("");
  double ratio_best = std::nan("");
  double vertex = 0, edge = 0, blocked = 0, longest_block = 0, idle = 0;
};

struct Outcome {
  bool ok = false;
  bool complete = false;
  std::string failure;
  std::vector<std::optional<PhaseRow>> phases;  // per phase of the mission (none: never started)
};

PhaseRow phase_row(const record::PhaseMetrics& p, std::uint32_t robots) {
  PhaseRow r;
  r.complete = p.complete;
  if (p.end_tick) r.ticks = static_cast<double>(*p.end_tick - p.start_tick);
  if (p.name == "cover") {
    const double cells = task_number(p, "target_cells");
    if (std::isfinite(cells) && robots > 0) r.lower_bound = std::ceil(cells / robots);
    r.reach_bound = task_number(p, "reach_bound_moves");
    r.colour_bound = task_number(p, "colour_bound_moves");
  } else if (p.name == "mapf") {
    r.lower_bound = task_number(p, "planned_makespan");
    const double driven = task_number(p, "makespan_ticks");
    if (std::isfinite(driven) && r.lower_bound > 0) r.ratio = driven / r.lower_bound;
  }
  if (p.name != "mapf" && std::isfinite(r.ticks) && r.lower_bound > 0) r.ratio = r.ticks / r.lower_bound;
  if (std::isfinite(r.ticks) && std::isfinite(r.reach_bound) && r.lower_bound > 0) {
    const double colour = std::isfinite(r.colour_bound) ? r.colour_bound : 0;
    r.ratio_best = r.ticks / std::max({r.lower_bound, r.reach_bound, colour});
  }
  r.vertex = static_cast<double>(p.motion.vertex_conflict_events);
  r.edge = static_cast<double>(p.motion.edge_conflict_events);
  r.blocked = static_cast<double>(p.motion.total.blocked_moves);
  for (const auto& [name, m] : p.motion.per_robot) {
    r.longest_block = std::max(r.longest_block, static_cast<double>(m.longest_blocked_ticks));
    r.idle += m.moves == 0 ? 1 : 0;
  }
  return r;
}

Outcome read_outcome(const RunOutcome& run, const std::vector<std::string>& mission) {
  Outcome o;
  o.phases.resize(mission.size());
  if (run.run_dir.empty() || !fs::exists(run.run_dir + "/metrics.json")) {
    o.failure = run.ok ? "no metrics.json" : run.message;
    return o;
  }
  try {
    const record::RunMetrics m = record::read_metrics(run.run_dir + "/metrics.json");
    o.ok = true;
    o.complete = m.complete;
    for (std::size_t i = 0; i < m.phases.size() && i < mission.size(); ++i) o.phases[i] = phase_row(m.phases[i], m.robots);
    if (!run.ok) o.failure = run.message;
  } catch (const std::exception& e) {
    o.failure = e.what();
  }
  return o;
}

std::string cell_text(double v, int decimals) { return std::isfinite(v) ? fixed(v, decimals) : "-"; }

}  // namespace

int mission_experiment(const MissionExperimentOptions& options, std::ostream& out, std::ostream& err) {
  const char* me = "swarm experiment mission";
  MissionExperimentOptions o = options;
  if (o.maps.empty()) o.maps = config::builtin_map_names();
  if (o.quick) {
    o.maps = {"small"};
    o.seeds = 1;
    o.links = {"base"};
  }
  if (o.seeds < 1 || o.jobs < 1 || o.timeout_s < 1) {
    err << me << ": --seeds, --jobs and --timeout must be at least 1\n";
    return 2;
  }
  if (o.mission.empty()) {
    err << me << ": --mission names no phase\n";
    return 2;
  }
  std::vector<std::size_t> links;
  for (const std::string& l : o.links) {
    const auto& all = all_links();
    const auto it = std::find_if(all.begin(), all.end(), [&](const Links& x) { return x.name == l; });
    if (it == all.end()) {
      err << me << ": unknown --links setting '" << l << "' (base, delay, loss)\n";
      return 2;
    }
    links.push_back(static_cast<std::size_t>(it - all.begin()));
  }
  std::vector<Team> teams;
  for (const std::string& t : o.robots) {
    const std::optional<Team> team = parse_team(t);
    if (!team) {
      err << me << ": --robots '" << t << "' is not GROUPSxROBOTS_PER_GROUP (e.g. 3x3, 10x10)\n";
      return 2;
    }
    teams.push_back(*team);
  }
  std::string dir;
  try {
    dir = make_out_dir(o.out_dir, "experiment-mission");
  } catch (const OfflineBadInput& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }

  std::vector<Job> jobs;
  std::vector<RunJob> runs;
  for (std::size_t m = 0; m < o.maps.size(); ++m) {
    for (const std::size_t l : links) {
      for (std::size_t t = 0; t < teams.size(); ++t) {
        for (std::int64_t seed = 1; seed <= o.seeds; ++seed) {
          Job j{m, l, t, static_cast<std::uint64_t>(seed),
                "runs/" + fs::path(o.maps[m]).stem().string() + "-" + all_links()[l].name + "-" + teams[t].name + "-s" +
                    std::to_string(seed)};
          RunJob r;
          r.options.overrides.map = o.maps[m];
          r.options.overrides.seed = j.seed;
          r.options.overrides.groups = teams[t].groups;
          r.options.overrides.robots_per_group = teams[t].per_group;
          r.options.overrides.mission = o.mission;
          r.options.out_dir = (fs::path(dir) / j.dir).string();
          r.options.timeout = std::chrono::seconds(o.timeout_s);
          r.options.customize = all_links()[l].apply;
          jobs.push_back(j);
          runs.push_back(std::move(r));
        }
      }
    }
  }
  std::string mission_text;
  for (const auto& p : o.mission) mission_text += (mission_text.empty() ? "" : ",") + p;
  out << me << ": " << runs.size() << " runs of " << mission_text << ", " << o.jobs << " at once, into " << dir
      << "\n";
  RunnerOptions ro;
  ro.jobs = static_cast<int>(o.jobs);
  ro.first_domain = domain_id_for(::getpid());
  std::vector<Outcome> outcomes(runs.size());
  std::size_t finished = 0;
  ro.on_finished = [&](std::size_t i, const RunOutcome& r) {
    ++finished;
    outcomes[i] = read_outcome(r, o.mission);
    out << "[" << finished << "/" << runs.size() << "] " << jobs[i].dir << ": "
        << (outcomes[i].complete ? "complete" : outcomes[i].ok ? "INCOMPLETE" : "FAILED " + outcomes[i].failure)
        << " (" << fixed(r.wall_seconds, 1) << " s)\n"
        << std::flush;
  };
  (void)run_jobs(runs, ro);

  // Per phase, one row per map, setting and team: mean ± std of ticks and ratio over the seeds
  // whose phase completed; the worst conflicts, blocks and longest block over every seed.
  std::ostringstream table;
  table << "Mission " << mission_text << ", seeds 1.." << o.seeds
        << ": ticks and ratio are mean ± std over the seeds whose phase completed (n = completed/runs); "
           "conflicts (vertex/edge), blocked moves and the longest block are the worst seed's; idle: robots "
           "that never moved, mean\n";
  json aggregates = json::array();
  Figure figure{"Mission " + mission_text + ": ticks per phase (mean ± std over seeds)", {}};
  for (std::size_t ph = 0; ph < o.mission.size(); ++ph) {
    const bool cover = o.mission[ph] == "cover";
    std::vector<std::string> header = {"map", "links", "robots", "n", "ticks", "ratio to bound"};
    if (cover) header.push_back("ratio to largest bound");
    for (const char* h : {"conflicts v/e", "blocked", "longest block", "idle"}) header.push_back(h);
    TextTable t(header);
    t.add_section("phase " + std::to_string(ph + 1) + ": " + o.mission[ph] +
                  (cover ? " (bound: ⌈cells / robots⌉; largest bound: the largest of that, the moves to the cell "
                           "farthest from every robot and the moves that land the robots on every cell of both "
                           "chessboard colours)"
                   : o.mission[ph] == "mapf" ? " (ratio: driven makespan / planned)"
                                             : ""));
    BarPanel panel{o.mission[ph], "ticks", o.maps, {}, "map"};
    for (auto& g : panel.groups) g = fs::path(g).stem().string();
    for (const std::size_t l : links) panel.series.push_back({all_links()[l].name, all_links()[l].colour, {}, {}});
    for (std::size_t m = 0; m < o.maps.size(); ++m) {
      for (std::size_t li = 0; li < links.size(); ++li) {
        for (std::size_t tm = 0; tm < teams.size(); ++tm) {
          std::vector<double> ticks, ratio, ratio_best;
          PhaseRow worst;
          double idle = 0;
          int runs_here = 0, done = 0;
          for (std::size_t i = 0; i < jobs.size(); ++i) {
            if (jobs[i].map != m || jobs[i].links != links[li] || jobs[i].team != tm) continue;
            ++runs_here;
            if (!outcomes[i].phases[ph]) continue;
            const PhaseRow& r = *outcomes[i].phases[ph];
            worst.vertex = std::max(worst.vertex, r.vertex);
            worst.edge = std::max(worst.edge, r.edge);
            worst.blocked = std::max(worst.blocked, r.blocked);
            worst.longest_block = std::max(worst.longest_block, r.longest_block);
            idle += r.idle;
            if (!r.complete) continue;
            ++done;
            ticks.push_back(r.ticks);
            if (std::isfinite(r.ratio)) ratio.push_back(r.ratio);
            if (std::isfinite(r.ratio_best)) ratio_best.push_back(r.ratio_best);
          }
          const Summary st = summarize(ticks), sr = summarize(ratio), sb = summarize(ratio_best);
          std::vector<std::string> row = {fs::path(o.maps[m]).stem().string(), all_links()[links[li]].name,
                                          teams[tm].name, std::to_string(done) + "/" + std::to_string(runs_here),
                                          st.n ? format_mean_std(st, 0) : "-", sr.n ? format_mean_std(sr, 2) : "-"};
          if (cover) row.push_back(sb.n ? format_mean_std(sb, 2) : "-");
          for (std::string c : {cell_text(worst.vertex, 0) + "/" + cell_text(worst.edge, 0), cell_text(worst.blocked, 0),
                                cell_text(worst.longest_block, 0), runs_here ? fixed(idle / runs_here, 1) : "-"}) {
            row.push_back(std::move(c));
          }
          t.add_row(row);
          if (tm == 0) {
            panel.series[li].values.push_back(st.n ? st.mean : std::nan(""));
            panel.series[li].errors.push_back(st.n ? st.std : 0.0);
          }
          aggregates.push_back({{"phase", o.mission[ph]},
                                {"map", o.maps[m]},
                                {"links", all_links()[links[li]].name},
                                {"robots", teams[tm].name},
                                {"runs", runs_here},
                                {"complete", done},
                                {"ticks", {{"mean", st.n ? json(st.mean) : json(nullptr)}, {"std", st.n ? json(st.std) : json(nullptr)}}},
                                {"ratio", {{"mean", sr.n ? json(sr.mean) : json(nullptr)}, {"std", sr.n ? json(sr.std) : json(nullptr)}}},
                                {"ratio_to_larger_bound",
                                 {{"mean", sb.n ? json(sb.mean) : json(nullptr)}, {"std", sb.n ? json(sb.std) : json(nullptr)}}},
                                {"worst_vertex_conflicts", worst.vertex},
                                {"worst_edge_conflicts", worst.edge},
                                {"worst_blocked_moves", worst.blocked},
                                {"longest_block_ticks", worst.longest_block},
                                {"idle_robots_mean", runs_here ? json(idle / runs_here) : json(nullptr)}});
        }
      }
    }
    table << "\n" << t.render();
    figure.panels.push_back(panel);
  }
  int complete = 0;
  for (const Outcome& x : outcomes) complete += x.complete ? 1 : 0;
  table << "\n" << complete << " of " << outcomes.size() << " runs completed the whole mission\n";

  std::ostringstream csv;
  csv << "run,map,links,robots,seed,status,mission_complete,phase,phase_complete,ticks,lower_bound,ratio,reach_bound,"
         "colour_bound,ratio_to_largest_bound,vertex_conflicts,edge_conflicts,blocked_moves,longest_block_ticks,idle_robots,failure\n";
  json runs_json = json::array();
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& j = jobs[i];
    const Outcome& x = outcomes[i];
    std::string why = x.failure;
    for (char& c : why) c = c == ',' || c == '\n' ? ';' : c;
    json r = {{"dir", j.dir},     {"map", o.maps[j.map]},         {"links", all_links()[j.links].name},
              {"robots", teams[j.team].name}, {"seed", j.seed}, {"status", x.ok ? "ok" : "failed"},
              {"complete", x.complete}};
    if (!x.failure.empty()) r["failure"] = x.failure;
    json phases = json::array();
    for (std::size_t ph = 0; ph < o.mission.size(); ++ph) {
      csv << j.dir << "," << o.maps[j.map] << "," << all_links()[j.links].name << "," << teams[j.team].name << ","
          << j.seed << "," << (x.ok ? "ok" : "failed") << "," << (x.complete ? "true" : "false") << ","
          << o.mission[ph] << ",";
      if (!x.phases[ph]) {
        csv << "false,,,,,,,,,,,," << why << "\n";
        phases.push_back(nullptr);
        continue;
      }
      const PhaseRow& p = *x.phases[ph];
      const auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
      csv << (p.complete ? "true" : "false") << "," << cell_text(p.ticks, 0) << "," << cell_text(p.lower_bound, 0) << ","
          << cell_text(p.ratio, 3) << "," << cell_text(p.reach_bound, 0) << "," << cell_text(p.colour_bound, 0) << ","
          << cell_text(p.ratio_best, 3) << ","
          << p.vertex << "," << p.edge << "," << p.blocked << "," << p.longest_block
          << "," << p.idle << "," << why << "\n";
      phases.push_back({{"phase", o.mission[ph]},
                        {"complete", p.complete},
                        {"ticks", num(p.ticks)},
                        {"lower_bound", num(p.lower_bound)},
                        {"ratio", num(p.ratio)},
                        {"reach_bound", num(p.reach_bound)},
                        {"colour_bound", num(p.colour_bound)},
                        {"ratio_to_largest_bound", num(p.ratio_best)},
                        {"vertex_conflicts", p.vertex},
                        {"edge_conflicts", p.edge},
                        {"blocked_moves", p.blocked},
                        {"longest_block_ticks", p.longest_block},
                        {"idle_robots", p.idle}});
    }
    r["phases"] = phases;
    runs_json.push_back(r);
  }
  ExperimentOutputs outputs;
  outputs.table = table.str();
  outputs.csv = csv.str();
  outputs.json = json({{"kind", "mission"},
                       {"mission", o.mission},
                       {"maps", o.maps},
                       {"seeds", o.seeds},
                       {"runs", runs_json},
                       {"aggregates", aggregates}})
                     .dump(2) +
                 "\n";
  outputs.figures.emplace_back("mission.png", figure);
  return finish_experiment(dir, outputs, me, out, err);
}

}  // namespace swarm::tools
