#include "swarm/tasks/mapf/mapf_goals.hpp"

#include <set>
#include <utility>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"

namespace swarm::tasks {

std::vector<planner::Cell> mapf_goals(const swarm::scenario::Mapf& m, const planner::OccupancyGrid& map, int robots,
                                      const std::string& field) {
  std::vector<planner::Cell> goals;
  if (m.has_scen()) {
    const std::string& path = m.scen();
    try {
      const auto scen = planner::mapf::load_movingai_scen(path);
      for (const auto& row : scen.rows) {
        if (row.map_width != map.width() || row.map_height != map.height()) {
          throw config::ConfigError(field + ".scen: " + path + " line " + std::to_string(row.line) + " is for a " +
                            std::to_string(row.map_width) + " x " + std::to_string(row.map_height) + " map; the map is " +
                            std::to_string(map.width()) + " x " + std::to_string(map.height()));
        }
        if (static_cast<int>(goals.size()) == robots) break;
        goals.push_back({row.goal_x, map.height() - 1 - row.goal_y});
      }
      if (static_cast<int>(goals.size()) < robots) {
        throw config::ConfigError(field + ".scen: " + path + " has " + std::to_string(goals.size()) + " rows for " +
                          std::to_string(robots) + " robots");
      }
    } catch (const planner::MapFileError& e) {
      throw config::ConfigError(field + ".scen: " + e.what());
    }
  } else {
    for (const auto& p : m.goals()) {
      goals.push_back(config::MapFrame::of(map).contains(p.x(), p.y()) ? map.cell_at(p.x(), p.y()) : planner::Cell{-1, -1});
    }
  }
  std::set<std::pair<int, int>> seen;
  for (std::size_t r = 0; r < goals.size(); ++r) {
    const planner::Cell c = goals[r];
    const std::string which = field + (m.has_scen() ? ".scen row " : ".goals[") + std::to_string(r) +
                              (m.has_scen() ? "" : "]") + " (robot " + std::to_string(r) + ")";
    if (!map.in_bounds(c)) throw config::ConfigError(which + ": the goal is outside the map");
    if (!map.is_free(c)) {
      throw config::ConfigError(which + ": the goal, cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                        "), is not a free cell of the map");
    }
    if (!seen.insert({c.x, c.y}).second) {
      throw config::ConfigError(which + ": another robot has the same goal cell (" + std::to_string(c.x) + ", " +
                        std::to_string(c.y) + ")");
    }
  }
  return goals;
}

}  // namespace swarm::tasks
