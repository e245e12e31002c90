#include "clean_command.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>

#include "clean_report.hpp"
#include "named_map.hpp"
#include "offline_common.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;

planner::Cell parse_start(const std::string& text, const planner::OccupancyGrid& map) {
  const auto comma = text.find(',');
  planner::Cell c;
  const auto number = [&](const char* b, const char* e, int& v) {
    const auto [end, ec] = std::from_chars(b, e, v);
    return ec == std::errc() && end == e;
  };
  if (comma == std::string::npos || !number(text.data(), text.data() + comma, c.x) ||
      !number(text.data() + comma + 1, text.data() + text.size(), c.y)) {
    throw OfflineBadInput("--start '" + text + "': expected X,Y (a cell: integers, x right, y up)");
  }
  if (!map.in_bounds(c)) {
    throw OfflineBadInput("--start " + text + " is outside the map (x 0.." + std::to_string(map.width() - 1) +
                          ", y 0.." + std::to_string(map.height() - 1) + ")");
  }
  if (!map.is_free(c)) throw OfflineBadInput("--start " + text + " is on a blocked cell");
  return c;
}

planner::PlowOptions::Sweep parse_sweep(const std::string& s) {
  if (s == "columns") return planner::PlowOptions::Sweep::kColumns;
  if (s == "rows") return planner::PlowOptions::Sweep::kRows;
  throw OfflineBadInput("--sweep '" + s + "'; accepted: columns, rows");
}

}  // namespace

int clean_command(const CleanCommandOptions& o, std::ostream& out, std::ostream& err) {
  try {
    if (!(o.k > 0 && o.k <= 1)) throw OfflineBadInput("--k must be in (0, 1] (the paper: 0.5)");
    if (o.margin < 0) throw OfflineBadInput("--margin must be 0 or more cells");
    planner::OccupancyGrid map;
    try {
      map = load_named_map(o.map);
    } catch (const std::runtime_error& e) {
      throw OfflineBadInput(e.what());
    }
    planner::GroupKConfig config;
    config.k = o.k;
    config.seed = o.seed;
    config.plow.sweep = parse_sweep(o.sweep);
    config.area_margin = o.margin;
    const std::optional<planner::Cell> start = o.start.empty() ? top_left_start(map) : parse_start(o.start, map);
    if (!start) throw OfflineBadInput("map '" + o.map + "' has no free cell to clean");
    const std::string dir = make_out_dir(o.out_dir, "clean-" + fs::path(o.map).stem().string());
    planner::CoverageTimeModel model;
    model.cell_m = map.resolution();

    const CleanRun run = run_clean(map, *start, config, model);
    const std::string summary = "plowing vs Group-k on " + o.map + " (" + std::to_string(map.width()) + " x " +
                                std::to_string(map.height()) + " cells of " + fixed(map.resolution(), 2) +
                                " m), start (" + std::to_string(start->x) + ", " + std::to_string(start->y) +
                                "), k = " + fixed(o.k, 2) +
                                (o.margin > 0 ? ", group areas widened by " + std::to_string(o.margin) + " cells" : "") + "\n" + grouping_text(map, run) + "\n" + coverage_text(run);
    out << summary << "written to " << dir << "\n";
    std::ofstream(fs::path(dir) / "summary.txt") << summary;
    const planner::Grouping& g = run.grouping;
    const auto png = [&](const char* name) { return (fs::path(dir) / name).string(); };
    draw_groups_png(map, g, g.basic, {}, "Basic_Group: " + std::to_string(g.basic.size()) + " groups", png("groups-basic.png"));
    draw_groups_png(map, g, g.released, {}, "Release_Group (k = " + fixed(o.k, 2) + "): " + std::to_string(g.released.size()) + " groups",
                    png("groups-released.png"));
    draw_groups_png(map, g, g.groups, g.order,
                    "Merge_Group: " + std::to_string(g.groups.size()) + " groups, #: cleaning order after the outside area",
                    png("groups.png"));
    draw_path_png(map, run, false, png("plow.png"));
    draw_path_png(map, run, true, png("group-k.png"));
    write_figure_png(coverage_figure({{o.map, &run}}, "Clean area over time: plowing vs Group-k"), png("coverage.png"));
  } catch (const OfflineBadInput& e) {
    err << "swarm clean: " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {
    err << "swarm clean: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace swarm::tools
