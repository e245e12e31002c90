// Where tests find data that lives outside the repository: the team's MovingAI benchmark maps in
// shared/benchmarks beside the checkout (set at configure time; $SWARM_BENCHMARKS_DIR overrides).
#pragma once

#include <cstdlib>
#include <string>

namespace swarm::test {

inline std::string benchmarks_dir() {
  const char* env = std::getenv("SWARM_BENCHMARKS_DIR");
  return env != nullptr && *env != '\0' ? env : SWARM_BENCHMARKS_DIR;
}

}  // namespace swarm::test
