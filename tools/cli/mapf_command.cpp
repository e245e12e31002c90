#include "mapf_command.hpp"

#include "format.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "mapf_maps.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/graph_file.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm/planner/mapf/validate.hpp"
#include "swarm/planner/mapf/warehouse.hpp"
#include "swarm/record/grid_canvas.hpp"
#include "swarm/record/path_player.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
namespace pm = swarm::planner::mapf;
using swarm::planner::Cell;
using swarm::planner::OccupancyGrid;

int auto_scale(const OccupancyGrid& map, int requested) {
  if (requested > 0) return requested;
  return std::clamp(900 / std::max(map.width(), map.height()), 2, 32);
}

// What the pictures draw on: a grid instance's map, or for a graph a blank grid with its vertices
// laid out on it (at their positions, or on a circle when the file gives none) and its edges.
struct Scene {
  OccupancyGrid canvas;
  std::vector<Cell> spot;                    // a graph: per vertex, its cell on the canvas
  std::vector<std::pair<Cell, Cell>> edges;  // a graph: the lines drawn under the paths

  // Where the instance's cell c (a graph: vertex_cell(v)) is drawn.
  [[nodiscard]] Cell place(Cell c) const { return spot.empty() ? c : spot[static_cast<std::size_t>(c.x)]; }
  [[nodiscard]] std::vector<Cell> place(const std::vector<Cell>& cells) const {
    std::vector<Cell> out;
    for (const Cell c : cells) out.push_back(place(c));
    return out;
  }
};

Scene scene_of(const pm::Instance& in) {
  Scene s;
  if (!in.graph) {
    s.canvas = in.map;
    return s;
  }
  const pm::Graph& g = *in.graph;
  const int n = g.vertices();
  std::vector<pm::Position> at = g.positions();
  if (at.empty()) {
    for (int v = 0; v < n; ++v) {
      const double a = 2 * std::numbers::pi * v / n;
      at.push_back({std::cos(a), std::sin(a)});
    }
  }
  double x0 = at[0].x, x1 = at[0].x, y0 = at[0].y, y1 = at[0].y;
  for (const pm::Position& p : at) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const double extent = std::max({x1 - x0, y1 - y0, 1e-9});
  // Scale: the shortest edge three cells long (no edges: as if the vertices were spread evenly),
  // the whole picture at most 300 cells across.
  double shortest = std::numeric_limits<double>::infinity();
  for (const pm::Edge& e : g.edges()) {
    const pm::Position &p = at[static_cast<std::size_t>(e.u)], &q = at[static_cast<std::size_t>(e.v)];
    if (const double d = std::hypot(p.x - q.x, p.y - q.y); d > 1e-9) shortest = std::min(shortest, d);
  }
  if (!std::isfinite(shortest)) shortest = extent / std::sqrt(static_cast<double>(n));
  const double cells_per_unit = std::min(3.0 / shortest, 300.0 / extent);
  const auto to_cell = [&](double v, double lo) { return static_cast<int>(std::lround((v - lo) * cells_per_unit)) + 1; };
  s.canvas = OccupancyGrid(to_cell(x1, x0) + 2, to_cell(y1, y0) + 2, 0.2, 0, 0, swarm::planner::CellState::Free);
  for (const pm::Position& p : at) s.spot.push_back({to_cell(p.x, x0), to_cell(p.y, y0)});
  for (const pm::Edge& e : g.edges()) s.edges.push_back({s.spot[static_cast<std::size_t>(e.u)], s.spot[static_cast<std::size_t>(e.v)]});
  return s;
}

// A graph's edges and vertices (with their ids when there are few), under everything else.
void draw_graph(swarm::record::GridCanvas& canvas, const Scene& scene) {
  constexpr swarm::record::Rgb kEdge{170, 170, 170};
  for (const auto& [a, b] : scene.edges) canvas.polyline({a, b}, kEdge, 1);
  for (std::size_t v = 0; v < scene.spot.size(); ++v) {
    canvas.marker(scene.spot[v], kEdge, swarm::record::Marker::Disc, 0.5);
    if (scene.spot.size() <= 60) canvas.label(scene.spot[v], std::to_string(v), swarm::record::kInk);
  }
}

// The picture's title (solver, agents, status) and its numbers line.
std::string title_of(const std::string& solver, const pm::Instance& in, const pm::Result& r) {
  std::string t = solver + ": " + std::to_string(in.agents()) + " agents, " + pm::to_string(r.status);
  if (r.conflicts > 0) t += ", " + std::to_string(r.conflicts) + " collisions";
  return t;
}
std::string numbers_of(const pm::Result& r) {
  std::string t;
  if (r.soc != pm::kNoCost) t += "soc " + std::to_string(r.soc) + " (lb " + std::to_string(r.lower_bound) + "), ";
  if (r.makespan != pm::kNoCost) t += "makespan " + std::to_string(r.makespan) + ", ";
  return t + fixed(r.seconds, 3) + " s";
}

void write_paths_png(const std::string& path, const pm::Instance& in, const Scene& scene, const pm::Result& r,
                     const std::string& title, int scale) {
  swarm::record::GridCanvas canvas(scene.canvas, scale);
  draw_graph(canvas, scene);
  for (int a = 0; a < in.agents(); ++a) {
    const auto colour = swarm::record::palette_colour(a);
    if (a < static_cast<int>(r.paths.size())) {
      canvas.polyline(scene.place(r.paths[static_cast<std::size_t>(a)]), colour, std::max(1, scale / 4));
    }
    canvas.marker(scene.place(in.starts[static_cast<std::size_t>(a)]), colour, swarm::record::Marker::Ring);
    canvas.marker(scene.place(in.goals[static_cast<std::size_t>(a)]), colour, swarm::record::Marker::Cross);
  }
  canvas.set_title(title);
  canvas.add_legend(numbers_of(r), swarm::record::kInk);
  canvas.add_legend("o start, x goal, one colour per agent", swarm::record::kInk);
  canvas.write_png(path);
}

// A self-contained HTML page that plays the plan: the map (drawn by GridCanvas, embedded as a PNG)
// with the agents moving on it, play/pause, step and a time slider.
void write_animation(const std::string& dir, const pm::Instance& in, const Scene& scene, const pm::Result& r,
                     const std::string& title, int scale) {
  const std::string background = (fs::path(dir) / ".animation-background.png").string();
  {
    swarm::record::GridCanvas canvas(scene.canvas, scale);
    draw_graph(canvas, scene);
    for (int a = 0; a < in.agents(); ++a) {
      canvas.marker(scene.place(in.goals[static_cast<std::size_t>(a)]), swarm::record::palette_colour(a),
                    swarm::record::Marker::Cross, 0.6);
    }
    canvas.set_title(title);
    canvas.add_legend(numbers_of(r), swarm::record::kInk);
    canvas.add_legend("discs: agents at time t, x: goals", swarm::record::kInk);
    canvas.write_png(background);
  }
  swarm::record::PathPlayer data;
  data.background_png = swarm::record::read_file(background);
  fs::remove(background);
  data.scale = scale;
  data.band = swarm::record::kBandPx;
  data.height = scene.canvas.height();
  data.vanish = in.rules.at_goal == pm::GoalRule::Vanish;
  for (int a = 0; a < in.agents(); ++a) {
    data.colours.push_back(swarm::record::palette_colour(a));
    data.paths.emplace_back();
    if (a < static_cast<int>(r.paths.size())) data.paths.back() = scene.place(r.paths[static_cast<std::size_t>(a)]);
  }
  swarm::record::write_path_player((fs::path(dir) / "animation.html").string(), "swarm mapf", data);
}

}  // namespace

int mapf_command(const MapfOptions& o, std::ostream& out, std::ostream& err) {
  const auto bad = [&](const std::string& msg) {
    err << "swarm mapf: " << msg << "\n";
    return 2;
  };
  pm::SolverConfig cfg;
  if (!pm::parse_solver(o.solver, cfg.kind)) {
    std::string names;
    for (const auto& n : pm::solver_names()) names += (names.empty() ? "" : ", ") + n;
    return bad("--solver: unknown solver '" + o.solver + "' (expected one of " + names + ")");
  }
  if (o.w < 1.0) return bad("--w: the suboptimality bound must be >= 1 (got " + fixed(o.w, 3) + ")");
  if (!(o.time_limit_s > 0)) return bad("--time-limit: must be a positive number of seconds");
  const bool from_graph = !o.graph.empty();
  const bool from_scen = !o.scen.empty();
  if (from_graph && (!o.map.empty() || from_scen || o.random || o.agents)) {
    return bad("--graph: the file holds the graph and its agents; give it without --map, --scen, --agents and --random");
  }
  if (!from_graph) {
    if (o.map.empty()) return bad("--map: required (a MovingAI .map, a map_server YAML, a built-in name or warehouse-RxC), or --graph FILE");
    if (from_scen == o.random.has_value()) return bad("give either --scen FILE --agents K or --random K");
    if (from_scen && !o.agents) return bad("--agents: required with --scen (the first K rows are the agents)");
    if (!from_scen && o.agents) return bad("--agents: only with --scen (use --random K for random agents)");
  }

  MapfMap m;
  pm::Instance in;
  try {
    if (from_graph) {
      in = pm::load_graph_instance(o.graph);
      m.name = fs::path(o.graph).filename().string();
    } else {
      m = load_mapf_map(o.map);
      if (from_scen) {
        const pm::Scenario scen = pm::load_movingai_scen(o.scen);
        in = pm::instance_from_scen(m.grid, scen, *o.agents, m.movingai_file ? m.file : "");
        if (m.warehouse && !o.standard_rules) in.rules = pm::Rules::paper_warehouse();
      } else {
        in = make_random_instance(m, *o.random, o.seed, o.standard_rules);
      }
    }
  } catch (const std::exception& e) {
    return bad(e.what());
  }
  if (const auto problems = pm::check_instance(in); !problems.empty()) {
    return bad((from_scen ? o.scen + ": " : std::string()) + problems.front());
  }
  if ((cfg.kind == pm::SolverKind::Ga || cfg.kind == pm::SolverKind::Ga1) &&
      (!m.warehouse || in.rules != pm::Rules::paper_warehouse())) {
    return bad("--solver " + o.solver + ": the paper's GA runs only on --map warehouse-RxC with the paper's rules");
  }
  cfg.ecbs.w = o.w;
  const pm::TimeoutPlan plan = o.last_node_on_timeout ? pm::TimeoutPlan::LastExpanded : pm::TimeoutPlan::FewestConflicts;
  cfg.cbs.timeout_plan = cfg.ecbs.timeout_plan = plan;
  cfg.lacam.seed = cfg.ga.seed = o.seed;
  cfg.lacam.refine = o.refine;
  if (o.ga_population) cfg.ga.population = *o.ga_population;
  if (o.ga_generations1) cfg.ga.stage1_generations = *o.ga_generations1;
  if (o.ga_generations2) cfg.ga.stage2_generations = *o.ga_generations2;
  if (o.ga_elite) cfg.ga.elite = *o.ga_elite;
  if (o.ga_initial_idle) cfg.ga.max_initial_idle = *o.ga_initial_idle;
  if (o.ga_crossover) cfg.ga.crossover_rate = *o.ga_crossover;
  if (o.ga_mutation) cfg.ga.mutation_rate = *o.ga_mutation;

  const std::string dir = o.out_dir.empty() ? "runs/mapf-" + local_timestamp() : o.out_dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) return bad("--out: cannot create the directory " + dir);

  if (!o.quiet) {
    const std::string size = from_graph ? std::to_string(in.graph->vertices()) + " vertices, " +
                                              std::to_string(in.graph->edges().size()) + " edges"
                                        : std::to_string(in.map.width()) + " x " + std::to_string(in.map.height());
    out << "swarm mapf: " << in.agents() << " agents on " << m.name << " (" << size << ", " << pm::describe(in.rules)
        << " rules), solver " << o.solver << ", limit " << fixed(o.time_limit_s, 1) << " s\n" << std::flush;
  }
  pm::StopCondition stop = pm::StopCondition::after(o.time_limit_s);
  const auto started = std::chrono::steady_clock::now();
  auto next_note = started + std::chrono::seconds(2);
  if (!o.quiet) {
    stop.predicate = [&]() {
      const auto now = std::chrono::steady_clock::now();
      if (now >= next_note) {
        out << "  ... " << static_cast<int>(std::chrono::duration<double>(now - started).count()) << " s\n" << std::flush;
        next_note = now + std::chrono::seconds(2);
      }
      return false;
    };
  }
  const pm::Result r = pm::solve(in, cfg, stop);

  // result.json: coordinates of the map file (MovingAI / warehouse: y from the top), or the graph
  // file's vertex ids.
  const auto file_xy = [&](Cell c) { return m.y_down ? pm::to_movingai_xy(in.map, c) : c; };
  const auto place = [&](Cell c) {
    if (from_graph) return nlohmann::json(c.x);
    const Cell f = file_xy(c);
    return nlohmann::json::array({f.x, f.y});
  };
  nlohmann::json j;
  if (from_graph) {
    j["graph"] = o.graph;
  } else {
    j["map"] = o.map;
    j["scen"] = o.scen;
  }
  j["agents"] = in.agents();
  if (o.random) j["seed"] = o.seed;
  j["solver"] = o.solver;
  if (cfg.kind == pm::SolverKind::Ecbs) j["w"] = o.w;
  j["time_limit"] = o.time_limit_s;
  j["rules"] = pm::describe(in.rules);
  j["status"] = pm::to_string(r.status);
  j["soc"] = r.soc;
  j["makespan"] = r.makespan;
  j["lower_bound"] = r.lower_bound;
  j["seconds"] = r.seconds;
  j["collisions"] = r.conflicts;
  j["message"] = r.message;
  j["coordinates"] = from_graph ? "vertex ids of the graph file"
                     : m.y_down ? "x = column, y = row from the top (MovingAI)"
                                : "x = column, y = row from the bottom (map_server cells)";
  j["stats"] = {{"high_level_expanded", r.stats.high_level_expanded},
                {"high_level_generated", r.stats.high_level_generated},
                {"low_level_expanded", r.stats.low_level_expanded}};
  nlohmann::json starts = nlohmann::json::array(), goals = nlohmann::json::array(), paths = nlohmann::json::array();
  double work = 0, idle = 0;
  for (int a = 0; a < in.agents(); ++a) {
    starts.push_back(place(in.starts[static_cast<std::size_t>(a)]));
    goals.push_back(place(in.goals[static_cast<std::size_t>(a)]));
    nlohmann::json p = nlohmann::json::array();
    if (a < static_cast<int>(r.paths.size())) {
      for (Cell c : r.paths[static_cast<std::size_t>(a)]) p.push_back(place(c));
      work += pm::path_cost(in, a, r.paths[static_cast<std::size_t>(a)]);
      idle += pm::idle_steps(in, a, r.paths[static_cast<std::size_t>(a)]);
    }
    paths.push_back(p);
  }
  if (!r.paths.empty() && in.agents() > 0) {
    j["work_time_per_agent"] = work / in.agents();
    j["stop_time_per_agent"] = idle / in.agents();
  }
  const std::string title = title_of(o.solver, in, r);
  try {
    // The numbers indented, the arrays one agent a line (a 1000-agent plan stays readable).
    std::string text = j.dump(1);
    text.erase(text.find_last_of('}'));
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    for (const auto& [key, arr] : {std::pair{"starts", &starts}, std::pair{"goals", &goals}, std::pair{"paths", &paths}}) {
      text += ",\n \"" + std::string(key) + "\": [";
      for (std::size_t a = 0; a < arr->size(); ++a) text += (a == 0 ? "\n  " : ",\n  ") + (*arr)[a].dump();
      text += "\n ]";
    }
    std::ofstream(fs::path(dir) / "result.json") << text << "\n}\n";
    const Scene scene = scene_of(in);
    const int scale = auto_scale(scene.canvas, o.scale);
    write_paths_png((fs::path(dir) / "paths.png").string(), in, scene, r, title, scale);
    write_animation(dir, in, scene, r, title, scale);
    if (from_graph) {
      pm::save_graph_instance((fs::path(dir) / "instance.graph").string(), in);
    } else {
      swarm::planner::save_movingai_map((fs::path(dir) / "map.map").string(), in.map);
      pm::save_movingai_scen((fs::path(dir) / "instance.scen").string(), in, "map.map");
    }
  } catch (const std::exception& e) {
    err << "swarm mapf: cannot write the outputs into " << dir << ": " << e.what() << "\n";
    return 1;
  }
  out << title << ", " << numbers_of(r) << "\n";
  if (!r.message.empty()) out << "  " << r.message << "\n";
  out << "  wrote " << dir << "/result.json, paths.png, animation.html\n";
  return r.status == pm::Status::Solved ? 0 : 1;
}

}  // namespace swarm::tools
