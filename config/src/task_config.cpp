#include "swarm/config/task_config.hpp"

#include <set>
#include <utility>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/rng.hpp"

namespace swarm::config {

planner::CoverRoutesConfig cover_routes_config(const swarm::scenario::Cover& c, std::uint64_t seed,
                                               std::uint64_t salt) {
  planner::CoverRoutesConfig out;
  switch (c.darp_init()) {
    case swarm::scenario::DARP_GIVEN: out.darp.init = planner::DarpInit::Given; break;
    case swarm::scenario::DARP_RANDOM: out.darp.init = planner::DarpInit::Random; break;
    case swarm::scenario::DARP_KMEANS: out.darp.init = planner::DarpInit::KMeans; break;
    default: out.darp.init = planner::DarpInit::BfsKMeans; break;
  }
  out.darp.distance =
      c.darp_distance() == swarm::scenario::DARP_EUCLIDEAN ? planner::DarpDistance::Euclidean : planner::DarpDistance::Geodesic;
  out.darp.max_iterations = static_cast<int>(c.darp_max_iterations());
  out.darp.seed = planner::mix_seed(seed, salt);
  switch (c.order()) {
    case swarm::scenario::ORDER_PLOW: out.order = planner::CoverOrder::Plow; break;
    case swarm::scenario::ORDER_GROUP_K: out.order = planner::CoverOrder::GroupK; break;
    default: out.order = planner::CoverOrder::Stc; break;
  }
  return out;
}

planner::mapf::SolverConfig mapf_solver_config(const swarm::scenario::Mapf& m, std::uint64_t seed) {
  planner::mapf::SolverConfig c;
  switch (m.solver()) {
    case swarm::scenario::MAPF_CBS: c.kind = planner::mapf::SolverKind::Cbs; break;
    case swarm::scenario::MAPF_LACAM: c.kind = planner::mapf::SolverKind::Lacam; break;
    default: c.kind = planner::mapf::SolverKind::Ecbs; break;
  }
  c.ecbs.w = m.w();
  c.lacam.seed = seed;
  return c;
}

std::vector<planner::Cell> mapf_goals(const swarm::scenario::Mapf& m, const planner::OccupancyGrid& map, int robots,
                                      const std::string& field) {
  std::vector<planner::Cell> goals;
  if (m.has_scen()) {
    const std::string& path = m.scen();
    try {
      const auto scen = planner::mapf::load_movingai_scen(path);
      for (const auto& row : scen.rows) {
        if (row.map_width != map.width() || row.map_height != map.height()) {
          throw ConfigError(field + ".scen: " + path + " line " + std::to_string(row.line) + " is for a " +
                            std::to_string(row.map_width) + " x " + std::to_string(row.map_height) + " map; the map is " +
                            std::to_string(map.width()) + " x " + std::to_string(map.height()));
        }
        if (static_cast<int>(goals.size()) == robots) break;
        goals.push_back({row.goal_x, map.height() - 1 - row.goal_y});
      }
      if (static_cast<int>(goals.size()) < robots) {
        throw ConfigError(field + ".scen: " + path + " has " + std::to_string(goals.size()) + " rows for " +
                          std::to_string(robots) + " robots");
      }
    } catch (const planner::MapFileError& e) {
      throw ConfigError(field + ".scen: " + e.what());
    }
  } else {
    for (const auto& p : m.goals()) {
      const bool inside = p.x() >= map.origin_x() && p.y() >= map.origin_y() &&
                          p.x() < map.origin_x() + map.width() * map.resolution() &&
                          p.y() < map.origin_y() + map.height() * map.resolution();
      goals.push_back(inside ? map.cell_at(p.x(), p.y()) : planner::Cell{-1, -1});
    }
  }
  std::set<std::pair<int, int>> seen;
  for (std::size_t r = 0; r < goals.size(); ++r) {
    const planner::Cell c = goals[r];
    const std::string which = field + (m.has_scen() ? ".scen row " : ".goals[") + std::to_string(r) +
                              (m.has_scen() ? "" : "]") + " (robot " + std::to_string(r) + ")";
    if (!map.in_bounds(c)) throw ConfigError(which + ": the goal is outside the map");
    if (!map.is_free(c)) {
      throw ConfigError(which + ": the goal, cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                        "), is not a free cell of the map");
    }
    if (!seen.insert({c.x, c.y}).second) {
      throw ConfigError(which + ": another robot has the same goal cell (" + std::to_string(c.x) + ", " +
                        std::to_string(c.y) + ")");
    }
  }
  return goals;
}

}  // namespace swarm::config
