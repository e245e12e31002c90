#include "clean_report.hpp"

#include <algorithm>
#include <sstream>

#include "offline_common.hpp"
#include "swarm/planner/coverage/plow.hpp"
#include "swarm/record/grid_canvas.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

using planner::Cell;

std::string complexities(const std::vector<planner::ObstacleGroup>& groups) {
  std::string s;
  for (const planner::ObstacleGroup& g : groups) {
    if (!s.empty()) s += " ";
    s += fixed(g.complexity(), 2);
  }
  return s.empty() ? "(none)" : s;
}

std::string cell_text(Cell c) { return std::string("(") + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

}  // namespace

std::optional<double> CleanRun::group_k_when_plow_at(double fraction) const {
  const std::optional<double> t = plow_curve.time_to(fraction);
  if (!t) return std::nullopt;
  return group_k_curve.fraction_at(*t);
}

CleanRun run_clean(const planner::OccupancyGrid& map, Cell start, const planner::GroupKConfig& config,
                   const planner::CoverageTimeModel& model) {
  CleanRun r;
  r.start = start;
  const planner::CellMask all = planner::free_cells(map);
  r.grouping = planner::group_obstacles(map, config);
  r.plow = planner::plow(map, all, start, config.plow);
  r.group_k = planner::group_k(map, r.grouping, all, start, config.plow);
  r.plow_curve = planner::coverage_curve(all, map, r.plow.cells, model);
  r.group_k_curve = planner::coverage_curve(all, map, r.group_k.path.cells, model);
  const std::vector<planner::CellMask> parts = planner::group_k_parts(map, r.grouping, all);
  for (std::size_t p = 1; p < parts.size(); ++p) r.grouped_cells += planner::count_cells(parts[p]);
  return r;
}

std::optional<Cell> top_left_start(const planner::OccupancyGrid& map) {
  std::optional<Cell> best;
  int best_d = 0;
  for (int y = map.height() - 1; y >= 0; --y) {
    for (int x = 0; x < map.width(); ++x) {
      if (!map.is_free({x, y})) continue;
      // Steps from (1, 1) counted from the top left; (1, 1) itself is best.
      const int d = std::abs(x - 1) + std::abs(map.height() - 2 - y);
      if (!best || d < best_d) best = Cell{x, y}, best_d = d;
    }
  }
  return best;
}

std::string grouping_text(const planner::OccupancyGrid& map, const CleanRun& run) {
  const planner::Grouping& g = run.grouping;
  std::ostringstream s;
  const int free = planner::count_cells(planner::free_cells(map));
  s << g.obstacles.size() << " obstacles (blocked areas off the wall)\n"
    << "Basic_Group:   " << g.basic.size() << " groups, C = " << complexities(g.basic) << "\n"
    << "Release_Group: " << g.released.size() << " groups, C = " << complexities(g.released) << "\n"
    << "Merge_Group:   " << g.groups.size() << " groups, C = " << complexities(g.groups) << "\n"
    << "cleaning order: the outside area (" << free - run.grouped_cells << " free cells, "
    << fixed(100.0 * (free - run.grouped_cells) / std::max(1, free), 1) << " %)";
  for (std::size_t k = 0; k < g.order.size(); ++k) {
    const planner::ObstacleGroup& grp = g.groups[static_cast<std::size_t>(g.order[k])];
    s << ", #" << k + 1 << " C=" << fixed(grp.complexity(), 2) << " box " << cell_text(grp.lo) << "-" << cell_text(grp.hi);
  }
  s << "\n";
  return s.str();
}

std::string coverage_text(const CleanRun& run) {
  TextTable t({"", "plowing", "Group-k"});
  const auto time_to = [](const planner::CoverageCurve& c, double f) {
    const auto v = c.time_to(f);
    return v ? fixed(*v, 1) : std::string("never");
  };
  for (double f : {0.5, 0.8, 0.9, 1.0}) {
    t.add_row({"time to " + fixed(100 * f, 0) + " % clean (s)", time_to(run.plow_curve, f), time_to(run.group_k_curve, f)});
  }
  const auto turns = [](const planner::CoveragePath& p) {
    const planner::TurnCounts c = p.turns();
    return std::to_string(p.steps()) + " / " + std::to_string(c.turns_90) + " / " + std::to_string(c.turns_180);
  };
  t.add_row({"steps / 90 deg / 180 deg turns", turns(run.plow), turns(run.group_k.path)});
  for (double f : {0.4, 0.45, 0.5}) {
    const auto t_plow = run.plow_curve.time_to(f);
    const auto gk = run.group_k_when_plow_at(f);
    t.add_row({"clean when plowing has " + fixed(100 * f, 0) + " %" + (t_plow ? " (" + fixed(*t_plow, 0) + " s)" : ""),
               fixed(100 * f, 1) + " %", gk ? fixed(100 * *gk, 1) + " %" : "-"});
  }
  return t.render();
}

void draw_groups_png(const planner::OccupancyGrid& map, const planner::Grouping& grouping,
                     const std::vector<planner::ObstacleGroup>& groups, const std::vector<int>& order,
                     const std::string& title, const std::string& png_path) {
  record::GridCanvas c(map, picture_scale(map));
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const planner::ObstacleGroup& g = groups[i];
    const record::Rgb colour = record::palette_colour(static_cast<int>(i));
    for (int y = g.lo.y; y <= g.hi.y; ++y) {
      for (int x = g.lo.x; x <= g.hi.x; ++x) c.fill_cell({x, y}, colour, map.is_free({x, y}) ? 0.25 : 0.0);
    }
    for (int o : g.obstacles) {
      for (const Cell cell : grouping.obstacles[static_cast<std::size_t>(o)].cells) c.fill_cell(cell, colour, 0.8);
    }
    c.outline(g.lo, g.hi, colour, 2);
    std::string text;
    const auto at = std::find(order.begin(), order.end(), static_cast<int>(i));
    if (at != order.end()) {
      text = "#";
      text += std::to_string(at - order.begin() + 1);
      text += " ";
    }
    text += "C=";
    text += fixed(g.complexity(), 2);
    c.label({g.hi.x, g.hi.y}, text);
  }
  c.set_title(title);
  c.write_png(png_path);
}

void draw_path_png(const planner::OccupancyGrid& map, const CleanRun& run, bool group_k,
                   const std::string& png_path) {
  record::GridCanvas c(map, picture_scale(map));
  const auto rgb = [](Colour k) { return record::Rgb{k.r, k.g, k.b}; };
  if (!group_k) {
    c.polyline(run.plow.cells, rgb(kPlowColour), 1);
    c.set_title("plowing: " + std::to_string(run.plow.steps()) + " steps, " + fixed(run.plow_curve.total_time_s, 0) + " s");
  } else {
    const auto& parts = run.group_k.parts;
    const auto& cells = run.group_k.path.cells;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const std::size_t end = p + 1 < parts.size() ? parts[p + 1].first_cell : cells.size() - 1;
      const std::vector<Cell> piece(cells.begin() + static_cast<std::ptrdiff_t>(parts[p].first_cell),
                                    cells.begin() + static_cast<std::ptrdiff_t>(end) + 1);
      c.polyline(piece, p == 0 ? rgb(kGroupKColour) : record::palette_colour(parts[p].group + 1), p == 0 ? 1 : 2);
    }
    c.set_title("Group-k: " + std::to_string(run.group_k.path.steps()) + " steps, " +
                fixed(run.group_k_curve.total_time_s, 0) + " s; outside first, then groups #1..#" +
                std::to_string(parts.size() - 1));
    c.add_legend("outside the groups", rgb(kGroupKColour));
  }
  c.marker(run.start, record::kInk, record::Marker::Cross, 1.5);
  c.write_png(png_path);
}

Figure coverage_figure(const std::vector<std::pair<std::string, const CleanRun*>>& runs, const std::string& title) {
  Figure f;
  f.title = title;
  for (const auto& [name, run] : runs) {
    CurvePanel p;
    p.title = name;
    p.x_label = "time (s)";
    p.y_label = "clean area (%)";
    p.y_max = 100;
    const double end = std::max(run->plow_curve.total_time_s, run->group_k_curve.total_time_s);
    for (int i = 0; i <= 400; ++i) p.x.push_back(end * i / 400.0);
    PlotSeries plow{"plowing", kPlowColour, {}, {}}, gk{"Group-k", kGroupKColour, {}, {}};
    for (double t : p.x) {
      plow.values.push_back(100 * run->plow_curve.fraction_at(t));
      gk.values.push_back(100 * run->group_k_curve.fraction_at(t));
    }
    p.series = {plow, gk};
    for (double frac : {0.4, 0.5}) {
      if (const auto t = run->plow_curve.time_to(frac)) {
        const auto g = run->group_k_when_plow_at(frac);
        p.marks.push_back({*t, "plowing " + fixed(100 * frac, 0) + " %: Group-k " + fixed(100 * g.value_or(0), 1) + " %"});
      }
    }
    f.panels.push_back(std::move(p));
  }
  f.note = "time model: 0.17 m/s, 90 deg turn 1 s, 180 deg 2 s";
  return f;
}

}  // namespace swarm::tools
