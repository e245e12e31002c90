// MAPF graph instance files (planner/mapf/graph_file.hpp): bad input throws MapFileError; what
// loads passes check_instance and comes back unchanged from save_graph_instance.
#include <cstdint>

#include "fuzz_files.hpp"
#include "swarm/planner/mapf/graph_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace pm = swarm::planner::mapf;
  pm::Instance in;
  try {
    in = pm::load_graph_instance(swarm::fuzz::temp_file("x.graph", data, size));
  } catch (const swarm::planner::MapFileError&) {
    return 0;
  }
  if (!pm::check_instance(in).empty()) __builtin_trap();
  const std::string copy = swarm::fuzz::temp_file("copy.graph", data, 0);
  pm::save_graph_instance(copy, in);
  const pm::Instance again = pm::load_graph_instance(copy);
  if (!(*again.graph == *in.graph) || again.graph->edges() != in.graph->edges() || again.starts != in.starts ||
      again.goals != in.goals) {
    __builtin_trap();
  }
  return 0;
}
