#include "mcap_export.hpp"

#include <google/protobuf/text_format.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "swarm/planner/sensing/raycast.hpp"
#include "swarm/record/mcap_writer.hpp"
#include "swarm/record/record.hpp"

namespace swarm::tools {
namespace {

using nlohmann::json;
using planner::Cell;
using planner::CellState;
using planner::OccupancyGrid;

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

class Exporter {
 public:
  Exporter(const std::string& path, const record::Header& h) : out_(path), h_(h) {
    tick_ns_ = std::uint64_t{h.scenario().tick_ms()} * 1'000'000U;
    resolution_ = h.resolution() > 0 ? h.resolution() : 0.2;
    robots_ = static_cast<int>(h.groups() * h.robots_per_group());
    names_ = record::robot_names(h);
  }

  [[nodiscard]] std::uint64_t ns(std::uint32_t tick) const { return tick * tick_ns_; }
  [[nodiscard]] static json stamp(std::uint64_t ns) { return {{"sec", ns / 1'000'000'000U}, {"nsec", ns % 1'000'000'000U}}; }
  [[nodiscard]] const std::string& robot_name(int id) const { return names_[static_cast<std::size_t>(id)]; }
  [[nodiscard]] json cell_centre(int x, int y) const {
    return {{"x", h_.origin_x() + (x + 0.5) * resolution_}, {"y", h_.origin_y() + (y + 0.5) * resolution_}, {"z", 0.0}};
  }

  std::uint16_t channel(const std::string& topic, const char* schema_name, const json& schema) {
    const auto it = channels_.find(topic);
    if (it != channels_.end()) return it->second;
    auto s = schemas_.find(schema_name);
    if (s == schemas_.end()) s = schemas_.emplace(schema_name, out_.add_schema(schema_name, "jsonschema", schema.dump())).first;
    return channels_[topic] = out_.add_channel(s->second, topic, "json");
  }

  void send(const std::string& topic, const char* schema_name, const json& schema, std::uint32_t tick, const json& message) {
    const std::uint16_t c = channel(topic, schema_name, schema);
    out_.write(c, ns(tick), message.dump());
    std::string key = topic;
    for (const char* prefix : {"/route/", "/scan/"}) {
      if (topic.rfind(prefix, 0) == 0) key = std::string(prefix) + "*";
    }
    ++result_.per_topic[key];
  }

  void grid(const std::string& topic, std::uint32_t tick, const OccupancyGrid& g) {
    std::vector<std::int8_t> cells(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      const CellState s = g.at(static_cast<int>(i));
      cells[i] = s == CellState::Free ? 0 : s == CellState::Occupied ? 100 : -1;  // as a ROS occupancy grid
    }
    send(topic, "foxglove.Grid", grid_schema(), tick,
         {{"timestamp", stamp(ns(tick))},
          {"frame_id", "map"},
          {"pose", identity_pose(g.origin_x(), g.origin_y())},
          {"column_count", g.width()},
          {"cell_size", {{"x", g.resolution()}, {"y", g.resolution()}}},
          {"row_stride", g.width()},
          {"cell_stride", 1},
          {"fields", json::array({{{"name", "occupancy"}, {"offset", 0}, {"type", kNumericInt8}}})},
          {"data", base64(cells)}});
  }

  void robots_scene() {
    static constexpr std::array<std::array<double, 3>, 8> kPalette = {{{0.12, 0.47, 0.71},
                                                                        {1.00, 0.50, 0.05},
                                                                        {0.17, 0.63, 0.17},
                                                                        {0.84, 0.15, 0.16},
                                                                        {0.58, 0.40, 0.74},
                                                                        {0.55, 0.34, 0.29},
                                                                        {0.89, 0.47, 0.76},
                                                                        {0.50, 0.50, 0.50}}};
    json entities = json::array();
    for (int r = 0; r < robots_; ++r) {
      const auto& c = kPalette[static_cast<std::size_t>(r / static_cast<int>(h_.robots_per_group())) % kPalette.size()];
      const json colour = {{"r", c[0]}, {"g", c[1]}, {"b", c[2]}, {"a", 1.0}};
      entities.push_back({{"timestamp", stamp(0)},
                          {"frame_id", robot_name(r)},
                          {"id", robot_name(r)},
                          {"lifetime", stamp(0)},
                          {"frame_locked", true},
                          {"cubes", json::array({{{"pose", identity_pose()},
                                                  {"size", {{"x", resolution_ * 0.8}, {"y", resolution_ * 0.8}, {"z", resolution_ * 0.5}}},
                                                  {"color", colour}}})},
                          {"texts", json::array({{{"pose", identity_pose()},
                                                  {"billboard", true},
                                                  {"font_size", 12.0},
                                                  {"scale_invariant", true},
                                                  {"color", colour},
                                                  {"text", robot_name(r)}}})}});
    }
    send("/robots", "foxglove.SceneUpdate", scene_schema(), 0, {{"deletions", json::array()}, {"entities", entities}});
  }

  void poses(const record::Poses& p, const OccupancyGrid* truth, int beams, float range_cells) {
    json transforms = json::array();
    const int n = std::min(robots_, p.xy_size() / 2);
    std::vector<float> ranges(static_cast<std::size_t>(std::max(beams, 0)));
    for (int r = 0; r < n; ++r) {
      const int x = p.xy(2 * r), y = p.xy(2 * r + 1);
      transforms.push_back({{"timestamp", stamp(ns(p.tick()))},
                            {"parent_frame_id", "map"},
                            {"child_frame_id", robot_name(r)},
                            {"translation", cell_centre(x, y)},
                            {"rotation", identity_pose()["orientation"]}});
      if (truth == nullptr || beams <= 0) continue;
      planner::scan(*truth, Cell{x, y}, beams, range_cells, ranges.data());
      json metres = json::array();
      for (const float c : ranges) metres.push_back(std::round(c * resolution_ * 1000.0) / 1000.0);
      scans_.push_back({"/scan/" + robot_name(r),
                        {{"timestamp", stamp(ns(p.tick()))},
                         {"frame_id", robot_name(r)},
                         {"pose", identity_pose()},
                         {"start_angle", 0.0},
                         {"end_angle", planner::beam_angle(beams - 1, beams)},
                         {"ranges", std::move(metres)},
                         {"intensities", json::array()}}});
    }
    send("/tf", "foxglove.FrameTransforms", transforms_schema(), p.tick(), {{"transforms", transforms}});
    for (auto& [topic, message] : scans_) send(topic, "foxglove.LaserScan", scan_schema(), p.tick(), message);
    scans_.clear();
  }

  void route(const record::RoutePlan& r) {
    json poses = json::array();
    for (int k = 0; k + 1 < r.xy_size(); k += 2) {
      json pose = identity_pose();
      pose["position"] = cell_centre(r.xy(k), r.xy(k + 1));
      poses.push_back(std::move(pose));
    }
    send("/route/" + robot_name(static_cast<int>(r.robot())), "foxglove.PosesInFrame", poses_schema(), r.tick(),
         {{"timestamp", stamp(ns(r.tick()))}, {"frame_id", "map"}, {"poses", std::move(poses)}});
  }

  void log(std::uint32_t tick, const std::string& text) {
    send("/log", "foxglove.Log", log_schema(), tick,
         {{"timestamp", stamp(ns(tick))}, {"level", kLogInfo}, {"message", text}, {"name", "gcs"}, {"file", ""}, {"line", 0}});
  }

  McapExport finish() {
    out_.close();
    result_.messages = out_.messages();
    result_.bytes = out_.bytes();
    return result_;
  }

  record::McapWriter& writer() { return out_; }

 private:
  record::McapWriter out_;
  const record::Header& h_;
  std::uint64_t tick_ns_ = 0;
  double resolution_ = 0.2;
  int robots_ = 0;
  std::vector<std::string> names_;
  std::map<std::string, std::uint16_t> schemas_, channels_;
  std::vector<std::pair<std::string, json>> scans_;
  McapExport result_;
};

}  // namespace

McapExport export_mcap(const std::vector<record::Frame>& frames, const config::World* world, const std::string& path) {
  if (frames.empty() || !frames.front().has_header()) throw std::runtime_error("the run record has no Header frame");
  const record::Header& h = frames.front().header();
  Exporter e(path, h);
  std::string scenario_text;
  google::protobuf::TextFormat::PrintToString(h.scenario(), &scenario_text);
  std::string mission;
  for (const auto& p : config::mission_phases(h.scenario())) mission += (mission.empty() ? "" : ",") + config::task_name(p);
  e.writer().add_metadata("scenario", {{"seed", std::to_string(h.scenario().seed())},
                                       {"map", h.scenario().map()},
                                       {"groups", std::to_string(h.groups())},
                                       {"robots_per_group", std::to_string(h.robots_per_group())},
                                       {"mission", mission},
                                       {"tick_ms", std::to_string(h.scenario().tick_ms())},
                                       {"scenario", scenario_text}});
  const OccupancyGrid* truth = world != nullptr ? &world->truth : nullptr;
  const int beams = static_cast<int>(h.scenario().lidar_beams());
  const auto range_cells = static_cast<float>(h.scenario().sensing_range_m() / (h.resolution() > 0 ? h.resolution() : 0.2));
  e.robots_scene();
  if (truth != nullptr) e.grid("/map/truth", 0, *truth);
  for (const record::Frame& f : frames) {
    if (f.has_map()) {
      const OccupancyGrid g = record::map_of(h, &f.map());
      e.grid("/map", f.map().tick(), g);
    } else if (f.has_poses()) {
      e.poses(f.poses(), truth, beams, range_cells);
    } else if (f.has_route()) {
      e.route(f.route());
    } else if (f.has_phase()) {
      const record::PhaseChange& p = f.phase();
      e.log(p.tick(), "phase " + std::to_string(p.phase() + 1) + " (" + p.task() + ") " +
                          (p.ended() ? (p.complete() ? "ended, complete" : "ended, incomplete") : "started"));
    } else if (f.has_summary()) {
      const std::uint32_t tick = f.summary().steps();
      e.log(tick, std::string("run ended at tick ") + std::to_string(tick) + (f.summary().complete() ? ", complete" : ", incomplete"));
    }
  }
  return e.finish();
}

}  // namespace swarm::tools
