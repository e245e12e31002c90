#include "swarm/gcs/gcs_task.hpp"

#include "swarm/planner/grid/map_patch.hpp"

namespace swarm::gcs {

record::Frame map_frame(std::uint32_t tick, std::uint32_t round, std::uint32_t phase,
                        const planner::OccupancyGrid& map) {
  record::Frame f;
  auto* m = f.mutable_map();
  m->set_tick(tick);
  m->set_round(round);
  m->set_phase(phase);
  const auto rle = planner::encode_grid_rle(map);
  m->set_rle(std::string(rle.begin(), rle.end()));
  return f;
}

record::Frame route_frame(std::uint32_t tick, std::uint32_t phase, int robot, const std::vector<planner::Cell>& route,
                          std::uint32_t region_cells) {
  record::Frame f;
  auto* rp = f.mutable_route();
  rp->set_tick(tick);
  rp->set_phase(phase);
  rp->set_robot(static_cast<std::uint32_t>(robot));
  for (const planner::Cell& c : route) {
    rp->add_xy(c.x);
    rp->add_xy(c.y);
  }
  if (region_cells > 0) rp->set_region_cells(region_cells);
  return f;
}

}  // namespace swarm::gcs
