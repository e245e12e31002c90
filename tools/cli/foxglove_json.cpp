#include "foxglove_json.hpp"

#include <array>
#include <cmath>
#include <map>

#include "swarm/planner/sensing/raycast.hpp"

namespace swarm::tools {
namespace {

using nlohmann::json;
using planner::Cell;
using planner::CellState;

// The JSON Schemas of Foxglove's message types, as much of them as the export writes.
json object(json properties) { return {{"type", "object"}, {"properties", std::move(properties)}}; }
json array_of(json items) { return {{"type", "array"}, {"items", std::move(items)}}; }
const json kNumber = {{"type", "number"}};
const json kInteger = {{"type", "integer"}};
const json kString = {{"type", "string"}};
const json kBool = {{"type", "boolean"}};
json time_schema() { return object({{"sec", kInteger}, {"nsec", kInteger}}); }
json vec3_schema() { return object({{"x", kNumber}, {"y", kNumber}, {"z", kNumber}}); }
json pose_schema() {
  return object({{"position", vec3_schema()}, {"orientation", object({{"x", kNumber}, {"y", kNumber}, {"z", kNumber}, {"w", kNumber}})}});
}
json color_schema() { return object({{"r", kNumber}, {"g", kNumber}, {"b", kNumber}, {"a", kNumber}}); }

json grid_schema() {
  return object({{"timestamp", time_schema()},
                 {"frame_id", kString},
                 {"pose", pose_schema()},
                 {"column_count", kInteger},
                 {"cell_size", object({{"x", kNumber}, {"y", kNumber}})},
                 {"row_stride", kInteger},
                 {"cell_stride", kInteger},
                 {"fields", array_of(object({{"name", kString}, {"offset", kInteger}, {"type", kInteger}}))},
                 {"data", {{"type", "string"}, {"contentEncoding", "base64"}}}});
}
json transforms_schema() {
  return object({{"transforms", array_of(object({{"timestamp", time_schema()},
                                                 {"parent_frame_id", kString},
                                                 {"child_frame_id", kString},
                                                 {"translation", vec3_schema()},
                                                 {"rotation", pose_schema()["properties"]["orientation"]}}))}});
}
json scene_schema() {
  const json cube = object({{"pose", pose_schema()}, {"size", vec3_schema()}, {"color", color_schema()}});
  const json line = object({{"type", kInteger},
                            {"pose", pose_schema()},
                            {"thickness", kNumber},
                            {"scale_invariant", kBool},
                            {"points", array_of(vec3_schema())},
                            {"color", color_schema()}});
  const json text = object({{"pose", pose_schema()},
                            {"billboard", kBool},
                            {"font_size", kNumber},
                            {"scale_invariant", kBool},
                            {"color", color_schema()},
                            {"text", kString}});
  return object({{"deletions", array_of(object({{"timestamp", time_schema()}, {"type", kInteger}, {"id", kString}}))},
                 {"entities", array_of(object({{"timestamp", time_schema()},
                                               {"frame_id", kString},
                                               {"id", kString},
                                               {"lifetime", time_schema()},
                                               {"frame_locked", kBool},
                                               {"cubes", array_of(cube)},
                                               {"lines", array_of(line)},
                                               {"texts", array_of(text)}}))}});
}
json poses_schema() {
  return object({{"timestamp", time_schema()}, {"frame_id", kString}, {"poses", array_of(pose_schema())}});
}
json scan_schema() {
  return object({{"timestamp", time_schema()},
                 {"frame_id", kString},
                 {"pose", pose_schema()},
                 {"start_angle", kNumber},
                 {"end_angle", kNumber},
                 {"ranges", array_of(kNumber)},
                 {"intensities", array_of(kNumber)}});
}
json log_schema() {
  return object({{"timestamp", time_schema()},
                 {"level", kInteger},
                 {"message", kString},
                 {"name", kString},
                 {"file", kString},
                 {"line", kInteger}});
}

// The page's palette (tools/view/page/index.html PALETTE): groups in turn; grey, the last, also for the lost.
constexpr std::array<std::array<double, 3>, 8> kPalette = {{{31, 119, 180},
                                                             {255, 127, 14},
                                                             {44, 160, 44},
                                                             {214, 39, 40},
                                                             {148, 103, 189},
                                                             {140, 86, 75},
                                                             {227, 119, 194},
                                                             {127, 127, 127}}};

constexpr int kNumericInt8 = 2;  // foxglove.NumericType
constexpr int kLogInfo = 2;      // foxglove.Log.Level

std::string base64(const std::vector<std::int8_t>& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<std::uint8_t>(bytes[i + 2]);
    out.push_back(kAlphabet[(v >> 18) & 63]);
    out.push_back(kAlphabet[(v >> 12) & 63]);
    out.push_back(i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=');
    out.push_back(i + 2 < bytes.size() ? kAlphabet[v & 63] : '=');
  }
  return out;
}

json identity_pose(double x = 0, double y = 0) {
  return {{"position", {{"x", x}, {"y", y}, {"z", 0.0}}}, {"orientation", {{"x", 0.0}, {"y", 0.0}, {"z", 0.0}, {"w", 1.0}}}};
}

json stamp(std::uint64_t ns) { return {{"sec", ns / 1'000'000'000U}, {"nsec", ns % 1'000'000'000U}}; }

json centre(Cell c, const FoxgloveFrame& f) {
  return {{"x", f.origin_x + (c.x + 0.5) * f.resolution}, {"y", f.origin_y + (c.y + 0.5) * f.resolution}, {"z", 0.0}};
}

}  // namespace

const json& foxglove_schema(const std::string& name) {
  static const std::map<std::string, json> schemas = {{"foxglove.Grid", grid_schema()},
                                                      {"foxglove.FrameTransforms", transforms_schema()},
                                                      {"foxglove.SceneUpdate", scene_schema()},
                                                      {"foxglove.PosesInFrame", poses_schema()},
                                                      {"foxglove.LaserScan", scan_schema()},
                                                      {"foxglove.Log", log_schema()}};
  return schemas.at(name);
}

json foxglove_grid(const planner::OccupancyGrid& g, std::uint64_t ns) {
  std::vector<std::int8_t> cells(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    const CellState s = g.at(static_cast<int>(i));
    cells[i] = s == CellState::Free ? 0 : s == CellState::Occupied ? 100 : -1;
  }
  return {{"timestamp", stamp(ns)},
          {"frame_id", "map"},
          {"pose", identity_pose(g.origin_x(), g.origin_y())},
          {"column_count", g.width()},
          {"cell_size", {{"x", g.resolution()}, {"y", g.resolution()}}},
          {"row_stride", g.width()},
          {"cell_stride", 1},
          {"fields", json::array({{{"name", "occupancy"}, {"offset", 0}, {"type", kNumericInt8}}})},
          {"data", base64(cells)}};
}

json foxglove_transforms(const std::vector<std::string>& names, const std::vector<Cell>& cells, const FoxgloveFrame& f,
                         std::uint64_t ns) {
  json transforms = json::array();
  for (std::size_t r = 0; r < names.size() && r < cells.size(); ++r) {
    transforms.push_back({{"timestamp", stamp(ns)},
                          {"parent_frame_id", "map"},
                          {"child_frame_id", names[r]},
                          {"translation", centre(cells[r], f)},
                          {"rotation", identity_pose()["orientation"]}});
  }
  return {{"transforms", std::move(transforms)}};
}

json group_colour(int group, double alpha) {
  const auto& c = kPalette[static_cast<std::size_t>(group) % kPalette.size()];
  return {{"r", c[0] / 255.0}, {"g", c[1] / 255.0}, {"b", c[2] / 255.0}, {"a", alpha}};
}

json foxglove_robots(const std::vector<std::string>& names, int robots_per_group, double resolution,
                     const std::vector<bool>& lost, const std::vector<int>& took_over) {
  // The viewer page's palette (view/page/index.html), as fractions.

  json entities = json::array();
  for (std::size_t r = 0; r < names.size(); ++r) {
    const bool gone = r < lost.size() && lost[r];
    const int group = static_cast<int>(r / static_cast<std::size_t>(std::max(1, robots_per_group)));
    const auto& grey = kPalette.back();
    const json colour = gone ? json{{"r", grey[0] / 255.0}, {"g", grey[1] / 255.0}, {"b", grey[2] / 255.0}, {"a", 0.5}}
                             : group_colour(group, 1.0);
    std::string label = names[r];
    if (gone) label += " (lost)";
    else if (r < took_over.size() && took_over[r] >= 0) label += " (leads group " + std::to_string(took_over[r]) + ")";
    entities.push_back({{"timestamp", stamp(0)},
                        {"frame_id", names[r]},
                        {"id", names[r]},
                        {"lifetime", stamp(0)},
                        {"frame_locked", true},
                        {"cubes", json::array({{{"pose", identity_pose()},
                                                {"size", {{"x", resolution * 0.8}, {"y", resolution * 0.8}, {"z", resolution * 0.5}}},
                                                {"color", colour}}})},
                        {"texts", json::array({{{"pose", identity_pose()},
                                                {"billboard", true},
                                                {"font_size", 12.0},
                                                {"scale_invariant", true},
                                                {"color", colour},
                                                {"text", label}}})}});
  }
  return {{"deletions", json::array()}, {"entities", std::move(entities)}};
}

json foxglove_route(const std::vector<Cell>& cells, const FoxgloveFrame& f, std::uint64_t ns) {
  json poses = json::array();
  for (const Cell c : cells) {
    json pose = identity_pose();
    pose["position"] = centre(c, f);
    poses.push_back(std::move(pose));
  }
  return {{"timestamp", stamp(ns)}, {"frame_id", "map"}, {"poses", std::move(poses)}};
}

json foxglove_scan(const std::string& robot, const std::vector<float>& ranges_cells, double resolution, std::uint64_t ns) {
  json metres = json::array();
  for (const float c : ranges_cells) metres.push_back(std::round(c * resolution * 1000.0) / 1000.0);
  const int beams = static_cast<int>(ranges_cells.size());
  return {{"timestamp", stamp(ns)},
          {"frame_id", robot},
          {"pose", identity_pose()},
          {"start_angle", 0.0},
          {"end_angle", beams > 0 ? planner::beam_angle(beams - 1, beams) : 0.0},
          {"ranges", std::move(metres)},
          {"intensities", json::array()}};
}

json foxglove_entity(const std::string& id, std::uint64_t ns) {
  return {{"timestamp", stamp(ns)},
          {"frame_id", "map"},
          {"id", id},
          {"lifetime", stamp(0)},
          {"frame_locked", false},
          {"cubes", json::array()},
          {"lines", json::array()},
          {"texts", json::array()}};
}

void add_cells(json& entity, const std::vector<Cell>& cells, const json& colour, const FoxgloveFrame& f) {
  for (const Cell c : cells) {
    json pose = identity_pose();
    pose["position"] = centre(c, f);
    entity["cubes"].push_back({{"pose", std::move(pose)},
                               {"size", {{"x", f.resolution}, {"y", f.resolution}, {"z", f.resolution * 0.05}}},
                               {"color", colour}});
  }
}

void add_line(json& entity, const std::vector<Cell>& cells, const json& colour, const FoxgloveFrame& f) {
  json points = json::array();
  for (const Cell c : cells) points.push_back(centre(c, f));
  entity["lines"].push_back({{"type", 0},  // LINE_STRIP
                             {"pose", identity_pose()},
                             {"thickness", f.resolution * 0.25},
                             {"scale_invariant", false},
                             {"points", std::move(points)},
                             {"color", colour}});
}

json foxglove_log(const std::string& text, std::uint64_t ns) {
  return {{"timestamp", stamp(ns)}, {"level", kLogInfo}, {"message", text}, {"name", "gcs"}, {"file", ""}, {"line", 0}};
}

}  // namespace swarm::tools
