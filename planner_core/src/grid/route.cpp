#include "swarm/planner/grid/route.hpp"

namespace swarm::planner {

std::vector<Cell> wait_then(Cell cell, int ticks, const std::vector<Cell>& path) {
  std::vector<Cell> out(static_cast<std::size_t>(ticks > 0 ? ticks : 0) + 1, cell);
  if (!path.empty()) out.insert(out.end(), path.begin() + 1, path.end());
  return out;
}

}  // namespace swarm::planner
