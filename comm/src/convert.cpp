#include "swarm/comm/convert.hpp"

#include <stdexcept>

namespace swarm::comm {

std::vector<std::int16_t> to_xy(const std::vector<planner::Cell>& cells) {
  std::vector<std::int16_t> xy;
  xy.reserve(cells.size() * 2);
  for (const auto& c : cells) {
    xy.push_back(static_cast<std::int16_t>(c.x));
    xy.push_back(static_cast<std::int16_t>(c.y));
  }
  return xy;
}

std::vector<planner::Cell> from_xy(const std::vector<std::int16_t>& xy) {
  if (xy.size() % 2 != 0) throw std::runtime_error("a cell list has an odd number of coordinates");
  std::vector<planner::Cell> cells;
  cells.reserve(xy.size() / 2);
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) cells.push_back({xy[i], xy[i + 1]});
  return cells;
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

std::vector<std::optional<planner::Cell>> optional_cells_from_xy(const std::vector<std::int16_t>& xy) {
  std::vector<std::optional<planner::Cell>> cells;
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
    if (xy[i] < 0 || xy[i + 1] < 0) {
      cells.emplace_back(std::nullopt);
    } else {
      cells.emplace_back(planner::Cell{xy[i], xy[i + 1]});
    }
  }
  return cells;
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
  std::vector<std::uint8_t> rle = planner::encode_grid_rle(map);
  if (encoding != planner::PatchEncoding::ZstdRunLength) return rle;
  return planner::zstd_pack(rle.data(), rle.size());
}

void decode_map(const std::vector<std::uint8_t>& data, planner::PatchEncoding encoding, planner::OccupancyGrid& into) {
  bool ok = false;
  if (encoding == planner::PatchEncoding::ZstdRunLength) {
    // An RLE pair is at most 6 bytes per cell.
    if (auto rle = planner::zstd_unpack(data.data(), data.size(), 6 * into.size() + 16)) {
      ok = planner::decode_grid_rle(rle->data(), rle->size(), into);
    }
  } else {
    ok = planner::decode_grid_rle(data.data(), data.size(), into);
  }
  if (!ok) throw std::runtime_error("received a malformed global map");
}

std::vector<planner::CellChange> decode_patch(const std::vector<std::uint8_t>& data, std::size_t map_cells) {
  auto changes = planner::decode_changes(data.data(), data.size());
  if (!changes) throw std::runtime_error("received a malformed map patch");
  for (const planner::CellChange& c : *changes) {
    if (c.index < 0 || static_cast<std::size_t>(c.index) >= map_cells) {
      throw std::runtime_error("a map patch changes cell " + std::to_string(c.index) + " of a map of " +
                               std::to_string(map_cells) + " cells");
    }
  }
  return *changes;
}

std::vector<std::uint8_t> encode_mask(const std::vector<std::uint8_t>& mask, int width, int height) {
  planner::OccupancyGrid g(width, height);
  for (std::size_t i = 0; i < mask.size() && i < g.size(); ++i) {
    if (mask[i]) g.set(static_cast<int>(i), planner::CellState::Free);
  }
  return planner::encode_grid_rle(g);
}

std::vector<std::uint8_t> decode_mask(const std::vector<std::uint8_t>& data, int width, int height) {
  planner::OccupancyGrid g(width, height);
  if (!planner::decode_grid_rle(data.data(), data.size(), g)) {
    throw std::runtime_error("a cell set does not decode to " + std::to_string(width) + " x " +
                             std::to_string(height) + " cells");
  }
  std::vector<std::uint8_t> mask(g.size(), 0);
  for (std::size_t i = 0; i < g.size(); ++i) mask[i] = g.at(static_cast<int>(i)) == planner::CellState::Free;
  return mask;
}

}  // namespace swarm::comm
