#include "view_data.hpp"

#include <stdexcept>
#include <string>

#include "swarm/comm/link.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/record/record.hpp"
#include "swarm/tasks/collect/collect_world.hpp"
#include "swarm/tasks/registry.hpp"

namespace swarm::tools {
namespace {

std::string cells_text(const planner::OccupancyGrid& g) {
  std::string s(g.size(), '0');
  for (std::size_t i = 0; i < g.size(); ++i) {
    const planner::CellState c = g.at(static_cast<int>(i));
    s[i] = c == planner::CellState::Free ? '1' : c == planner::CellState::Occupied ? '2' : '0';
  }
  return s;
}

nlohmann::json xy_of(const google::protobuf::RepeatedField<std::int32_t>& xy) { return nlohmann::json(std::vector<int>(xy.begin(), xy.end())); }

}  // namespace

nlohmann::json mission_layout(const config::World& given) {
  nlohmann::json out = nlohmann::json::array();
  const std::vector<swarm::scenario::Phase> phases = config::mission_phases(given.scenario);
  config::World world = given;
  if (world.phase_data.size() != phases.size()) {
    try {
      tasks::resolve_mission(world, "the run's scenario");  // as the roles do: the same seed, the same objects
    } catch (const std::exception&) {
      return out;  // the run's own roles would have refused it; nothing to draw
    }
  }
  for (std::size_t i = 0; i < phases.size() && i < world.phase_data.size(); ++i) {
    if (!phases[i].has_collect()) continue;
    const auto* c = std::any_cast<tasks::CollectWorld>(&world.phase_data[i]);
    if (c == nullptr) continue;
    nlohmann::json objects = nlohmann::json::array(), destinations = nlohmann::json::array();
    for (const planner::TourObject& o : c->objects) objects.push_back({o.cell.x, o.cell.y, o.type});
    for (const planner::Cell d : c->destinations) destinations.push_back({d.x, d.y});
    out.push_back({{"phase", i}, {"task", config::task_name(phases[i])}, {"objects", objects}, {"destinations", destinations}});
  }
  return out;
}

std::vector<std::string> link_names() {
  std::vector<std::string> names;
  for (int l = 0; l < comm::kLinkClasses; ++l) names.push_back(comm::link_name(static_cast<comm::LinkClass>(l)));
  return names;
}

nlohmann::json status_schema() {
  const nlohmann::json integer = {{"type", "integer"}};
  nlohmann::json bytes = {{"type", "object"}, {"properties", nlohmann::json::object()}};
  for (const std::string& l : link_names()) bytes["properties"][l] = integer;
  return {{"type", "object"},
          {"properties",
           {{"tick", integer},
            {"phase", integer},
            {"task", {{"type", "string"}}},
            {"settling", {{"type", "boolean"}}},
            {"progress_done", integer},
            {"progress_total", integer},
            {"vertex_conflicts", integer},
            {"edge_conflicts", integer},
            {"blocked_moves", integer},
            {"lost_robots", integer},
            {"sent_bytes", bytes},
            {"objects", {{"type", "array"}, {"items", integer}}}}}};
}

nlohmann::json status_message(const StatusFacts& s) {
  nlohmann::json bytes = nlohmann::json::object();
  const std::vector<std::string> links = link_names();
  for (std::size_t l = 0; l < s.sent_bytes.size() && l < links.size(); ++l) bytes[links[l]] = s.sent_bytes[l];
  return {{"tick", s.tick},
          {"phase", s.phase},
          {"task", s.task},
          {"settling", s.settling},
          {"progress_done", s.progress_done},
          {"progress_total", s.progress_total},
          {"vertex_conflicts", s.vertex_conflicts},
          {"edge_conflicts", s.edge_conflicts},
          {"blocked_moves", s.blocked_moves},
          {"lost_robots", s.lost_robots},
          {"sent_bytes", std::move(bytes)},
          {"objects", s.objects}};
}

std::string event_text(TeamEvent e, const std::string& robot, int group, std::uint32_t tick) {
  switch (e) {
    case TeamEvent::Lost: return robot + " lost at tick " + std::to_string(tick);
    case TeamEvent::Back: return robot + " back at tick " + std::to_string(tick);
    case TeamEvent::TakeOver: return robot + " leads group " + std::to_string(group) + " from tick " + std::to_string(tick);
  }
  return robot;
}

nlohmann::json replay_json(const std::vector<record::Frame>& frames, const planner::OccupancyGrid* truth,
                           const nlohmann::json& layout) {
  if (frames.empty() || !frames.front().has_header()) throw std::runtime_error("the run record has no Header frame");
  const record::Header& h = frames.front().header();
  const double resolution = h.resolution() > 0 ? h.resolution() : 0.2;
  std::string mission;
  for (const auto& p : config::mission_phases(h.scenario())) mission += (mission.empty() ? "" : ",") + config::task_name(p);
  nlohmann::json j = {{"width", h.width()},
                      {"height", h.height()},
                      {"resolution", resolution},
                      {"origin", {h.origin_x(), h.origin_y()}},
                      {"groups", h.groups()},
                      {"robots_per_group", h.robots_per_group()},
                      {"names", record::robot_names(h)},
                      {"scenario", {{"map", h.scenario().map()}, {"seed", h.scenario().seed()}, {"mission", mission}}},
                      {"tick_ns", std::uint64_t{h.scenario().tick_ms()} * 1'000'000U},
                      {"truth", truth != nullptr ? nlohmann::json(cells_text(*truth)) : nlohmann::json(nullptr)},
                      {"maps", nlohmann::json::array()},
                      {"poses", nlohmann::json::array()},
                      {"routes", nlohmann::json::array()},
                      {"plans", nlohmann::json::array()},
                      {"phases", nlohmann::json::array()},
                      {"tallies", nlohmann::json::array()},
                      {"events", nlohmann::json::array()},
                      {"links", link_names()},
                      {"layout", layout},
                      {"end", nullptr}};
  for (const record::Frame& f : frames) {
    if (f.has_map()) {
      const planner::OccupancyGrid g = record::map_of(h, &f.map());
      j["maps"].push_back({{"tick", f.map().tick()}, {"cells", cells_text(g)}});
    } else if (f.has_poses()) {
      j["poses"].push_back({{"tick", f.poses().tick()}, {"phase", f.poses().phase()}, {"xy", xy_of(f.poses().xy())}});
      if (f.poses().has_tally()) {
        const record::Tally& t = f.poses().tally();
        j["tallies"].push_back({{"tick", f.poses().tick()},
                                {"vertex", t.vertex_conflicts()},
                                {"edge", t.edge_conflicts()},
                                {"blocked", t.blocked_moves()},
                                {"done", t.progress_done()},
                                {"total", t.progress_total()},
                                {"bytes", std::vector<std::uint64_t>(t.sent_bytes().begin(), t.sent_bytes().end())},
                                {"objects", xy_of(t.objects())}});
      }
    } else if (f.has_plan()) {
      const auto& p = f.plan();
      std::vector<int> segments;
      for (const auto& s : p.global_segments()) segments.insert(segments.end(), s.xy().begin(), s.xy().end());
      j["plans"].push_back({{"tick", p.tick()}, {"group", p.group()}, {"frontiers", xy_of(p.group_frontiers_xy())}, {"segments", segments}});
    } else if (f.has_event()) {
      const auto& e = f.event();
      const char* kind = e.kind() == record::Event::ROBOT_LOST ? "lost" : e.kind() == record::Event::ROBOT_BACK ? "back" : "take_over";
      j["events"].push_back({{"tick", e.tick()}, {"kind", kind}, {"robot", e.robot()}, {"group", e.group()}});
    } else if (f.has_route()) {
      const auto& r = f.route();
      j["routes"].push_back(
          {{"tick", r.tick()}, {"phase", r.phase()}, {"robot", r.robot()}, {"xy", xy_of(r.xy())}, {"region", r.region_cells()}});
    } else if (f.has_phase()) {
      const auto& p = f.phase();
      j["phases"].push_back({{"tick", p.tick()}, {"phase", p.phase()}, {"task", p.task()}, {"ended", p.ended()}, {"complete", p.complete()}});
    } else if (f.has_summary()) {
      j["end"] = {{"tick", f.summary().steps()}, {"complete", f.summary().complete()}};
    }
  }
  return j;
}

}  // namespace swarm::tools
