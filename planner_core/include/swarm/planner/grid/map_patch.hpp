// Map changes on the wire: compact byte encodings of CellChange lists and of whole grids.
//
// Patch layout: one tag byte (PatchEncoding), then
//  * Raw:       per change, the cell index as 4 bytes little-endian + 1 state byte (5 bytes each),
//               in the given order;
//  * RunLength: the changes sorted by index (for a repeated index the last one wins), grouped
//               into runs of consecutive indices with one state; per run varint(gap),
//               varint(length), state byte, where gap = start - end of the previous run (end =
//               one past its last index; 0 before the first run).
//  * ZstdRunLength: varint(size of the RunLength body), then that body compressed with zstd.
// Varints are unsigned LEB128 (as in protobuf): 7 bits per byte, low group first, high bit set on
// all but the last byte; at most 5 bytes for 32 bits.
// Whole grids (encode_grid_rle): (count varint, state byte) pairs over the cells in index order,
// i.e. row-major from y = 0; no header, the receiver knows the grid size.
//
// Scan updates are contiguous along beams, so RunLength is usually far smaller than Raw; Raw
// keeps order and duplicates. Decoders validate everything (tags, states 0..2, varint length,
// index overflow, truncation, a cap on the decoded size) and never read out of bounds.
//
//   std::vector<uint8_t> bytes = encode_changes(changes, PatchEncoding::RunLength);
//   if (auto got = decode_changes(bytes.data(), bytes.size())) map.apply(*got);
//
// Thread-safe (no shared state).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

enum class PatchEncoding : std::uint8_t { Raw = 0, RunLength = 1, ZstdRunLength = 2 };

// Decoding refuses patches that expand to more changes than this (a 4096 x 4096 map), so a few
// hostile bytes cannot demand gigabytes.
inline constexpr std::size_t kMaxPatchChanges = std::size_t{1} << 24;

// Indices must be >= 0 (they are y * width + x).
[[nodiscard]] std::vector<std::uint8_t> encode_changes(std::vector<CellChange> changes,
                                                       PatchEncoding encoding);

// nullopt if the input is empty, truncated, has an unknown tag or state, a negative or
// overflowing index, an over-long varint, a zero-length run, or decodes to more than
// kMaxPatchChanges changes. RunLength output is sorted by index.
[[nodiscard]] std::optional<std::vector<CellChange>> decode_changes(const std::uint8_t* data,
                                                                    std::size_t size);

// As above, and nullopt too if a change's index is not a cell of a map of `map_cells` cells.
[[nodiscard]] std::optional<std::vector<CellChange>> decode_changes(const std::uint8_t* data, std::size_t size,
                                                                    std::size_t map_cells);
[[nodiscard]] std::vector<std::uint8_t> encode_grid_rle(const OccupancyGrid& grid);

// Fills `into` (already sized by the receiver) from encode_grid_rle bytes. Returns false, leaving
// `into` unchanged, if the bytes are malformed or do not cover exactly into.size() cells.
[[nodiscard]] bool decode_grid_rle(const std::uint8_t* data, std::size_t size, OccupancyGrid& into);

// zstd around any byte string: varint(original size) + zstd frame. Decompression refuses more
// than max_size bytes and malformed input (nullopt).
[[nodiscard]] std::vector<std::uint8_t> zstd_pack(const std::uint8_t* data, std::size_t size);
[[nodiscard]] std::optional<std::vector<std::uint8_t>> zstd_unpack(const std::uint8_t* data, std::size_t size,
                                                                   std::size_t max_size);

// Whole maps in a run's encoding: RunLength = encode_grid_rle; ZstdRunLength = that, zstd_pack'ed
// (Raw is not used for whole maps: RunLength). decode_grid returns false, leaving `into`
// unchanged, on malformed bytes or bytes for another size.
[[nodiscard]] std::vector<std::uint8_t> encode_grid(const OccupancyGrid& grid, PatchEncoding encoding);
[[nodiscard]] bool decode_grid(const std::uint8_t* data, std::size_t size, PatchEncoding encoding,
                               OccupancyGrid& into);

// Cells as flat x0, y0, x1, y1, ... sequences (paths in messages). nullopt for an odd length.
[[nodiscard]] std::vector<std::int16_t> cells_to_xy(const std::vector<Cell>& cells);
[[nodiscard]] std::optional<std::vector<Cell>> cells_from_xy(const std::int16_t* xy, std::size_t n);

}  // namespace swarm::planner
