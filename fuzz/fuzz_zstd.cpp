// The zstd wrapper (varint size + zstd frame) under map patches and global maps: never more than
// the size limit, never a crash; what unpacks packs and unpacks to the same bytes.
#include <cstdint>

#include "swarm/planner/grid/map_patch.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr std::size_t kLimit = 1 << 16;
  if (auto out = swarm::planner::zstd_unpack(data, size, kLimit)) {
    if (out->size() > kLimit) __builtin_trap();
    const auto packed = swarm::planner::zstd_pack(out->data(), out->size());
    const auto back = swarm::planner::zstd_unpack(packed.data(), packed.size(), kLimit);
    if (!back || *back != *out) __builtin_trap();
  }
  return 0;
}
