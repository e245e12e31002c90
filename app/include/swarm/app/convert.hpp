// The one place where generated message fields become planner_core types and back (docs/style.md 7).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/map_patch.hpp"
#include "swarm/planner/grid/route.hpp"
#include "swarm_msgs.h"

namespace swarm::app {

// Decoders of bytes from other processes throw std::runtime_error on malformed input (never read
// or write out of bounds, never allocate more than the run's map allows); the mailbox drops such
// a message with a log line (lockstep.hpp).

// Cells as flat x0, y0, x1, y1, ... sequences of shorts. from_xy throws on an odd length.
std::vector<std::int16_t> to_xy(const std::vector<planner::Cell>& cells);
std::vector<planner::Cell> from_xy(const std::vector<std::int16_t>& xy);
// Optional cells: (-1, -1) stands for "none".
std::vector<std::int16_t> to_xy(const std::vector<std::optional<planner::Cell>>& cells);

// The simulator's report on a robot's latest route, carried in its Sense.
planner::RouteProgress route_progress(const msgs::Sense& sense);

// Map patches in the run's encoding (scenario map_encoding; see planner/grid/map_patch.hpp).
planner::PatchEncoding patch_encoding(int scenario_map_encoding);
std::vector<std::uint8_t> encode_patch(const std::vector<planner::CellChange>& changes, planner::PatchEncoding encoding);
// Throws std::runtime_error on a malformed patch, or one with a cell index outside a map of
// `map_cells` cells. The encoding is read from the patch itself.
std::vector<planner::CellChange> decode_patch(const std::vector<std::uint8_t>& data, std::size_t map_cells);

// Whole global maps: run-length, zstd-compressed when the run's encoding is ZstdRunLength.
std::vector<std::uint8_t> encode_map(const planner::OccupancyGrid& map, planner::PatchEncoding encoding);
// Throws std::runtime_error when the bytes do not decode to a map of into's size.
void decode_map(const std::vector<std::uint8_t>& data, planner::PatchEncoding encoding, planner::OccupancyGrid& into);

}  // namespace swarm::app
