// Pictures of a run from its record (record.hpp): the explored map with every robot's path, and
// frontier snapshots like Fig. 10 of the group-frontier paper (docs/papers.md section 1).
//
// Image layout: a band of kBandPx rows on top holds a title line and two legend lines; below it
// the map, `scale` pixels per cell, with y up (cell row y = 0 is the BOTTOM row of the image),
// starting at the left edge; an image narrower than kMinImageWidthPx is widened on the right (in
// the band's light grey) so the title stays readable. Colours:
// unknown mid grey, free white, occupied black; each group has one colour of the Okabe-Ito
// colour-blind-safe palette (group_colour); the start cell is a red X. Frontier snapshots draw
// the global map the leaders planned with; what the GCS had fused since is light grey (free) and
// dark grey (occupied).
//
//   auto frames = swarm::record::read_record(run_dir + "/run.pb");
//   swarm::record::render_map_png(frames, run_dir + "/map.png");
//   swarm::record::render_frontier_png(frames, 120, run_dir + "/frontiers-120.png");
//
// Both throw std::runtime_error when the record has no Header frame, a map version does not
// decode, or the PNG cannot be written. Thread-safe (no shared state).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <optional>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/proto/run_record.pb.h"

namespace swarm::record {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb& a, const Rgb& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  }
};

inline constexpr Rgb kUnknownColour{128, 128, 128};
inline constexpr Rgb kFreeColour{255, 255, 255};
inline constexpr Rgb kOccupiedColour{0, 0, 0};
inline constexpr Rgb kStartColour{230, 0, 0};
// Frontier snapshots: cells unknown in the planning map but known in the newer fused map.
inline constexpr Rgb kSeenFreeColour{200, 200, 200};
inline constexpr Rgb kSeenOccupiedColour{64, 64, 64};
inline constexpr int kBandPx = 56;             // title + two legend rows above the map
inline constexpr int kMinImageWidthPx = 480;  // room for the title and the legend

// Colour of group g (0-based); the palette repeats after 7 groups.
Rgb group_colour(int group);

// Where things land in a rendered image. Pixel columns grow to the right, rows downwards.
struct RenderGeometry {
  int width_cells = 0;
  int height_cells = 0;
  int scale = 6;  // pixels per cell side

  int image_width() const {
    return width_cells * scale > kMinImageWidthPx ? width_cells * scale : kMinImageWidthPx;
  }
  int image_height() const { return kBandPx + height_cells * scale; }
  // Top-left pixel of cell (x, y).
  int left(int x) const { return x * scale; }
  int top(int y) const { return kBandPx + (height_cells - 1 - y) * scale; }
  // Centre pixel of cell (x, y).
  int centre_col(int x) const { return left(x) + scale / 2; }
  int centre_row(int y) const { return top(y) + scale / 2; }
};

// The geometry render_*_png use for these frames (map size from the Header frame).
RenderGeometry render_geometry(const std::vector<Frame>& frames, int scale = 6);

// The last map version as background, each robot's path in its group's colour (leaders, robot
// index 0 of a group, thicker than members), the start cell, a legend and a title line (map,
// mode, steps and planning rounds from the Summary frame).
void render_map_png(const std::vector<Frame>& frames, const std::string& png_path, int scale = 6);

// The maps behind a frontier snapshot at `tick`. The planning round in force is the highest round
// among the plans made at or before `tick`; its leaders planned with the global map their
// RoundStart message carried (under the paper's delay a round older than the GCS's fused map),
// which the record names by MapVersion.planning_map_tick.
struct SnapshotMaps {
  std::optional<std::uint32_t> round;        // planning round in force; nullopt before any plan
  planner::OccupancyGrid planned;            // the global map that round was planned with
  std::optional<std::uint32_t> planned_tick; // when `planned` was fused; nullopt = no map yet
  planner::OccupancyGrid fused;              // the GCS's newest fused map at or before `tick`
  std::optional<std::uint32_t> fused_tick;   // nullopt = no map yet (all unknown)
  // false for records written before planning_map_tick existed (and before the first plan):
  // `planned` is then the fused map, as older pictures drew it.
  bool planned_recorded = false;
};

// Throws std::runtime_error as the renderers do, and when planning_map_tick names no map version.
SnapshotMaps snapshot_maps(const std::vector<Frame>& frames, std::uint32_t tick);

// A frontier snapshot (Fig. 10 of the paper) at `tick`: as background the global map the leaders
// planned with (snapshot_maps), with the cells the GCS had fused since drawn light / dark grey;
// the robots at `tick`; for the planning round in force each group's group frontiers filled in
// its colour, the global frontier segments hatched and outlined (the segment a group chose in
// case B outlined in its colour), and each robot's waypoint linked to it. The title names both
// maps' ticks.
void render_frontier_png(const std::vector<Frame>& frames, std::uint32_t tick,
                         const std::string& png_path, int scale = 6);

}  // namespace swarm::record
