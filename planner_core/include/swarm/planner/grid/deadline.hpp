// A deadline `seconds` from now that never wraps. A limit of 1e10 s or inf converted to
// steady_clock ticks would overflow to a time already past and stop a search at once; here any
// limit beyond the clock's range is "no limit" (time_point::max()), and 0 or less is "now".
// NaN is the callers' to refuse (config::Problems::time_limit, the CLI's number checks); here it
// reads as no time at all.
#pragma once

#include <chrono>
#include <cmath>

namespace swarm::planner {

[[nodiscard]] inline std::chrono::steady_clock::time_point deadline_after(
    double seconds, std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now()) {
  using Clock = std::chrono::steady_clock;
  if (!(seconds > 0)) return now;
  // Room left on the clock, in seconds; a limit at or past it never comes.
  const double room = std::chrono::duration<double>(Clock::time_point::max() - now).count();
  if (!(seconds < room * 0.5)) return Clock::time_point::max();
  return now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

}  // namespace swarm::planner
