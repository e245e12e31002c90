#include "swarm/app/convert.hpp"

#include <stdexcept>

namespace swarm::app {

std::vector<std::int16_t> to_xy(const std::vector<planner::Cell>& cells) { return planner::cells_to_xy(cells); }

std::vector<planner::Cell> from_xy(const std::vector<std::int16_t>& xy) {
  auto cells = planner::cells_from_xy(xy.data(), xy.size());
  if (!cells) throw std::runtime_error("a cell list has an odd number of coordinates");
  return *cells;
}

std::vector<std::int16_t> to_xy(const std::vector<std::optional<planner::Cell>>& cells) {
  std::vector<std::int16_t> xy;
  xy.reserve(cells.size() * 2);
  for (const auto& c : cells) {
    xy.push_back(static_cast<std::int16_t>(c ? c->x : -1));
    xy.push_back(static_cast<std::int16_t>(c ? c->y : -1));
  }
  return xy;
}

planner::RouteProgress route_progress(const msgs::Sense& s) {
  return {s.route_id(), s.route_step(), static_cast<planner::RouteState>(s.route_state())};
}

planner::PatchEncoding patch_encoding(int scenario_map_encoding) {
  // The scenario's MapEncoding numbers match planner::PatchEncoding on purpose.
  switch (scenario_map_encoding) {
    case 0: return planner::PatchEncoding::Raw;
    case 2: return planner::PatchEncoding::ZstdRunLength;
    default: return planner::PatchEncoding::RunLength;
  }
}

std::vector<std::uint8_t> encode_patch(const std::vector<planner::CellChange>& changes, planner::PatchEncoding encoding) {
  return planner::encode_changes(changes, encoding);
}

std::vector<std::uint8_t> encode_map(const planner::OccupancyGrid& map, planner::PatchEncoding encoding) {
  return planner::encode_grid(map, encoding);
}

void decode_map(const std::vector<std::uint8_t>& data, planner::PatchEncoding encoding, planner::OccupancyGrid& into) {
  if (!planner::decode_grid(data.data(), data.size(), encoding, into)) {
    throw std::runtime_error("received a malformed global map");
  }
}

std::vector<planner::CellChange> decode_patch(const std::vector<std::uint8_t>& data, std::size_t map_cells) {
  auto changes = planner::decode_changes(data.data(), data.size(), map_cells);
  if (!changes) {
    throw std::runtime_error("received a malformed map patch, or one with cells outside the map of " +
                             std::to_string(map_cells) + " cells");
  }
  return *changes;
}

}  // namespace swarm::app
