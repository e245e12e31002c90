#include "swarm/planner/tours/tour_file.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace swarm::planner {
namespace {


struct Line {
  int number = 0;
  std::vector<std::string> words;
};

struct Placed {
  int line = 0;
  std::string type;
  Cell at;  // file coordinates
  bool fixed = false;
};

class Parser {
 public:
  explicit Parser(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw TourFileError(path_ + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what);
  }

  int integer(const Line& l, std::size_t i, const std::string& usage) const {
    const std::string& w = l.words[i];
    int v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size()) {
      fail(l.number, "'" + l.words[0] + "' takes " + usage + "; '" + w + "' is not an integer");
    }
    return v;
  }

  void arity(const Line& l, std::size_t lo, std::size_t hi, const std::string& usage) const {
    const std::size_t n = l.words.size() - 1;
    if (n < lo || n > hi) fail(l.number, "'" + l.words[0] + "' takes " + usage + " (got " + std::to_string(n) + " words)");
  }

  int heading(const Line& l, std::size_t i) const {
    static const std::pair<const char*, int> kNames[] = {
        {"up", kHeadingUp}, {"down", kHeadingDown},
        {"left", kHeadingLeft}, {"right", kHeadingRight}};
    for (const auto& [name, h] : kNames) {
      if (l.words[i] == name) return h;
    }
    fail(l.number, "unknown heading '" + l.words[i] + "'; expected up, down, left or right");
  }

 private:
  std::string path_;
};

std::vector<Line> split_lines(const std::string& all) {
  std::istringstream in(all);
  std::vector<Line> out;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream words(text);
    Line l{n, {}};
    for (std::string w; words >> w;) l.words.push_back(w);
    if (!l.words.empty()) out.push_back(std::move(l));
  }
  return out;
}

}  // namespace

std::string TourFile::where(Cell c) const {
  return std::string("(") + std::to_string(c.x + origin.x) + ", " + std::to_string(c.y + origin.y) + ")";
}

TourFile load_tour_file(const std::string& path, const TourMapLoader& load_map) {
  std::ifstream in(path);
  if (!in) throw TourFileError(path + ": cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_tour_file(text.str(), path, load_map);
}

TourFile parse_tour_file(const std::string& text, const std::string& path, const TourMapLoader& load_map) {
  const Parser p(path);
  TourFile f;
  f.path = path;
  std::optional<Line> size_line, map_line, start_line, origin_line, after_line;
  std::vector<Placed> destinations, objects;
  std::vector<Line> obstacles;
  const auto once = [&](std::optional<Line>& slot, const Line& l) {
    if (slot) p.fail(l.number, "a second '" + l.words[0] + "' line (the first is line " + std::to_string(slot->number) + ")");
    slot = l;
  };
  for (const Line& l : split_lines(text)) {
    const std::string& w = l.words[0];
    if (w == "size") {
      p.arity(l, 2, 2, "W H");
      once(size_line, l);
    } else if (w == "map") {
      p.arity(l, 1, 1, "a built-in map name, a map_server YAML or a MovingAI .map file");
      once(map_line, l);
    } else if (w == "origin") {
      p.arity(l, 2, 2, "X Y");
      once(origin_line, l);
    } else if (w == "start") {
      p.arity(l, 2, 3, "X Y [up|down|left|right]");
      once(start_line, l);
    } else if (w == "after-drop") {
      p.arity(l, 1, 1, "up|down|left|right");
      once(after_line, l);
    } else if (w == "destination" || w == "object") {
      const bool object = w == "object";
      p.arity(l, 3, object ? 4 : 3, object ? "TYPE X Y [fixed]" : "TYPE X Y");
      Placed d{l.number, l.words[1], {p.integer(l, 2, "TYPE X Y"), p.integer(l, 3, "TYPE X Y")}, false};
      if (object && l.words.size() == 5) {
        if (l.words[4] != "fixed") p.fail(l.number, "'object' takes TYPE X Y [fixed]; got '" + l.words[4] + "'");
        d.fixed = true;
      }
      (object ? objects : destinations).push_back(d);
    } else if (w == "obstacle") {
      p.arity(l, 4, 4, "X0 Y0 X1 Y1");
      obstacles.push_back(l);
    } else {
      p.fail(l.number, "unknown statement '" + w +
                           "'; expected size, map, origin, start, after-drop, destination, object or obstacle");
    }
  }

  // The map.
  if (size_line && map_line) {
    p.fail(map_line->number, "both 'size' (line " + std::to_string(size_line->number) + ") and 'map'; give one");
  }
  if (size_line) {
    const int w = p.integer(*size_line, 1, "W H"), h = p.integer(*size_line, 2, "W H");
    if (w < 1 || h < 1 || w > 10000 || h > 10000) p.fail(size_line->number, "'size' must be 1..10000 cells each way");
    f.map = OccupancyGrid(w, h, 0.1, 0, 0, CellState::Free);
    f.map_text = std::to_string(w) + " x " + std::to_string(h) + " cells";
  } else if (map_line) {
    try {
      f.map = load_map(map_line->words[1], std::filesystem::path(path).parent_path().string());
    } catch (const std::exception& e) {
      p.fail(map_line->number, "map '" + map_line->words[1] + "': " + e.what());
    }
    f.map_text = map_line->words[1];
  } else {
    p.fail(0, "no 'size W H' or 'map NAME' line: the tour needs a map");
  }
  if (origin_line) f.origin = {p.integer(*origin_line, 1, "X Y"), p.integer(*origin_line, 2, "X Y")};
  const auto cell = [&](Cell at) { return Cell{at.x - f.origin.x, at.y - f.origin.y}; };
  const auto inside_or_fail = [&](int line, const std::string& what, Cell at) {
    const Cell c = cell(at);
    if (!f.map.in_bounds(c)) {
      p.fail(line, what + " is outside the map (x " + std::to_string(f.origin.x) + ".." +
                       std::to_string(f.origin.x + f.map.width() - 1) + ", y " + std::to_string(f.origin.y) +
                       ".." + std::to_string(f.origin.y + f.map.height() - 1) + ")");
    }
    return c;
  };
  if (!obstacles.empty()) {
    f.map_text += ", " + std::to_string(obstacles.size()) + " obstacle blocks";
  } else if (size_line) {
    f.map_text += ", no obstacles";
  }
  for (const Line& l : obstacles) {
    const std::string usage = "X0 Y0 X1 Y1";
    const Cell a{p.integer(l, 1, usage), p.integer(l, 2, usage)}, b{p.integer(l, 3, usage), p.integer(l, 4, usage)};
    const Cell lo = inside_or_fail(l.number, "obstacle corner " + f.where(cell(a)), a);
    const Cell hi = inside_or_fail(l.number, "obstacle corner " + f.where(cell(b)), b);
    for (int y = std::min(lo.y, hi.y); y <= std::max(lo.y, hi.y); ++y) {
      for (int x = std::min(lo.x, hi.x); x <= std::max(lo.x, hi.x); ++x) f.map.set({x, y}, CellState::Occupied);
    }
  }

  // Start, headings, destinations (they number the types), objects.
  if (!start_line) p.fail(0, "no 'start X Y' line: where does the robot start?");
  f.start_line = start_line->number;
  const Cell start{p.integer(*start_line, 1, "X Y [HEADING]"), p.integer(*start_line, 2, "X Y [HEADING]")};
  f.problem.start = inside_or_fail(f.start_line, "the start " + f.where(cell(start)), start);
  if (!f.map.is_free(f.problem.start)) p.fail(f.start_line, "the start " + f.where(f.problem.start) + " is on a blocked cell");
  if (start_line->words.size() == 4) f.problem.start_heading = p.heading(*start_line, 3);
  if (after_line) f.problem.heading_after_drop = p.heading(*after_line, 1);
  for (const Placed& d : destinations) {
    if (std::find(f.type_names.begin(), f.type_names.end(), d.type) != f.type_names.end()) {
      p.fail(d.line, "a second destination for type '" + d.type + "'; give one per type");
    }
    const Cell c = inside_or_fail(d.line, "the destination of '" + d.type + "' " + f.where(cell(d.at)), d.at);
    if (!f.map.is_free(c)) p.fail(d.line, "the destination of '" + d.type + "' " + f.where(c) + " is on a blocked cell");
    f.type_names.push_back(d.type);
    f.problem.destinations.push_back(c);
  }
  for (const Placed& o : objects) {
    const auto type = std::find(f.type_names.begin(), f.type_names.end(), o.type);
    if (type == f.type_names.end()) {
      p.fail(o.line, "type '" + o.type + "' has no destination (add a line 'destination " + o.type + " X Y')");
    }
    const Cell c = inside_or_fail(o.line, "object " + o.type + " " + f.where(cell(o.at)), o.at);
    if (!f.map.is_free(c)) p.fail(o.line, "object " + o.type + " " + f.where(c) + " is on a blocked cell");
    f.problem.objects.push_back({c, static_cast<int>(type - f.type_names.begin())});
    f.fixed.push_back(o.fixed);
    f.object_lines.push_back(o.line);
  }

  // What is left is reachability: destinations must be reachable, objects may be skipped.
  for (const TourIssue& issue : check_tour_problem(f.map, f.problem)) {
    if (issue.kind == TourIssue::kDestinationUnreachable) {
      const auto d = static_cast<std::size_t>(issue.index);
      p.fail(destinations[d].line, "the destination of '" + f.type_names[d] + "' " +
                                       f.where(f.problem.destinations[d]) + " cannot be reached from the start");
    }
    if (issue.kind == TourIssue::kObjectUnreachable) {
      const auto o = static_cast<std::size_t>(issue.index);
      f.unreachable.push_back(path + ":" + std::to_string(f.object_lines[o]) + ": object " +
                              f.type_names[static_cast<std::size_t>(f.problem.objects[o].type)] + " " +
                              f.where(f.problem.objects[o].cell) + " cannot be reached from the start");
    }
  }
  return f;
}

}  // namespace swarm::planner
