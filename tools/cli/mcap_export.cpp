#include "mcap_export.hpp"

#include <google/protobuf/text_format.h>

#include <stdexcept>

#include "foxglove_json.hpp"
#include "swarm/planner/sensing/raycast.hpp"
#include "swarm/record/mcap_writer.hpp"
#include "swarm/record/record.hpp"
#include "view_data.hpp"

namespace swarm::tools {
namespace {

using nlohmann::json;
using planner::Cell;

// The file's channels, made as they are first written to, one schema per Foxglove type.
class Channels {
 public:
  explicit Channels(record::McapWriter& out) : out_(out) {}

  void send(const std::string& topic, const char* schema_name, std::uint64_t ns, const json& message) {
    auto it = channels_.find(topic);
    if (it == channels_.end()) {
      auto s = schemas_.find(schema_name);
      if (s == schemas_.end()) {
        const json schema = std::string(schema_name) == kStatusSchemaName ? status_schema() : foxglove_schema(schema_name);
        s = schemas_.emplace(schema_name, out_.add_schema(schema_name, "jsonschema", schema.dump())).first;
      }
      it = channels_.emplace(topic, out_.add_channel(s->second, topic, "json")).first;
    }
    out_.write(it->second, ns, message.dump());
    std::string key = topic;
    for (const char* prefix : {"/route/", "/scan/"}) {
      if (topic.rfind(prefix, 0) == 0) key = std::string(prefix) + "*";
    }
    ++per_topic_[key];
  }
  [[nodiscard]] const std::map<std::string, std::uint64_t>& per_topic() const { return per_topic_; }

 private:
  record::McapWriter& out_;
  std::map<std::string, std::uint16_t> schemas_, channels_;
  std::map<std::string, std::uint64_t> per_topic_;
};

std::vector<Cell> cells_of(const google::protobuf::RepeatedField<std::int32_t>& xy) {
  std::vector<Cell> out;
  for (int k = 0; k + 1 < xy.size(); k += 2) out.push_back({xy.Get(k), xy.Get(k + 1)});
  return out;
}

}  // namespace

McapExport export_mcap(const std::vector<record::Frame>& frames, const config::World* world, const std::string& path) {
  if (frames.empty() || !frames.front().has_header()) throw std::runtime_error("the run record has no Header frame");
  const record::Header& h = frames.front().header();
  record::McapWriter out(path);
  Channels channels(out);
  const std::uint64_t tick_ns = std::uint64_t{h.scenario().tick_ms()} * 1'000'000U;
  const FoxgloveFrame frame{h.resolution() > 0 ? h.resolution() : 0.2, h.origin_x(), h.origin_y()};
  const std::vector<std::string> names = record::robot_names(h);

  std::string scenario_text;
  google::protobuf::TextFormat::PrintToString(h.scenario(), &scenario_text);
  std::string mission;
  for (const auto& p : config::mission_phases(h.scenario())) mission += (mission.empty() ? "" : ",") + config::task_name(p);
  out.add_metadata("scenario", {{"seed", std::to_string(h.scenario().seed())},
                                {"map", h.scenario().map()},
                                {"groups", std::to_string(h.groups())},
                                {"robots_per_group", std::to_string(h.robots_per_group())},
                                {"mission", mission},
                                {"tick_ms", std::to_string(h.scenario().tick_ms())},
                                {"scenario", scenario_text}});

  const planner::OccupancyGrid* truth = world != nullptr ? &world->truth : nullptr;
  const int beams = static_cast<int>(h.scenario().lidar_beams());
  const auto range_cells = static_cast<float>(h.scenario().sensing_range_m() / frame.resolution);
  const int per_group = static_cast<int>(std::max(1U, h.robots_per_group()));
  channels.send("/robots", "foxglove.SceneUpdate", 0, foxglove_robots(names, per_group, frame.resolution));
  // What the clock said so far, for /status and the robots' marks.
  StatusFacts status;
  std::vector<bool> lost(names.size(), false);
  std::vector<int> took_over(names.size(), -1);
  std::vector<int> leader_of(h.groups());
  for (std::size_t g = 0; g < leader_of.size(); ++g) leader_of[g] = static_cast<int>(g) * per_group;
  if (truth != nullptr) channels.send("/map/truth", "foxglove.Grid", 0, foxglove_grid(*truth, 0));
  std::vector<float> ranges(static_cast<std::size_t>(std::max(beams, 0)));
  for (const record::Frame& f : frames) {
    if (f.has_map()) {
      const std::uint64_t ns = f.map().tick() * tick_ns;
      channels.send("/map", "foxglove.Grid", ns, foxglove_grid(record::map_of(h, &f.map()), ns));
    } else if (f.has_poses()) {
      const std::uint64_t ns = f.poses().tick() * tick_ns;
      const std::vector<Cell> cells = cells_of(f.poses().xy());
      channels.send("/tf", "foxglove.FrameTransforms", ns, foxglove_transforms(names, cells, frame, ns));
      if (f.poses().has_tally()) {
        const record::Tally& t = f.poses().tally();
        status.tick = f.poses().tick();
        status.vertex_conflicts = t.vertex_conflicts();
        status.edge_conflicts = t.edge_conflicts();
        status.blocked_moves = t.blocked_moves();
        status.progress_done = t.progress_done();
        status.progress_total = t.progress_total();
        status.sent_bytes.assign(t.sent_bytes().begin(), t.sent_bytes().end());
        status.objects.assign(t.objects().begin(), t.objects().end());
        channels.send("/status", kStatusSchemaName, ns, status_message(status));
      }
      if (truth == nullptr || beams <= 0) continue;
      for (std::size_t r = 0; r < cells.size() && r < names.size(); ++r) {
        planner::scan(*truth, cells[r], beams, range_cells, ranges.data());
        channels.send("/scan/" + names[r], "foxglove.LaserScan", ns, foxglove_scan(names[r], ranges, frame.resolution, ns));
      }
    } else if (f.has_route()) {
      const std::uint64_t ns = f.route().tick() * tick_ns;
      channels.send("/route/" + names.at(f.route().robot()), "foxglove.PosesInFrame", ns,
                    foxglove_route(cells_of(f.route().xy()), frame, ns));
    } else if (f.has_event()) {
      const record::Event& e = f.event();
      const std::uint64_t ns = e.tick() * tick_ns;
      if (e.robot() >= names.size()) continue;
      TeamEvent kind = TeamEvent::TakeOver;
      if (e.kind() == record::Event::TAKE_OVER) {
        if (e.group() < leader_of.size()) {
          took_over[static_cast<std::size_t>(leader_of[e.group()])] = -1;
          leader_of[e.group()] = static_cast<int>(e.robot());
        }
        took_over[e.robot()] = static_cast<int>(e.robot()) % per_group == 0 ? -1 : static_cast<int>(e.group());
      } else {
        kind = e.kind() == record::Event::ROBOT_LOST ? TeamEvent::Lost : TeamEvent::Back;
        lost[e.robot()] = kind == TeamEvent::Lost;
        status.lost_robots += kind == TeamEvent::Lost ? 1 : -1;
      }
      channels.send("/log", "foxglove.Log", ns, foxglove_log(event_text(kind, names[e.robot()], static_cast<int>(e.group()), e.tick()), ns));
      channels.send("/robots", "foxglove.SceneUpdate", ns, foxglove_robots(names, per_group, frame.resolution, lost, took_over));
    } else if (f.has_phase()) {
      const record::PhaseChange& p = f.phase();
      const std::uint64_t ns = p.tick() * tick_ns;
      if (!p.ended()) {
        status.phase = p.phase();
        status.task = p.task();
      }
      channels.send("/log", "foxglove.Log", ns,
                    foxglove_log("phase " + std::to_string(p.phase() + 1) + " (" + p.task() + ") " +
                                     (p.ended() ? (p.complete() ? "ended, complete" : "ended, incomplete") : "started"),
                                 ns));
    } else if (f.has_summary()) {
      const std::uint64_t ns = f.summary().steps() * tick_ns;
      channels.send("/log", "foxglove.Log", ns,
                    foxglove_log("run ended at tick " + std::to_string(f.summary().steps()) +
                                     (f.summary().complete() ? ", complete" : ", incomplete"),
                                 ns));
    }
  }
  out.close();
  return {out.messages(), out.bytes(), channels.per_topic()};
}

}  // namespace swarm::tools
