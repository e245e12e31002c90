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

std::vector<planner::CellChange> decode_patch(const std::vector<std::uint8_t>& data) {
  auto changes = planner::decode_changes(data.data(), data.size());
  if (!changes) throw std::runtime_error("received a malformed map patch");
  return *changes;
}

}  // namespace swarm::comm
