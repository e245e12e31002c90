#include "tour_report.hpp"

#include <nlohmann/json.hpp>

#include "offline_common.hpp"
#include "swarm/record/grid_canvas.hpp"
#include "text_table.hpp"

namespace swarm::tools {
namespace {

using planner::TourPlan;
using planner::TourVariant;
using record::Marker;

constexpr Marker kTypeMarkers[] = {Marker::Disc, Marker::Square, Marker::Triangle, Marker::Ring, Marker::Cross};

Marker type_marker(int type) { return kTypeMarkers[static_cast<std::size_t>(type) % 5]; }

std::string run_name(const TourFile& f, const TourPlan& plan, std::size_t r) {
  const auto name = [&](std::size_t k) { return f.type_names[static_cast<std::size_t>(plan.runs[k].type)]; };
  return (r == 0 ? std::string("Start") : name(r - 1)) + " -> " + name(r);
}

}  // namespace

std::string variant_title(TourVariant v) {
  switch (v) {
    case TourVariant::kNna: return "NNA method";
    case TourVariant::kDistance: return "distance";
    case TourVariant::kDistanceAngle: return "distance + angle";
  }
  return "?";
}

TourTotals tour_totals(const TourPlan& plan) {
  TourTotals t;
  t.length = plan.length_cells();
  t.rotation_rad = plan.rotation_rad();
  for (const planner::TourRun& run : plan.runs) {
    const bool ref = run.reference.has_value();
    t.best_length += ref ? run.reference->cost.length.cells() : run.length.cells();
    t.best_rotation_rad += planner::eighths_to_rad(ref ? run.reference->cost.rotation : run.rotation);
    t.exact = t.exact && ref && run.reference->exact;
  }
  return t;
}

std::string leg_table(const TourFile& file, const std::vector<VariantPlan>& plans) {
  std::vector<std::string> header{"sequence"};
  for (const VariantPlan& p : plans) {
    header.push_back(variant_title(p.variant) + ": length");
    header.push_back("rotation (rad)");
  }
  TextTable t(header);
  if (plans.empty()) return t.render();
  const TourPlan& first = plans.front().plan;
  for (std::size_t r = 0; r < first.runs.size(); ++r) {
    std::vector<std::string> row{run_name(file, first, r)};
    for (const VariantPlan& p : plans) {
      row.push_back(fixed(p.plan.runs[r].length.cells(), 2));
      row.push_back(fixed(planner::eighths_to_rad(p.plan.runs[r].rotation), 2));
    }
    t.add_row(row);
  }
  std::vector<std::string> sum{"Sum"}, best{"best order"}, gap{"GA's gap to it"};
  bool references = true;
  for (const VariantPlan& p : plans) {
    const TourTotals tt = tour_totals(p.plan);
    sum.push_back(fixed(tt.length, 2));
    sum.push_back(fixed(tt.rotation_rad, 2));
    references = references && std::all_of(p.plan.runs.begin(), p.plan.runs.end(),
                                            [](const planner::TourRun& r) { return r.reference.has_value(); });
    best.push_back(fixed(tt.best_length, 2) + (tt.exact ? "" : "~"));
    best.push_back(fixed(tt.best_rotation_rad, 2));
    gap.push_back(tt.best_length > 0 ? std::string("+") + fixed(100.0 * (tt.length / tt.best_length - 1), 2) + " %" : "-");
    gap.push_back("");
  }
  t.add_row(sum);
  if (references) {
    t.add_section("the best order of each run for the same rule (exact; ~ = local search):");
    t.add_row(best);
    t.add_row(gap);
  }
  return t.render();
}

void draw_tour_png(const TourFile& file, const VariantPlan& vp, const std::string& png_path) {
  const TourPlan& plan = vp.plan;
  record::GridCanvas c(file.map, picture_scale(file.map));
  const auto colour = [](int type) { return record::palette_colour(type); };
  for (const planner::TourLeg& leg : plan.legs) c.polyline(leg.cells, colour(leg.stop.type), 3);
  for (std::size_t d = 0; d < file.problem.destinations.size(); ++d) {
    c.marker(file.problem.destinations[d], colour(static_cast<int>(d)), Marker::Ring, 1.2);
  }
  for (const planner::TourObject& o : file.problem.objects) c.marker(o.cell, colour(o.type), type_marker(o.type), 0.6);
  int n = 0;
  for (const planner::TourLeg& leg : plan.legs) {
    if (leg.stop.kind == planner::TourStop::kPickUp) c.label(leg.stop.cell, std::to_string(++n));
  }
  c.marker(file.problem.start, record::kInk, Marker::Cross, 0.9);
  c.set_title(variant_title(vp.variant) + ": " + fixed(plan.length_cells(), 2) + " cells, " +
              fixed(plan.rotation_rad(), 2) + " rad (1, 2, ...: pick-ups)");
  for (std::size_t t = 0; t < file.type_names.size(); ++t) c.add_legend(file.type_names[t], colour(static_cast<int>(t)));
  c.write_png(png_path);
}

nlohmann::json tour_json(const TourFile& file, const VariantPlan& vp) {
  using nlohmann::json;
  const auto xy = [&](planner::Cell c) { return json::array({c.x + file.origin.x, c.y + file.origin.y}); };
  json legs = json::array();
  for (const planner::TourLeg& leg : vp.plan.legs) {
    json cells = json::array();
    for (const planner::Cell c : leg.cells) cells.push_back(xy(c));
    json l{{"type", file.type_names[static_cast<std::size_t>(leg.stop.type)]},
           {"stop", leg.stop.kind == planner::TourStop::kPickUp ? "pick-up" : "drop"},
           {"at", xy(leg.stop.cell)},
           {"length", leg.length.cells()},
           {"rotation_rad", planner::eighths_to_rad(leg.rotation)},
           {"through_objects", leg.through_objects},
           {"cells", cells}};
    if (leg.stop.kind == planner::TourStop::kPickUp) l["object_line"] = file.object_lines[static_cast<std::size_t>(leg.stop.object)];
    legs.push_back(std::move(l));
  }
  json runs = json::array();
  for (const planner::TourRun& r : vp.plan.runs) {
    json run{{"type", file.type_names[static_cast<std::size_t>(r.type)]},
             {"length", r.length.cells()},
             {"rotation_rad", planner::eighths_to_rad(r.rotation)},
             {"generations", r.generations}};
    if (r.reference) {
      run["best_length"] = r.reference->cost.length.cells();
      run["best_rotation_rad"] = planner::eighths_to_rad(r.reference->cost.rotation);
      run["best_exact"] = r.reference->exact;
    }
    runs.push_back(std::move(run));
  }
  json skipped = json::array();
  for (int s : vp.plan.skipped) skipped.push_back(file.object_lines[static_cast<std::size_t>(s)]);
  return json{{"variant", planner::variant_name(vp.variant)},
              {"length", vp.plan.length_cells()},
              {"rotation_rad", vp.plan.rotation_rad()},
              {"skipped_object_lines", skipped},
              {"runs", runs},
              {"legs", legs}};
}

}  // namespace swarm::tools
