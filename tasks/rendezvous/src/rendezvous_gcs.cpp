#include "swarm/tasks/rendezvous/rendezvous_gcs.hpp"

#include <cstdio>

#include "swarm/tasks/rendezvous/gather.hpp"

namespace swarm::gcs {

using planner::Cell;

Cell rendezvous_target(const swarm::scenario::Rendezvous& c, Cell start, const planner::OccupancyGrid& map) {
  return c.has_point() ? map.cell_at(c.point().x(), c.point().y()) : start;
}

RendezvousGcsTask::RendezvousGcsTask(const swarm::scenario::Rendezvous& config, const swarm::scenario::Mapf& paths,
                                     std::uint32_t phase, bool map_given)
    : config_(config),
      drive_(paths, phase, map_given, [this](const GcsContext& ctx, const planner::OccupancyGrid& map,
                                             const std::vector<int>& robots) { return pick(ctx, map, robots); }) {}

std::vector<Cell> RendezvousGcsTask::pick(const GcsContext& ctx, const planner::OccupancyGrid& map,
                                          const std::vector<int>& robots) {
  std::vector<Cell> at;
  for (const int r : robots) at.push_back(ctx.cell_of(r));
  const tasks::rendezvous::Gathering g = tasks::rendezvous::gather(map, rendezvous_target(config_, ctx.setup.world.start, map), at);
  centre_ = g.centre;
  cells_ = g.cells.size();
  path_sum_ = g.path_sum;
  unreachable_.clear();
  std::vector<Cell> goals(static_cast<std::size_t>(ctx.setup.topology.robots()), Cell{-1, -1});
  for (std::size_t i = 0; i < robots.size(); ++i) {
    goals[static_cast<std::size_t>(robots[i])] = g.goals[i];
    if (g.goals[i].x < 0) unreachable_.push_back(robots[i]);
  }
  std::fprintf(stderr, "gcs: rendezvous at tick %u: %zu robots to %zu cells around (%d, %d), paths %.0f cells%s\n",
               ctx.tick(), robots.size(), cells_, centre_.x, centre_.y, path_sum_,
               unreachable_.empty() ? "" : (", " + std::to_string(unreachable_.size()) + " cannot reach it").c_str());
  return goals;
}

void RendezvousGcsTask::step(GcsContext& ctx) {
  for (int r = 0; r < ctx.setup.topology.robots(); ++r) {
    if (!ctx.alive(r) && lost_.insert(r).second) {
      std::fprintf(stderr, "gcs: rendezvous: robot %d lost at tick %u\n", r, ctx.tick());
    }
  }
  drive_.step(ctx);
}

ProgressLine RendezvousGcsTask::progress(const GcsContext& ctx) const {
  ProgressLine line = drive_.progress(ctx);
  line.label = "gathered";
  if (!lost_.empty()) line.detail += "  lost " + std::to_string(lost_.size());
  return line;
}

nlohmann::json RendezvousGcsTask::numbers() const {
  return {{"target", config_.has_point() ? "point" : "home"},
          {"centre", {centre_.x, centre_.y}},
          {"gathering_cells", cells_},
          {"assigned_path_cells", path_sum_},
          {"robots_unreachable", unreachable_},
          {"robots_lost", std::vector<int>(lost_.begin(), lost_.end())},
          {"paths", drive_.numbers()}};
}

}  // namespace swarm::gcs
