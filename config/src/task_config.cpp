#include "swarm/config/task_config.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"
#include "swarm/planner/grid/rng.hpp"

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

bool delivery_ticks_bounded(const swarm::scenario::Scenario& s) {
  auto bounded = [](const swarm::scenario::Link& l) {
    return l.loss() == 0 && l.delay_ms() == 0 && l.bandwidth_bytes_per_s() == 0;
  };
  return !s.realtime() && bounded(s.links().sim_robot()) && bounded(s.links().member_leader()) &&
         bounded(s.links().leader_gcs());
}

bool map_given(const swarm::scenario::Scenario& s, std::size_t index) {
  const auto phases = mission_phases(s);
  for (std::size_t i = 0; i <= index && i < phases.size(); ++i) {
    if (phases[i].has_explore()) return false;
  }
  return index < phases.size();
}

bool any_map_given(const swarm::scenario::Scenario& s) {
  const std::size_t phases = mission_phases(s).size();
  for (std::size_t i = 0; i < phases; ++i) {
    if (map_given(s, i)) return true;
  }
  return false;
}

swarm::scenario::Mapf resolved_mapf(const swarm::scenario::Mapf& mapf, const swarm::scenario::Scenario& s) {
  swarm::scenario::Mapf m = mapf;
  if (m.execution() != swarm::scenario::MAPF_EXECUTE_AUTO) return m;
  auto undelayed = [](const swarm::scenario::Link& l) { return l.delay_ticks() == 0 && l.jitter_ticks() == 0; };
  // Any fault (a kill too: timed robots would not wait for a dead one's replanned neighbours,
  // and a route through its cell would block for good) calls for the graph.
  const bool timed = delivery_ticks_bounded(s) && s.faults_size() == 0 && undelayed(s.links().sim_robot()) &&
                     undelayed(s.links().member_leader()) && undelayed(s.links().leader_gcs());
  m.set_execution(timed ? swarm::scenario::MAPF_EXECUTE_TIMED : swarm::scenario::MAPF_EXECUTE_ADG);
  return m;
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

namespace {

planner::Cell cell_of_point(const planner::OccupancyGrid& map, double x, double y) {
  const bool inside = x >= map.origin_x() && y >= map.origin_y() && x < map.origin_x() + map.width() * map.resolution() &&
                      y < map.origin_y() + map.height() * map.resolution();
  return inside ? map.cell_at(x, y) : planner::Cell{-1, -1};
}

}  // namespace

CollectWorld collect_world(const swarm::scenario::Collect& c, const planner::OccupancyGrid& map,
                           const std::vector<planner::Cell>& robot_cells, std::uint64_t seed, const std::string& field) {
  CollectWorld w;
  // Reachable by any robot from its start (the live task gives each object to some robot).
  const auto reach = planner::reachable_mask(map, robot_cells, planner::MotionModel::eight());
  std::vector<std::uint8_t> taken(map.size(), 0);
  for (const planner::Cell& r : robot_cells) taken[map.index(r)] = 1;
  const auto check = [&](planner::Cell cell, const std::string& which) {
    if (!map.in_bounds(cell)) throw ConfigError(field + which + ": outside the map");
    if (!map.is_free(cell)) throw ConfigError(field + which + ": on a cell that is not free");
    if (!reach[map.index(cell)]) throw ConfigError(field + which + ": no robot can reach it");
  };
  for (int i = 0; i < c.destinations_size(); ++i) {
    w.destinations.push_back(cell_of_point(map, c.destinations(i).x(), c.destinations(i).y()));
    check(w.destinations.back(), ".destinations[" + std::to_string(i) + "]");
  }
  if (c.objects_size() > 0) {
    for (int i = 0; i < c.objects_size(); ++i) {
      const auto& o = c.objects(i);
      w.objects.push_back({cell_of_point(map, o.at().x(), o.at().y()), static_cast<int>(o.type())});
      check(w.objects.back().cell, ".objects[" + std::to_string(i) + "]");
    }
  } else {
    planner::Rng rng(planner::mix_seed(seed, 7000));
    std::vector<int> free;
    for (std::size_t i = 0; i < map.size(); ++i) {
      if (reach[i] && !taken[i]) free.push_back(static_cast<int>(i));
    }
    const std::uint32_t count = c.scatter() * c.types();
    if (free.size() < count + c.types()) {
      throw ConfigError(field + ".scatter: " + std::to_string(count) + " objects do not fit in " +
                        std::to_string(free.size()) + " free cells");
    }
    for (std::uint32_t t = 0; t < c.types(); ++t) {
      for (std::uint32_t k = 0; k < c.scatter(); ++k) {
        const std::size_t pick = rng.below(free.size());
        w.objects.push_back({map.cell_of(free[pick]), static_cast<int>(t)});
        taken[static_cast<std::size_t>(free[pick])] = 1;
        free.erase(free.begin() + static_cast<std::ptrdiff_t>(pick));
      }
    }
  }
  if (w.destinations.empty()) {
    // Free reachable cells beside a wall, in index order, taken evenly spaced: one per type.
    std::vector<planner::Cell> border;
    for (std::size_t i = 0; i < map.size(); ++i) {
      const planner::Cell cell = map.cell_of(static_cast<int>(i));
      if (!reach[i] || taken[i]) continue;
      bool wall = false;
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) wall = wall || map.is_occupied({cell.x + dx, cell.y + dy});
      }
      if (wall) border.push_back(cell);
    }
    int types = static_cast<int>(c.types());
    for (const auto& o : w.objects) types = std::max(types, o.type + 1);
    for (int t = 0; t < types && !border.empty(); ++t) {
      w.destinations.push_back(border[(static_cast<std::size_t>(t) * border.size()) / static_cast<std::size_t>(types)]);
    }
  }
  for (std::size_t i = 0; i < w.objects.size(); ++i) {
    if (w.objects[i].type < 0 || static_cast<std::size_t>(w.objects[i].type) >= w.destinations.size()) {
      throw ConfigError(field + ".objects[" + std::to_string(i) + "]: its type " + std::to_string(w.objects[i].type) +
                        " has no destination (" + std::to_string(w.destinations.size()) + " given)");
    }
  }
  return w;
}

}  // namespace swarm::config
