// Whole maps as they arrive over DDS (RoundStart; app::decode_map wraps
// this): run-length and zstd run-length, into a map of the receiver's size. The first two bytes
// choose that size (1..64 each) and the encoding; malformed bytes give false and leave the map as
// it was; a map that decodes encodes back to bytes that decode the same.
#include <cstdint>

#include "swarm/planner/grid/map_patch.hpp"

using namespace swarm::planner;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int width = 1 + (data[0] & 63), height = 1 + (data[1] & 63);
  const auto encoding = (data[0] & 64) ? PatchEncoding::ZstdRunLength : PatchEncoding::RunLength;
  OccupancyGrid map(width, height);
  if (!decode_grid(data + 2, size - 2, encoding, map)) {
    for (std::size_t i = 0; i < map.size(); ++i) {
      if (map.at(static_cast<int>(i)) != CellState::Unknown) __builtin_trap();  // left unchanged
    }
    return 0;
  }
  const auto bytes = encode_grid(map, encoding);
  OccupancyGrid again(width, height);
  if (!decode_grid(bytes.data(), bytes.size(), encoding, again)) __builtin_trap();
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (map.at(static_cast<int>(i)) != again.at(static_cast<int>(i))) __builtin_trap();
  }
  return 0;
}
