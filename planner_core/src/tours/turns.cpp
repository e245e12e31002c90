#include "swarm/planner/tours/turns.hpp"

#include <cassert>
#include <cstdlib>

namespace swarm::planner {

std::optional<int> step_heading(Cell from, Cell to) {
  const int dx = to.x - from.x;
  const int dy = to.y - from.y;
  assert(std::abs(dx) <= 1 && std::abs(dy) <= 1 && "step_heading: not 8-neighbours");
  if (dx == 0 && dy == 0) return std::nullopt;
  // Indexed by (dy + 1) * 3 + (dx + 1); the centre is unused.
  static constexpr int kHeading[9] = {5, 6, 7, 4, -1, 0, 3, 2, 1};
  return kHeading[(dy + 1) * 3 + (dx + 1)];
}

int rotation_eighths(const std::vector<Cell>& path, std::optional<int> initial,
                     std::optional<int>* final_heading) {
  int total = 0;
  std::optional<int> heading = initial;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const std::optional<int> h = step_heading(path[i - 1], path[i]);
    if (!h) continue;
    if (heading) total += turn_eighths(*heading, *h);
    heading = h;
  }
  if (final_heading != nullptr) *final_heading = heading;
  return total;
}

TurnCounts count_turns(const std::vector<Cell>& path) {
  TurnCounts t;
  std::optional<int> heading;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const std::optional<int> h = step_heading(path[i - 1], path[i]);
    if (!h) continue;
    if (heading) {
      switch (turn_eighths(*heading, *h)) {
        case 1: ++t.turns_45; break;
        case 2: ++t.turns_90; break;
        case 3: ++t.turns_135; break;
        case 4: ++t.turns_180; break;
        default: break;
      }
    }
    heading = h;
  }
  return t;
}

}  // namespace swarm::planner
