// MovingAI benchmark files: a `.map` (first input byte even) or a `.scen` (odd); bad input throws
// planner::MapFileError.
#include <cstdint>

#include "fuzz_files.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/mapf/movingai_scen.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  try {
    if (data[0] % 2 == 0) {
      const auto map = swarm::planner::load_movingai_map(swarm::fuzz::temp_file("x.map", data + 1, size - 1));
      if (map.width() <= 0 || map.height() <= 0) __builtin_trap();
    } else {
      (void)swarm::planner::mapf::load_movingai_scen(swarm::fuzz::temp_file("x.scen", data + 1, size - 1));
    }
  } catch (const swarm::planner::MapFileError&) {
  }
  return 0;
}
