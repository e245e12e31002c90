// From a validated scenario to its world: data folder, map lookup, start and robots' cells.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <limits>
#include <optional>

#include "swarm/config/scenario.hpp"
#include "swarm/config/task_config.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/grid/start_cells.hpp"

#ifndef SWARM_SOURCE_DIR
#error "SWARM_SOURCE_DIR must be defined by the build (config/CMakeLists.txt)"
#endif

namespace swarm::config {
namespace {

namespace fs = std::filesystem;
using swarm::planner::Cell;
using swarm::planner::CellState;
using swarm::planner::OccupancyGrid;

std::string joined_builtins() {
  std::string out;
  for (const std::string& n : builtin_map_names()) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string metres(double x, double y) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.2f, %.2f)", x, y);
  return buf;
}

// "[0.00, 20.00)": the metres a map spans along one axis.
std::string span(double from, double to) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%.2f, %.2f)", from, to);
  return buf;
}

std::string cell_text(Cell c) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}

std::string centre_text(const OccupancyGrid& g, Cell c) {
  double x = 0;
  double y = 0;
  g.centre_of(c, x, y);
  return metres(x, y);
}

// Connected areas of Free cells. 4-connected flood fill: a diagonal move that never cuts a
// corner (frontier.hpp) passes through Free orthogonal cells, so it reaches the same cells.
struct Areas {
  std::vector<int> label;  // per cell, -1 = not Free
  std::vector<int> size;   // per label
};

Areas free_areas(const OccupancyGrid& g) {
  Areas a;
  a.label.assign(g.size(), -1);
  std::deque<int> todo;
  for (int i = 0; i < static_cast<int>(g.size()); ++i) {
    if (g.at(i) != CellState::Free || a.label[i] >= 0) continue;
    const int id = static_cast<int>(a.size.size());
    a.size.push_back(0);
    a.label[i] = id;
    todo.push_back(i);
    while (!todo.empty()) {
      const Cell c = g.cell_of(todo.front());
      todo.pop_front();
      ++a.size[id];
      for (int k = 0; k < 4; ++k) {
        const Cell n{c.x + swarm::planner::kNeighbourDx[k], c.y + swarm::planner::kNeighbourDy[k]};
        if (!g.is_free(n) || a.label[g.index(n)] >= 0) continue;
        a.label[g.index(n)] = id;
        todo.push_back(g.index(n));
      }
    }
  }
  return a;
}

// The Free cell nearest `to` (squared distance in cells; ties: lowest y, then x) among cells whose
// area holds at least `min_area` cells, if any.
std::optional<Cell> nearest_free(const OccupancyGrid& g, Cell to, const Areas& areas,
                                 int min_area) {
  std::optional<Cell> best;
  long long best_d = std::numeric_limits<long long>::max();
  for (int i = 0; i < static_cast<int>(g.size()); ++i) {
    if (areas.label[i] < 0 || areas.size[areas.label[i]] < min_area) continue;
    const Cell c = g.cell_of(i);
    const long long dx = c.x - to.x;
    const long long dy = c.y - to.y;
    if (dx * dx + dy * dy < best_d) best_d = dx * dx + dy * dy, best = c;
  }
  return best;
}

// Rounds metres to a micrometre so that cell centres print as "10.1", not "10.100000000000001".
double tidy(double v) { return std::round(v * 1e6) / 1e6; }

}  // namespace

std::string data_dir() {
  const char* env = std::getenv("SWARM_DATA_DIR");
  if (env != nullptr && *env != '\0') return env;
  return SWARM_SOURCE_DIR;
}

std::string member_process_name(int group, int first, int last) {
  const std::string g = std::to_string(group);
  if (first == last) return "member-" + g + "-" + std::to_string(first);
  return "members-" + g + "-" + std::to_string(first) + "-" + std::to_string(last);
}

std::string dds_profile_path() {
  const char* env = std::getenv("SWARM_DDS_PROFILE");
  if (env != nullptr && *env != '\0') return env;
  return data_dir() + "/deploy/fastdds_loopback.xml";
}

std::vector<std::string> builtin_map_names() {
  return {"open", "maze1", "maze2", "small", "clutter", "empty", "warehouse-5x8", "terminal", "rectangle"};
}

std::string resolve_map_path(const std::string& map, const std::string& scenario_dir) {
  const auto names = builtin_map_names();
  if (std::find(names.begin(), names.end(), map) != names.end()) {
    const fs::path p = fs::path(data_dir()) / "maps" / (map + ".yaml");
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) {
      throw ConfigError("built-in map '" + map + "' is missing: no file " + p.string() +
                        "; set SWARM_DATA_DIR to the folder that holds maps/ (the swarm source "
                        "tree)");
    }
    return p.string();
  }
  fs::path p(map);
  if (!map.empty() && p.is_relative() && !scenario_dir.empty()) p = fs::path(scenario_dir) / p;
  std::error_code ec;
  if (map.empty() || !fs::is_regular_file(p, ec)) {
    const std::string looked = map.empty() ? "" : " (no file " + p.string() + ")";
    throw ConfigError("unknown map '" + map + "': not a built-in (" + joined_builtins() +
                      ") nor an existing file" + looked);
  }
  return p.lexically_normal().string();
}

bool is_movingai_map(const std::string& path) { return fs::path(path).extension() == ".map"; }

std::string MapFrame::extent_text() const {
  return "x " + span(origin_x, origin_x + width * resolution) + " m and y " + span(origin_y, origin_y + height * resolution) +
         " m";
}

World resolve_world(const swarm::scenario::Scenario& scenario, const std::string& scenario_dir,
                    const std::string& source) {
  const std::string src = source.empty() ? "scenario '" + scenario.name() + "'" : source;
  validate(scenario, src);

  World w;
  w.scenario = scenario;
  try {
    w.map_path = resolve_map_path(scenario.map(), scenario_dir);
  } catch (const ConfigError& e) {
    throw ConfigError(src + ": field map: " + e.what());
  }
  try {
    w.truth = is_movingai_map(w.map_path) ? swarm::planner::load_movingai_map(w.map_path, scenario.map_resolution_m())
                                          : swarm::planner::load_map_yaml(w.map_path);
  } catch (const swarm::planner::MapFileError& e) {
    throw ConfigError(e.what());
  } catch (const std::exception& e) {
    throw ConfigError(w.map_path + ": cannot load the map: " + e.what());
  }
  const OccupancyGrid& g = w.truth;
  // Cells travel between processes as 16-bit signed coordinates (idl/swarm_msgs.idl): a larger map
  // would be narrowed on the wire and planned for wrongly, so it is refused here.
  if (g.width() > kMaxMapSide || g.height() > kMaxMapSide) {
    throw ConfigError(w.map_path + ": the map is " + std::to_string(g.width()) + " x " + std::to_string(g.height()) +
                      " cells; at most " + std::to_string(kMaxMapSide) +
                      " cells per side fit the messages' 16-bit cell coordinates (use a coarser resolution, "
                      "or cut the map)");
  }
  if (g.size() == 0) throw ConfigError(w.map_path + ": the map has no cells");

  const int robots = static_cast<int>(scenario.groups() * scenario.robots_per_group());
  const Areas areas = free_areas(g);
  const Cell centre{g.width() / 2, g.height() / 2};
  // The fix for a bad start: the nearest cell from which every robot has room, or, when no area
  // of the map is large enough, fewer robots.
  auto fix = [&](Cell near, const std::string& what) -> std::string {
    if (const auto c = nearest_free(g, near, areas, robots)) {
      return what + ", e.g. " + centre_text(g, *c);
    }
    int largest = 0;
    for (int a : areas.size) largest = std::max(largest, a);
    return "use fewer robots: no free area of " + w.map_path + " holds " + std::to_string(robots) +
           " (the largest has " + std::to_string(largest) + " cells)";
  };

  std::string start_text;  // how messages name the start
  if (scenario.has_start()) {
    const double x = scenario.start().x();
    const double y = scenario.start().y();
    start_text = "start " + metres(x, y) + " m";
    const MapFrame frame = MapFrame::of(g);
    const bool inside = frame.contains(x, y);
    if (inside) w.start = g.cell_at(x, y);
    if (!inside || !g.in_bounds(w.start)) {
      throw ConfigError(src + ": " + start_text + " is outside the map " + w.map_path + ", which spans " +
                        frame.extent_text() + "; " + fix(centre, "pick a free cell"));
    }
    if (!g.is_free(w.start)) {
      const char* state = g.is_occupied(w.start) ? "occupied" : "unknown";
      throw ConfigError(src + ": " + start_text + " is cell " + cell_text(w.start) + ", which is " +
                        state + " in " + w.map_path + "; " + fix(w.start, "pick a free cell"));
    }
  } else {
    const auto c = nearest_free(g, centre, areas, 1);
    if (!c) throw ConfigError(w.map_path + ": the map has no free cell to start from");
    w.start = *c;
    double x = 0;
    double y = 0;
    g.centre_of(w.start, x, y);
    start_text = "start " + metres(x, y) + " m (the default: the free cell nearest the map centre)";
    w.scenario.mutable_start()->set_x(tidy(x));
    w.scenario.mutable_start()->set_y(tidy(y));
  }

  const std::vector<std::uint8_t> mask = swarm::planner::reachable_mask(g, {w.start});
  const auto reachable = std::count(mask.begin(), mask.end(), std::uint8_t{1});
  if (reachable < robots) {
    throw ConfigError(src + ": " + start_text + " is cell " + cell_text(w.start) +
                      ", from which only " + std::to_string(reachable) +
                      " free cells are reachable in " + w.map_path + ", fewer than the " +
                      std::to_string(robots) + " robots (" + std::to_string(scenario.groups()) +
                      " groups x " + std::to_string(scenario.robots_per_group()) +
                      "); " + fix(w.start, "set start { x: .. y: .. } in a larger free area"));
  }

  w.robot_cells = swarm::planner::start_cells(g, w.start, robots);
  if (static_cast<int>(w.robot_cells.size()) != robots) {
    throw ConfigError(src + ": found start cells for only " +
                      std::to_string(w.robot_cells.size()) + " of " + std::to_string(robots) +
                      " robots around " + start_text + " in " + w.map_path);
  }
  w.frame = MapFrame::of(g);
  return w;
}

}  // namespace swarm::config
