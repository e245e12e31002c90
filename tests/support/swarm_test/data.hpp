// Where tests find data: the MovingAI benchmark maps and DARP instances in data/ (set at configure
// time; $SWARM_BENCHMARKS_DIR overrides), and the source tree's own
// files (built-in maps, scenarios).
#pragma once

#include <cstdlib>
#include <string>

namespace swarm::test {

inline std::string benchmarks_dir() {
  const char* env = std::getenv("SWARM_BENCHMARKS_DIR");
  return env != nullptr && *env != '\0' ? env : SWARM_BENCHMARKS_DIR;
}

// The source tree (maps/, scenarios/), as configured.
inline std::string source_dir() { return SWARM_TEST_SOURCE_DIR; }

}  // namespace swarm::test
