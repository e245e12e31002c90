// Tour files (planner/tours/tour_file.hpp): bad input throws TourFileError; what parses is a
// problem inside its map (start, destinations and objects on free cells, every object's type a
// destination's). A `map` line gets a fixed 16 x 16 room: the parser opens no file of its own.
#include <cstdint>
#include <string>

#include "swarm/planner/tours/tour_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sp = swarm::planner;
  const std::string text(reinterpret_cast<const char*>(data), size);
  sp::TourFile f;
  try {
    f = sp::parse_tour_file(text, "fuzz.tour", [](const std::string&, const std::string&) {
      return sp::OccupancyGrid(16, 16, 0.1, 0, 0, sp::CellState::Free);
    });
  } catch (const sp::TourFileError&) {
    return 0;
  }
  const auto free = [&](sp::Cell c) { return f.map.in_bounds(c) && f.map.is_free(c); };
  if (!free(f.problem.start)) __builtin_trap();
  if (f.problem.destinations.size() != f.type_names.size()) __builtin_trap();
  for (const sp::Cell d : f.problem.destinations) {
    if (!free(d)) __builtin_trap();
  }
  for (const auto& o : f.problem.objects) {
    if (!free(o.cell) || o.type < 0 || o.type >= static_cast<int>(f.type_names.size())) __builtin_trap();
  }
  return 0;
}
