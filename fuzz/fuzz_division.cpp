// Area division of maps nobody drew for it (a user's building, a partial map from exploration):
// any grid of up to 24 x 24 cells with walls anywhere, up to 8 robots anywhere, any weights, any
// start method. divide_areas must answer with a status, never crash; and check_division, the
// independent validator, must find nothing wrong with what it returns: connected regions that
// hold their starts, within one cell of every share when it says converged.
#include <cstdint>
#include <string>
#include <vector>

#include "swarm/planner/coverage/coverage_check.hpp"
#include "swarm/planner/coverage/darp.hpp"

using namespace swarm::planner;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  const int width = 1 + data[0] % 24, height = 1 + data[1] % 24;
  const int robots = 1 + data[2] % 8;
  const std::uint8_t flags = data[3];
  std::size_t at = 4;
  auto next = [&]() -> std::uint8_t { return at < size ? data[at++] : 0; };
  OccupancyGrid map(width, height, 0.2, 0, 0, CellState::Free);
  // One bit per cell: a wall.
  for (int i = 0; i < width * height; i += 8) {
    const std::uint8_t bits = next();
    for (int b = 0; b < 8 && i + b < width * height; ++b) {
      if (bits & (1u << b)) map.set(i + b, CellState::Occupied);
    }
  }
  DarpRequest req;
  for (int r = 0; r < robots; ++r) req.robots.push_back({next() % width, next() % height});
  if (flags & 1) {
    for (int r = 0; r < robots; ++r) req.weights.push_back(0.5 + next() % 4);
  }
  DarpConfig config;
  config.init = static_cast<DarpInit>((flags >> 1) % 4);
  config.distance = (flags & 8) ? DarpDistance::Geodesic : DarpDistance::Euclidean;
  config.seed = flags;
  config.max_iterations = 200;
  const DarpResult r = divide_areas(map, req, config);
  if (r.status == DarpStatus::BadInput) return 0;  // robots on walls or on one cell: said so
  if (r.status == DarpStatus::Failed && r.message.empty()) __builtin_trap();
  if (!check_division(map, req, r, false).empty()) __builtin_trap();
  return 0;
}
