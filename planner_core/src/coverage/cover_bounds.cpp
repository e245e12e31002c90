#include "swarm/planner/coverage/cover_bounds.hpp"

#include <algorithm>
#include <array>

#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {

namespace {
int colour(Cell c) { return (c.x + c.y) & 1; }
}  // namespace

CoverBounds cover_bounds(const OccupancyGrid& map, const std::vector<std::uint8_t>& uncovered,
                         const std::vector<Cell>& robots) {
  CoverBounds out;
  const std::vector<int> moves = step_distances(map, robots, MotionModel::four());
  std::array<int, 2> need{0, 0};  // uncovered cells of each colour
  for (std::size_t i = 0; i < uncovered.size() && i < moves.size(); ++i) {
    if (!uncovered[i]) continue;
    if (moves[i] < 0) {
      out.reachable = false;
      continue;
    }
    out.reach_moves = std::max(out.reach_moves, moves[i]);
    ++need[static_cast<std::size_t>(colour(map.cell_of(static_cast<int>(i))))];
  }
  std::array<int, 2> starting{0, 0};  // robots standing on each colour
  for (const Cell& r : robots) ++starting[static_cast<std::size_t>(colour(r))];
  if (robots.empty()) return out;
  // In k moves a robot lands ⌈k/2⌉ times on the colour it did not start on, ⌊k/2⌋ on its own.
  const auto enough = [&](int k) {
    for (int c = 0; c < 2; ++c) {
      const int own = starting[static_cast<std::size_t>(c)];
      const int other = starting[static_cast<std::size_t>(1 - c)];
      if (own * (k / 2) + other * ((k + 1) / 2) < need[static_cast<std::size_t>(c)]) return false;
    }
    return true;
  };
  int k = 0;
  while (!enough(k)) ++k;  // ends by k = 2 * max(need) + 1: every robot lands that often on each colour
  out.colour_moves = k;
  return out;
}

}  // namespace swarm::planner
