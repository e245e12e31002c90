#include "darp_command.hpp"

#include "format.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "swarm/planner/grid/deadline.hpp"
#include "swarm/planner/coverage/placement.hpp"
#include "experiment.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/planner/coverage/coverage_check.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/record/grid_canvas.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using planner::Cell;
using planner::DarpResult;
using planner::OccupancyGrid;
using Clock = std::chrono::steady_clock;

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A whole string as an int, or nullopt.
std::optional<int> whole_int(const std::string& text) {
  std::size_t used = 0;
  try {
    const int v = std::stoi(text, &used);
    return used == text.size() ? std::optional<int>(v) : std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// Robots from file coordinates, checked against the map: inside, free, distinct. `where[i]`
// names robot i's source in messages.
long free_cells(const OccupancyGrid& map) {
  return std::count(map.data().begin(), map.data().end(), planner::CellState::Free);
}

std::vector<Cell> checked_robots(const OccupancyGrid& map, const std::vector<Cell>& file_xy,
                                 const std::vector<std::string>& where) {
  if (static_cast<long>(file_xy.size()) > free_cells(map)) {
    throw DarpInputError(where.back() + ": " + std::to_string(file_xy.size()) + " robots, but the map has only " +
                         std::to_string(free_cells(map)) + " free cells");
  }
  std::vector<Cell> out;
  std::map<Cell, std::size_t> seen;
  for (std::size_t i = 0; i < file_xy.size(); ++i) {
    const Cell f = file_xy[i];
    if (f.x < 0 || f.y < 0 || f.x >= map.width() || f.y >= map.height()) {
      throw DarpInputError(where[i] + ": robot at " + planner::to_string(f) + " is outside the map (" + std::to_string(map.width()) +
                           " x " + std::to_string(map.height()) + " cells: x = column 0.." +
                           std::to_string(map.width() - 1) + ", y = row from the top 0.." +
                           std::to_string(map.height() - 1) + ")");
    }
    const Cell c = from_file_xy(map, f.x, f.y);
    if (!map.is_free(c)) throw DarpInputError(where[i] + ": robot at " + planner::to_string(f) + " is on a blocked cell");
    if (auto [it, fresh] = seen.emplace(c, i); !fresh) {
      throw DarpInputError(where[i] + ": a second robot at " + planner::to_string(f) + " (the first: " + where[it->second] + ")");
    }
    out.push_back(c);
  }
  return out;
}

std::vector<double> parse_weights(const std::string& text, std::size_t robots) {
  std::vector<double> out;
  if (text.empty()) return out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double w = 0;
    try {
      w = std::stod(trim(item), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != trim(item).size() || !(w > 0)) {
      throw DarpInputError("--weights: entry " + std::to_string(out.size()) + " (\"" + trim(item) +
                           "\") must be a positive number");
    }
    out.push_back(w);
  }
  if (out.size() != robots) {
    throw DarpInputError("--weights: " + std::to_string(out.size()) + " weights for " + std::to_string(robots) +
                         " robots (one per robot, in the robots' order)");
  }
  return out;
}

nlohmann::json cell_json(const OccupancyGrid& map, Cell c) {
  const Cell f = to_file_xy(map, c);
  return nlohmann::json::array({f.x, f.y});
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

LoadedMap load_darp_map(const std::string& spec) {
  if (spec.empty()) throw DarpInputError("--map is required: a built-in map, a map_server YAML file or a MovingAI .map");
  std::string path;
  try {
    path = config::resolve_map_path(spec, "");
  } catch (const std::exception& e) {
    throw DarpInputError(std::string("--map: ") + e.what() + ", a map_server YAML file or a MovingAI .map file");
  }
  LoadedMap out;
  out.path = path;
  try {
    out.grid = ends_with(path, ".map") ? planner::load_movingai_map(path) : planner::load_map_yaml(path);
  } catch (const std::exception& e) {
    throw DarpInputError(e.what());
  }
  if (free_cells(out.grid) == 0) throw DarpInputError(path + ": the map has no free cell");
  return out;
}

std::vector<Cell> parse_robot_list(const std::string& text, const OccupancyGrid& map) {
  std::vector<Cell> file_xy;
  std::vector<std::string> where;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ';')) {
    const std::string entry = "--robots entry " + std::to_string(file_xy.size());
    const auto comma = item.find(',');
    const auto x = comma == std::string::npos ? std::nullopt : whole_int(trim(item.substr(0, comma)));
    const auto y = comma == std::string::npos ? std::nullopt : whole_int(trim(item.substr(comma + 1)));
    if (!x || !y) {
      throw DarpInputError(entry + " (\"" + trim(item) + "\"): expected x,y (two integers: column, row from the top)");
    }
    file_xy.push_back({*x, *y});
    where.push_back(entry);
  }
  if (file_xy.empty()) throw DarpInputError("--robots: no robot given; expected \"x,y;x,y\"");
  return checked_robots(map, file_xy, where);
}

std::vector<Cell> read_robots_file(const std::string& path, const OccupancyGrid& map) {
  std::ifstream in(path);
  if (!in) throw DarpInputError(path + ": cannot read the robots file");
  std::vector<Cell> file_xy;
  std::vector<std::string> where;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    std::istringstream fields(t);
    std::string a, b, extra;
    fields >> a >> b >> extra;
    const auto x = whole_int(a);
    const auto y = whole_int(b);
    if (!x || !y || !extra.empty()) {
      throw DarpInputError(path + ":" + std::to_string(number) +
                           ": expected \"x y\" (two integers: column, row from the top), got \"" + t + "\"");
    }
    file_xy.push_back({*x, *y});
    where.push_back(path + ":" + std::to_string(number));
  }
  if (file_xy.empty()) throw DarpInputError(path + ": no robot in the file; expected one \"x y\" line per robot");
  return checked_robots(map, file_xy, where);
}

void draw_division(const OccupancyGrid& map, const std::vector<Cell>& robots, const DarpResult& division,
                   const std::vector<planner::CoveragePlan>& plans, const std::string& title,
                   const std::string& png_path) {
  const int scale = std::clamp(1000 / std::max(map.width(), map.height()), 2, 12);
  record::GridCanvas canvas(map, scale);
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    const int a = division.assignment[i];
    if (a >= 0) canvas.fill_cell(map.cell_of(i), record::palette_colour(a), 0.45);
    if (a == planner::kUnreachable) canvas.fill_cell(map.cell_of(i), {150, 150, 150}, 0.6);
  }
  const int line = scale >= 6 ? 2 : 1;
  for (std::size_t r = 0; r < plans.size(); ++r) {
    const record::Rgb colour = record::palette_colour(static_cast<int>(r));
    const record::Rgb dark{static_cast<std::uint8_t>(colour.r / 2), static_cast<std::uint8_t>(colour.g / 2),
                           static_cast<std::uint8_t>(colour.b / 2)};
    canvas.polyline(plans[r].coverage.cells, dark, line);
    canvas.polyline(plans[r].approach, record::kInk, 1);
    if (division.starts[r] != robots[r]) canvas.marker(division.starts[r], record::kInk, record::Marker::Ring, 2.4);
    canvas.marker(robots[r], dark, record::Marker::Disc, 1.6);
    std::string legend = "r";  // appended piecewise: GCC 12 warns (-Wrestrict) on "r" + std::to_string(..)
    legend += std::to_string(r) + ": " + std::to_string(division.cells[r]) + " cells";
    canvas.add_legend(legend, colour);
  }
  canvas.set_title(title);
  canvas.write_png(png_path);
}

int darp_command(const DarpOptions& o, std::ostream& out, std::ostream& err) {
  LoadedMap loaded;
  std::vector<Cell> robots;
  std::vector<double> weights;
  planner::DarpConfig cfg;
  std::string dir = o.out_dir;
  try {
    loaded = load_darp_map(o.map);
    const OccupancyGrid& map = loaded.grid;
    const int sources = !o.robots.empty() + !o.robots_file.empty() + o.count.has_value();
    if (sources != 1) {
      throw DarpInputError("give the robots one way: --robots \"x,y;x,y\", --robots-file FILE, or --count N "
                           "[--placement spread|bunched] [--seed S]");
    }
    if (!o.robots.empty()) robots = parse_robot_list(o.robots, map);
    if (!o.robots_file.empty()) robots = read_robots_file(o.robots_file, map);
    if (o.count) {
      const long piece = static_cast<long>(planner::largest_piece(map).size());
      if (*o.count < 1) throw DarpInputError("--count " + std::to_string(*o.count) + ": at least 1 robot");
      if (*o.count > piece) {
        throw DarpInputError("--count " + std::to_string(*o.count) + ": more robots than free cells (the map's largest "
                             "connected free area has " + std::to_string(piece) + ")");
      }
      planner::Rng rng(planner::mix_seed(o.seed, 0x9ace));
      if (o.placement == "spread") robots = planner::spread_cells(map, *o.count, rng);
      else if (o.placement == "bunched") robots = planner::bunched_cells(map, *o.count, std::nullopt, 0, rng);
      else throw DarpInputError("--placement \"" + o.placement + "\": expected spread or bunched");
    }
    weights = parse_weights(o.weights, robots.size());
    const auto method = planner::parse_division_method(o.method);
    if (!method) throw DarpInputError("--method \"" + o.method + "\": expected auto or darp");
    cfg.method = *method;
    const auto init = planner::parse_darp_init(o.init);
    if (!init) throw DarpInputError("--init \"" + o.init + "\": expected given, random, kmeans or bfs-kmeans");
    const auto distance = planner::parse_darp_distance(o.distance);
    if (!distance) throw DarpInputError("--distance \"" + o.distance + "\": expected euclidean or geodesic");
    if (o.reinit != "selective" && o.reinit != "always") {
      throw DarpInputError("--reinit \"" + o.reinit + "\": expected selective or always");
    }
    if (o.max_iterations < 0) throw DarpInputError("--max-iterations must be >= 0");
    if (!(o.time_limit_s >= 0)) throw DarpInputError("--time-limit must be >= 0 seconds");
    cfg.init = *init;
    cfg.distance = *distance;
    cfg.reinit_always = o.reinit == "always";
    cfg.max_iterations = o.max_iterations;
    cfg.seed = o.seed;
    if (dir.empty()) dir = "runs/darp-" + local_timestamp(std::time(nullptr));
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
      throw DarpInputError("--out " + dir + ": cannot create the directory (" + ec.message() + ")");
    }
  } catch (const DarpInputError& e) {
    err << "swarm darp: " << e.what() << "\n";
    return 2;
  }
  const OccupancyGrid& map = loaded.grid;

  out << "swarm darp: " << loaded.path << " (" << map.width() << " x " << map.height() << ", " << free_cells(map)
      << " free cells), " << robots.size() << " robots, method " << o.method << ", init " << o.init
      << (cfg.init == planner::DarpInit::BfsKMeans ? " (" + o.reinit + ")" : "") << ", " << o.distance << "\n";
  // Progress every second (DARP may run 10,000 iterations); the time limit, if any.
  const Clock::time_point t0 = Clock::now();
  Clock::time_point next_note = t0 + std::chrono::seconds(1);
  long polls = 0;
  const auto deadline = planner::deadline_after(o.time_limit_s, t0);
  auto should_stop = [&] {
    ++polls;
    const Clock::time_point now = Clock::now();
    if (now >= next_note) {
      err << "  ... " << polls << " iterations, " << static_cast<int>(seconds_since(t0)) << " s\n";
      next_note += std::chrono::seconds(1);
    }
    return o.time_limit_s > 0 && now >= deadline;
  };
  planner::DarpRequest request;
  request.robots = robots;
  request.weights = weights;
  const DarpResult division = planner::divide_areas(map, request, cfg, should_stop);
  const double seconds_division = seconds_since(t0);
  const Clock::time_point t1 = Clock::now();
  const std::vector<planner::CoveragePlan> plans = planner::plan_coverage(map, division, robots);
  const double seconds_paths = seconds_since(t1);

  // Trust nothing unchecked: the independent validators (a failure here is a bug).
  std::vector<std::string> problems =
      planner::check_division(map, request, division,
                              cfg.init == planner::DarpInit::Given && cfg.method == planner::DivisionMethod::Darp);
  for (std::size_t r = 0; r < plans.size(); ++r) {
    const OccupancyGrid region = planner::region_of(map, division.assignment, static_cast<int>(r));
    const Cell from = plans[r].approach.empty() ? robots[r] : plans[r].approach.back();
    for (const std::string& p : planner::check_coverage_path(region, from, plans[r].coverage.cells)) {
      problems.push_back("robot " + std::to_string(r) + " path: " + p);
    }
  }
  for (const std::string& p : problems) err << "swarm darp: internal check failed: " << p << "\n";

  nlohmann::json j;
  j["map"] = loaded.path;
  j["coordinates"] = "x = column, y = row from the top row of the map file (0-based)";
  j["status"] = planner::to_string(division.status);
  if (!division.message.empty()) j["message"] = division.message;
  j["method"] = o.method;
  j["finished_by"] = division.finished_by;
  j["iterations"] = division.iterations;
  j["repair_moves"] = division.repair_moves;
  j["starts_moved"] = division.starts_moved;
  j["init"] = o.init;
  j["reinit"] = o.reinit;
  j["distance"] = o.distance;
  j["seed"] = o.seed;
  j["max_iterations"] = o.max_iterations;
  j["alpha0"] = division.alpha0;
  j["alpha_reinit"] = division.alpha_reinit;
  j["final_imbalance"] = division.final_imbalance;
  j["max_deviation"] = division.max_deviation;
  j["split_regions"] = division.split_regions;
  j["unreachable_cells"] = division.unreachable_cells;
  j["cells"] = division.cells;
  j["shares"] = division.shares;
  j["weights"] = weights;
  j["seconds_division"] = seconds_division;
  j["seconds_paths"] = seconds_paths;
  nlohmann::json robots_json = nlohmann::json::array(), starts = nlohmann::json::array();
  for (std::size_t r = 0; r < robots.size(); ++r) {
    robots_json.push_back(cell_json(map, robots[r]));
    starts.push_back(cell_json(map, division.starts[r]));
  }
  j["robots"] = robots_json;
  j["starts"] = starts;
  nlohmann::json rows = nlohmann::json::array();
  for (int y = map.height() - 1; y >= 0; --y) {  // the file's first row is the top
    nlohmann::json row = nlohmann::json::array();
    for (int x = 0; x < map.width(); ++x) row.push_back(division.assignment[map.index({x, y})]);
    rows.push_back(std::move(row));
  }
  j["assignment"] = std::move(rows);
  nlohmann::json paths = nlohmann::json::array(), lengths = nlohmann::json::array(), turns = nlohmann::json::array(),
                 revisits = nlohmann::json::array(), approach = nlohmann::json::array(), left_out = nlohmann::json::array();
  for (const planner::CoveragePlan& p : plans) {
    nlohmann::json cells = nlohmann::json::array();
    for (const Cell& c : p.path()) cells.push_back(cell_json(map, c));
    paths.push_back(std::move(cells));
    const int approach_moves = p.approach.empty() ? 0 : static_cast<int>(p.approach.size()) - 1;
    lengths.push_back(approach_moves + p.coverage.length);
    approach.push_back(approach_moves);
    turns.push_back(planner::count_turns(p.path()).quarter_turns());
    revisits.push_back(p.coverage.revisits);
    left_out.push_back(p.coverage.left_out);
  }
  j["paths"] = std::move(paths);
  j["path_length"] = lengths;
  j["approach_length"] = std::move(approach);
  j["turns"] = turns;
  j["revisits"] = std::move(revisits);
  j["left_out"] = std::move(left_out);
  j["problems"] = problems;

  const std::string json_path = (fs::path(dir) / "result.json").string();
  const std::string png_path = (fs::path(dir) / "division.png").string();
  try {
    std::ofstream f(json_path);
    f << j.dump(1) << "\n";
    if (!f) throw std::runtime_error("cannot write " + json_path);
    std::ostringstream title;
    title << "DARP " << o.init << ", " << o.distance << ": " << robots.size() << " robots, "
          << planner::to_string(division.status) << " after " << division.iterations << " iterations";
    if (division.finished_by != "darp") title << " + " << division.finished_by << " (" << division.repair_moves << " cells)";
    draw_division(map, robots, division, plans, title.str(), png_path);
  } catch (const std::exception& e) {
    err << "swarm darp: " << e.what() << "\n";
    return 1;
  }

  char line[200];
  std::snprintf(line, sizeof line, "  %s, finished by %s: %d DARP iterations, %d cells repaired, %.3f s (alpha0 %.3f, "
                "final imbalance %.4f); paths in %.3f s\n",
                planner::to_string(division.status), division.finished_by.c_str(), division.iterations,
                division.repair_moves, seconds_division, division.alpha0, division.final_imbalance, seconds_paths);
  out << line;
  if (!division.message.empty()) out << "  " << division.message << "\n";
  if (division.starts_moved) out << "  some regions grow from a cell other than their robot's: it drives there first\n";
  if (division.unreachable_cells > 0) {
    out << "  " << division.unreachable_cells << " free cells no robot can reach (-2 in the assignment)\n";
  }
  out << "  robot   cells    share   path  turns  repeats\n";
  for (std::size_t r = 0; r < robots.size(); ++r) {
    std::snprintf(line, sizeof line, "  %5zu  %6d  %7.1f  %5d  %5d  %7d\n", r, division.cells[r], division.shares[r],
                  lengths[r].get<int>(), turns[r].get<int>(), plans[r].coverage.revisits);
    out << line;
  }
  out << "  wrote " << png_path << ", " << json_path << "\n";
  if (!problems.empty()) return 1;
  if (division.status == planner::DarpStatus::Impossible) return 3;
  return division.status == planner::DarpStatus::Converged ? 0 : 1;
}

}  // namespace swarm::tools
