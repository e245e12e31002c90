// Foxglove's message types as JSON (docs.foxglove.dev "Schemas"), for the MCAP export
// (mcap_export.hpp) and the live view (view/live_view.hpp): the same robots, maps and logs in both.
//
// Frames: "map" (metres, the map's origin) and one per robot, named as record::robot_names says.
// A robot stands at the centre of its cell. Times are nanoseconds (a tick times the tick length).
//
//   const FoxgloveFrame f{resolution, origin_x, origin_y};
//   json m = foxglove_transforms(names, cells, f, ns);   // schema: foxglove_schema("foxglove.FrameTransforms")
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::tools {

struct FoxgloveFrame {
  double resolution = 0.2;
  double origin_x = 0.0, origin_y = 0.0;
};

// The JSON Schema of a Foxglove type this file writes: foxglove.Grid, FrameTransforms,
// SceneUpdate, PosesInFrame, LaserScan, Log. Throws std::out_of_range for another name.
[[nodiscard]] const nlohmann::json& foxglove_schema(const std::string& name);

// The map as an occupancy grid: one int8 field, 0 free, 100 wall, -1 unknown (as ROS's).
[[nodiscard]] nlohmann::json foxglove_grid(const planner::OccupancyGrid& g, std::uint64_t ns);
// Every robot's frame in "map", cells[i] for names[i].
[[nodiscard]] nlohmann::json foxglove_transforms(const std::vector<std::string>& names, const std::vector<planner::Cell>& cells,
                                                 const FoxgloveFrame& f, std::uint64_t ns);
// One cube and label per robot, locked to its frame, in its group's colour (robots_per_group a group);
// a robot marked in `lost` grey, its label "NAME (lost)"; one with took_over[r] = G >= 0 leads
// group G in its first leader's place: "NAME (leads group G)".
[[nodiscard]] nlohmann::json foxglove_robots(const std::vector<std::string>& names, int robots_per_group, double resolution,
                                             const std::vector<bool>& lost = {}, const std::vector<int>& took_over = {});
// A group's colour as a foxglove.Color (the page's palette).
[[nodiscard]] nlohmann::json group_colour(int group, double alpha);
// A foxglove.SceneUpdate entity in "map" with no primitives yet, and what add_cells (one flat cube per
// cell) and add_line (a line strip through the cells' centres) put in it.
[[nodiscard]] nlohmann::json foxglove_entity(const std::string& id, std::uint64_t ns);
void add_cells(nlohmann::json& entity, const std::vector<planner::Cell>& cells, const nlohmann::json& colour, const FoxgloveFrame& f);
void add_line(nlohmann::json& entity, const std::vector<planner::Cell>& cells, const nlohmann::json& colour, const FoxgloveFrame& f);
// A route: its cells as poses in "map".
[[nodiscard]] nlohmann::json foxglove_route(const std::vector<planner::Cell>& cells, const FoxgloveFrame& f, std::uint64_t ns);
// A 360-degree scan in the robot's frame: beam i at 2 pi i / beams, ranges in cells.
[[nodiscard]] nlohmann::json foxglove_scan(const std::string& robot, const std::vector<float>& ranges_cells, double resolution,
                                           std::uint64_t ns);
[[nodiscard]] nlohmann::json foxglove_log(const std::string& text, std::uint64_t ns);

}  // namespace swarm::tools
