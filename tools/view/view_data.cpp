#include "view_data.hpp"

#include <stdexcept>
#include <string>

#include "swarm/config/scenario.hpp"
#include "swarm/record/record.hpp"

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

nlohmann::json replay_json(const std::vector<record::Frame>& frames, const planner::OccupancyGrid* truth) {
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
                      {"truth", truth != nullptr ? nlohmann::json(cells_text(*truth)) : nlohmann::json(nullptr)},
                      {"maps", nlohmann::json::array()},
                      {"poses", nlohmann::json::array()},
                      {"routes", nlohmann::json::array()},
                      {"plans", nlohmann::json::array()},
                      {"phases", nlohmann::json::array()},
                      {"end", nullptr}};
  for (const record::Frame& f : frames) {
    if (f.has_map()) {
      const planner::OccupancyGrid g = record::map_of(h, &f.map());
      j["maps"].push_back({{"tick", f.map().tick()}, {"cells", cells_text(g)}});
    } else if (f.has_poses()) {
      j["poses"].push_back({{"tick", f.poses().tick()}, {"phase", f.poses().phase()}, {"xy", xy_of(f.poses().xy())}});
    } else if (f.has_plan()) {
      const auto& p = f.plan();
      j["plans"].push_back({{"tick", p.tick()}, {"group", p.group()}, {"frontiers", xy_of(p.group_frontiers_xy())}});
    } else if (f.has_route()) {
      const auto& r = f.route();
      j["routes"].push_back({{"tick", r.tick()}, {"phase", r.phase()}, {"robot", r.robot()}, {"xy", xy_of(r.xy())}});
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
