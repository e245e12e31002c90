// Tables, pictures and JSON of collection tours (planner/tours/tour.hpp) for `swarm tour` and
// `swarm experiment tour`.
//
//   std::vector<VariantPlan> plans = ...;              // one per variant, same file and seed
//   std::cout << leg_table(file, plans);               // the paper's Table 5 / 6 layout
//   draw_tour_png(file, plans[2], "tour-distance-angle.png");
//
// Lengths are in cells (1 per straight step, sqrt 2 per diagonal; the paper's "pixels" have an
// unknown scale), rotations in radians. Thread-safe (no shared state).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

#include "swarm/planner/tours/tour.hpp"
#include "tour_file.hpp"

namespace swarm::tools {

struct VariantPlan {
  planner::TourVariant variant;
  planner::TourPlan plan;
};

// "NNA method" / "distance" / "distance + angle": the paper's column names.
[[nodiscard]] std::string variant_title(planner::TourVariant v);

// One row per type run ("Start -> paper", "paper -> pet", ...) and a Sum row, a length and a
// rotation column per variant; when the plans hold references (compute_reference), a row with the
// best orders' sums and one with the GA's gap to them.
[[nodiscard]] std::string leg_table(const TourFile& file, const std::vector<VariantPlan>& plans);

// The map, the destinations (rings), the objects (a marker shape per type, numbered in pick-up
// order), the start (a cross) and every leg in its type's colour.
void draw_tour_png(const TourFile& file, const VariantPlan& plan, const std::string& png_path);

// The plan with every leg's cells, in the file's coordinates.
[[nodiscard]] nlohmann::json tour_json(const TourFile& file, const VariantPlan& plan);

// The sum of the runs' reference costs (runs without one count their own cost).
struct TourTotals {
  double length = 0;        // cells
  double rotation_rad = 0;
  double best_length = 0;   // cells
  double best_rotation_rad = 0;
  bool exact = true;        // every reference was proven best
};
[[nodiscard]] TourTotals tour_totals(const planner::TourPlan& plan);

}  // namespace swarm::tools
