// Map patches as they arrive over DDS (patch_up, patch_down, patch_gcs; app::decode_patch wraps
// this): malformed bytes, or cells outside the receiver's map, give nullopt; a patch that decodes
// re-encodes (RunLength) to one that decodes to the same changes.
#include <cstdint>

#include "swarm/planner/grid/map_patch.hpp"

using namespace swarm::planner;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr std::size_t kMapCells = 1u << 20;
  const auto changes = decode_changes(data, size, kMapCells);
  if (!changes) return 0;
  for (const CellChange& c : *changes) {
    if (c.index < 0 || static_cast<std::size_t>(c.index) >= kMapCells) __builtin_trap();
  }
  // RunLength keeps the last change per cell, sorted by index: from there decoding is idempotent.
  const auto once = encode_changes(*changes, PatchEncoding::RunLength);
  const auto again = decode_changes(once.data(), once.size(), kMapCells);
  if (!again) __builtin_trap();
  const auto twice = encode_changes(*again, PatchEncoding::RunLength);
  const auto back = decode_changes(twice.data(), twice.size(), kMapCells);
  if (!back || *back != *again) __builtin_trap();
  return 0;
}
