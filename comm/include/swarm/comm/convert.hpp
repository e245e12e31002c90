// The one place where generated message fields become planner_core types and back (STYLE.md 7).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/planner/grid.hpp"
#include "swarm/planner/map_patch.hpp"

namespace swarm::comm {

// Cells as flat x0, y0, x1, y1, ... sequences of shorts.
std::vector<std::int16_t> to_xy(const std::vector<planner::Cell>& cells);
std::vector<planner::Cell> from_xy(const std::vector<std::int16_t>& xy);
// Optional cells: (-1, -1) stands for "none".
std::vector<std::int16_t> to_xy(const std::vector<std::optional<planner::Cell>>& cells);
std::vector<std::optional<planner::Cell>> optional_cells_from_xy(const std::vector<std::int16_t>& xy);

// Map patches: the encoding every run uses on the wire (run-length; see planner/map_patch.hpp).
inline constexpr planner::PatchEncoding kPatchEncoding = planner::PatchEncoding::RunLength;
std::vector<std::uint8_t> encode_patch(const std::vector<planner::CellChange>& changes);
// Throws std::runtime_error on a malformed patch (a peer bug, not an expected condition).
std::vector<planner::CellChange> decode_patch(const std::vector<std::uint8_t>& data);

}  // namespace swarm::comm
