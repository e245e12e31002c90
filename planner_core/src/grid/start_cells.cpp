#include "swarm/planner/grid/start_cells.hpp"

#include "swarm/planner/grid/motion.hpp"

#include <cstddef>
#include <cstdint>

namespace swarm::planner {

std::vector<Cell> start_cells(const OccupancyGrid& truth, Cell start, int n) {
  std::vector<Cell> out;
  if (n <= 0 || !truth.is_free(start)) return out;
  // The output doubles as the BFS queue: it is exactly the visit order, cut at n.
  std::vector<std::uint8_t> seen(truth.size(), 0);
  out.reserve(static_cast<std::size_t>(n));
  out.push_back(start);
  seen[static_cast<std::size_t>(truth.index(start))] = 1;
  const auto wanted = static_cast<std::size_t>(n);
  for (std::size_t head = 0; head < out.size() && out.size() < wanted; ++head) {
    MotionModel::eight().for_each_neighbour(truth, out[head], [&](Cell nb, double) {
      std::uint8_t& s = seen[static_cast<std::size_t>(truth.index(nb))];
      if (s || out.size() >= wanted) return;
      s = 1;
      out.push_back(nb);
    });
  }
  return out;
}

}  // namespace swarm::planner
