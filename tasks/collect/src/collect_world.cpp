#include "swarm/tasks/collect/collect_world.hpp"

#include <algorithm>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/motion.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::tasks {

namespace {

planner::Cell cell_of_point(const planner::OccupancyGrid& map, double x, double y) {
  return config::MapFrame::of(map).contains(x, y) ? map.cell_at(x, y) : planner::Cell{-1, -1};
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
    if (!map.in_bounds(cell)) throw config::ConfigError(field + which + ": outside the map");
    if (!map.is_free(cell)) throw config::ConfigError(field + which + ": on a cell that is not free");
    if (!reach[map.index(cell)]) throw config::ConfigError(field + which + ": no robot can reach it");
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
      throw config::ConfigError(field + ".scatter: " + std::to_string(count) + " objects do not fit in " +
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
      throw config::ConfigError(field + ".objects[" + std::to_string(i) + "]: its type " + std::to_string(w.objects[i].type) +
                        " has no destination (" + std::to_string(w.destinations.size()) + " given)");
    }
  }
  return w;
}

}  // namespace swarm::tasks
