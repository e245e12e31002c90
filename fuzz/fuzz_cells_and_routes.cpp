// Paths as they arrive over DDS (Route.path_xy, TaskOrder.routes_xy; comm wraps these):
// cells_from_xy; and a mapf plan's action-dependency graph, which
// the leader builds from the routes it receives and which refuses a plan with a conflict by
// throwing std::invalid_argument.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "swarm/planner/grid/map_patch.hpp"
#include "swarm/planner/mapf/adg.hpp"

using namespace swarm::planner;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  std::vector<std::int16_t> xy((size - 2) / 2);
  if (!xy.empty()) std::memcpy(xy.data(), data + 2, xy.size() * 2);
  const auto cells = cells_from_xy(xy.data(), xy.size());
  if (!cells || cells->empty()) return 0;
  if (cells_to_xy(*cells) != xy) __builtin_trap();
  // Up to 4 robots' paths of up to 64 steps each.
  std::vector<mapf::Path> paths;
  const std::size_t robots = 1 + data[0] % 4;
  const std::size_t per = std::max<std::size_t>(1, cells->size() / robots);
  for (std::size_t from = 0; from < cells->size() && paths.size() < robots; from += per) {
    const std::size_t to = std::min({from + per, from + 64, cells->size()});
    paths.emplace_back(cells->begin() + static_cast<std::ptrdiff_t>(from), cells->begin() + static_cast<std::ptrdiff_t>(to));
  }
  try {
    const auto adg = mapf::dependencies(paths);
    std::vector<std::uint32_t> progress(paths.size(), 0);
    for (std::size_t r = 0; r < paths.size(); ++r) (void)mapf::releasable(adg, static_cast<int>(r), progress);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
