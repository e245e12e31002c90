// The cleaning comparison of `swarm clean` and `swarm experiment clean`: plowing against Group-k
// (Jeon, Jo & Noh 2006; planner/coverage/plow.hpp, planner/coverage/group_k.hpp) on one map from one start, with
// the paper's time model, and its pictures.
//
//   const CleanRun run = run_clean(map, start, config, model);
//   std::cout << grouping_text(run.grouping) << coverage_text(run);
//   draw_groups_png(map, run.grouping, run.grouping.groups, run.grouping.order, "groups.png", "...");
//   write_figure_png(coverage_figure({{"clutter", run}}), "coverage.png");
//
// Thread-safe (no shared state).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plot.hpp"
#include "swarm/planner/coverage/coverage.hpp"
#include "swarm/planner/coverage/group_k.hpp"

namespace swarm::tools {

struct CleanRun {
  planner::Cell start;
  planner::Grouping grouping;
  planner::CoveragePath plow;
  planner::GroupKCoverage group_k;
  planner::CoverageCurve plow_curve;
  planner::CoverageCurve group_k_curve;
  int grouped_cells = 0;  // free cells inside some final group's box

  // Group-k's clean fraction when plowing reaches `fraction` (nullopt if plowing never does).
  [[nodiscard]] std::optional<double> group_k_when_plow_at(double fraction) const;
};

[[nodiscard]] CleanRun run_clean(const planner::OccupancyGrid& map, planner::Cell start,
                                 const planner::GroupKConfig& config,
                                 const planner::CoverageTimeModel& model);

// The paper's start, (1, 1) counted from the top-left corner, or the free cell nearest that
// corner (fewest steps right + down, then leftmost). nullopt on a map with no free cell.
[[nodiscard]] std::optional<planner::Cell> top_left_start(const planner::OccupancyGrid& map);

// The three stages' groups and complexities, the cleaning order, how much of the floor is grouped.
[[nodiscard]] std::string grouping_text(const planner::OccupancyGrid& map, const CleanRun& run);
// Times to 50 / 80 / 90 / 100 % for both methods, path sizes, and Group-k's clean area when
// plowing is at 40, 45 and 50 %.
[[nodiscard]] std::string coverage_text(const CleanRun& run);

// The map with `groups` (their obstacles and boxes in a colour each, "C=0.53" beside each box;
// with `order`, "#k" gives its place in the cleaning order).
void draw_groups_png(const planner::OccupancyGrid& map, const planner::Grouping& grouping,
                     const std::vector<planner::ObstacleGroup>& groups, const std::vector<int>& order,
                     const std::string& title, const std::string& png_path);

// A coverage path: plowing in one colour, Group-k coloured by part (outside first, then groups).
void draw_path_png(const planner::OccupancyGrid& map, const CleanRun& run, bool group_k,
                   const std::string& png_path);

// Clean % over time, one panel per (name, run), both methods, with dashed marks where plowing
// reaches 40 and 50 %.
[[nodiscard]] Figure coverage_figure(const std::vector<std::pair<std::string, const CleanRun*>>& runs,
                                     const std::string& title);

inline constexpr Colour kPlowColour{213, 94, 0};
inline constexpr Colour kGroupKColour{0, 114, 178};

}  // namespace swarm::tools
