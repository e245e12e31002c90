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

std::vector<std::uint8_t> encode_patch(const std::vector<planner::CellChange>& changes) {
  return planner::encode_changes(changes, kPatchEncoding);
}

std::vector<planner::CellChange> decode_patch(const std::vector<std::uint8_t>& data) {
  auto changes = planner::decode_changes(data.data(), data.size());
  if (!changes) throw std::runtime_error("received a malformed map patch");
  return *changes;
}

}  // namespace swarm::comm
