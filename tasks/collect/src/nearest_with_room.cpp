#include "swarm/tasks/collect/nearest_with_room.hpp"

#include <cmath>
#include <limits>
#include <numeric>

namespace swarm::collect {

std::vector<int> nearest_with_room(const std::vector<planner::Cell>& objects, const std::vector<planner::Cell>& holders,
                                   std::vector<std::size_t>& held) {
  held.resize(holders.size(), 0);
  std::vector<int> out(objects.size(), -1);
  if (holders.empty()) return out;
  const std::size_t total = std::accumulate(held.begin(), held.end(), objects.size());
  const std::size_t room = (total + holders.size() - 1) / holders.size();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t h = 0; h < holders.size(); ++h) {
      if (held[h] >= room) continue;
      const double d = std::hypot(holders[h].x - objects[i].x, holders[h].y - objects[i].y);
      if (d < best_d) {
        best_d = d;
        out[i] = static_cast<int>(h);
      }
    }
    if (out[i] >= 0) ++held[static_cast<std::size_t>(out[i])];
  }
  return out;
}

}  // namespace swarm::collect
