#include "swarm/planner/mapf/movingai_scen.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "file_fields.hpp"
#include "swarm/planner/grid/astar.hpp"

namespace swarm::planner::mapf {
namespace {

using detail::fail;
using detail::parse_double;
using detail::parse_int;

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

std::string xy(int x, int y) { return planner::to_string(Cell{x, y}); }

}  // namespace

Scenario load_movingai_scen(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(path, 0, "cannot open the scenario file (check the path)");
  Scenario scen;
  scen.path = path;
  std::string line;
  int line_no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.empty()) continue;
    if (!header) {
      std::istringstream ls(line);
      std::string word, version;
      ls >> word >> version;
      if (word != "version") fail(path, line_no, "expected \"version 1\" on the first line (got \"" + line + "\")");
      header = true;
      continue;
    }
    // Fields are tab-separated (the map name may not contain a tab).
    std::vector<std::string> f;
    std::size_t from = 0;
    while (true) {
      const std::size_t tab = line.find('\t', from);
      f.push_back(line.substr(from, tab == std::string::npos ? std::string::npos : tab - from));
      if (tab == std::string::npos) break;
      from = tab + 1;
    }
    if (f.size() != 9) {
      // Some files use spaces: split on whitespace instead.
      f.clear();
      std::istringstream ls(line);
      for (std::string w; ls >> w;) f.push_back(w);
    }
    if (f.size() != 9) {
      fail(path, line_no, "expected 9 fields (bucket, map, width, height, start x, start y, goal x, goal y, "
                          "optimal length), got " + std::to_string(f.size()));
    }
    ScenarioRow r;
    r.line = line_no;
    r.map_name = f[1];
    static const char* const kNames[] = {"bucket", "", "map width", "map height", "start x", "start y", "goal x", "goal y"};
    int* ints[] = {&r.bucket, nullptr, &r.map_width, &r.map_height, &r.start_x, &r.start_y, &r.goal_x, &r.goal_y};
    for (int k = 0; k < 8; ++k) {
      if (ints[k] != nullptr && !parse_int(f[static_cast<std::size_t>(k)], *ints[k])) {
        fail(path, line_no, std::string(kNames[k]) + " must be an integer (got \"" + f[static_cast<std::size_t>(k)] + "\")");
      }
    }
    if (!parse_double(f[8], r.optimal_length)) {
      fail(path, line_no, "optimal length must be a number (got \"" + f[8] + "\")");
    }
    scen.rows.push_back(std::move(r));
  }
  if (!header) fail(path, 0, "empty file: expected \"version 1\" and one agent a line");
  return scen;
}

Instance instance_from_scen(const OccupancyGrid& map, const Scenario& scen, int k, const std::string& map_file_name) {
  const std::string& path = scen.path;
  if (k < 1) fail(path, 0, "the number of agents must be at least 1 (got " + std::to_string(k) + ")");
  if (k > static_cast<int>(scen.rows.size())) {
    fail(path, 0, std::to_string(k) + " agents asked for, but the scenario has only " +
                      std::to_string(scen.rows.size()) + " rows");
  }
  Instance in;
  in.map = map;
  std::map<std::pair<int, int>, int> start_row, goal_row;
  for (int a = 0; a < k; ++a) {
    const ScenarioRow& r = scen.rows[static_cast<std::size_t>(a)];
    if (!map_file_name.empty() && file_name(r.map_name) != file_name(map_file_name)) {
      fail(path, r.line, "the scenario is for map \"" + r.map_name + "\", not \"" + file_name(map_file_name) + "\"");
    }
    if (r.map_width != map.width() || r.map_height != map.height()) {
      fail(path, r.line, "the scenario's map is " + std::to_string(r.map_width) + " x " + std::to_string(r.map_height) +
                             ", the map is " + std::to_string(map.width()) + " x " + std::to_string(map.height()));
    }
    for (const auto& [what, x, y] : {std::tuple{"start", r.start_x, r.start_y}, std::tuple{"goal", r.goal_x, r.goal_y}}) {
      if (x < 0 || y < 0 || x >= map.width() || y >= map.height()) {
        fail(path, r.line, std::string(what) + " " + xy(x, y) + " is outside the " + std::to_string(map.width()) + " x " +
                               std::to_string(map.height()) + " map");
      }
      if (!map.is_free(from_movingai_xy(map, x, y))) {
        fail(path, r.line, std::string(what) + " " + xy(x, y) + " is on a blocked cell of the map");
      }
    }
    if (auto [it, fresh] = start_row.emplace(std::pair{r.start_x, r.start_y}, r.line); !fresh) {
      fail(path, r.line, "start " + xy(r.start_x, r.start_y) + " is also the start of line " + std::to_string(it->second));
    }
    if (auto [it, fresh] = goal_row.emplace(std::pair{r.goal_x, r.goal_y}, r.line); !fresh) {
      fail(path, r.line, "goal " + xy(r.goal_x, r.goal_y) + " is also the goal of line " + std::to_string(it->second));
    }
    in.starts.push_back(from_movingai_xy(map, r.start_x, r.start_y));
    in.goals.push_back(from_movingai_xy(map, r.goal_x, r.goal_y));
  }
  return in;
}

void save_movingai_scen(const std::string& path, const Instance& in, const std::string& map_file_name) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) fail(path, 0, "cannot write the scenario file (check the folder exists and is writable)");
  out << "version 1\n";
  for (int a = 0; a < in.agents(); ++a) {
    const Cell s = to_movingai_xy(in.map, in.starts[static_cast<std::size_t>(a)]);
    const Cell g = to_movingai_xy(in.map, in.goals[static_cast<std::size_t>(a)]);
    const auto p = astar(in.map, in.starts[static_cast<std::size_t>(a)], in.goals[static_cast<std::size_t>(a)],
                         {.unknown_is_free = false, .motion = MotionModel::eight()});
    const double len = p ? path_length(*p) : 0.0;
    char num[64];
    std::snprintf(num, sizeof num, "%.8f", len);
    out << static_cast<int>(len / 4) << '\t' << file_name(map_file_name) << '\t' << in.map.width() << '\t'
        << in.map.height() << '\t' << s.x << '\t' << s.y << '\t' << g.x << '\t' << g.y << '\t' << num << '\n';
  }
  if (!out.flush()) fail(path, 0, "cannot write the scenario file");
}

}  // namespace swarm::planner::mapf
