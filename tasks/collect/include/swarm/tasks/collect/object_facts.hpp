// What collect's leaders and GCS tell each other of an object: in a report's and a resume
// order's values, one (object, what, a, b) set per object, `what` one of these.
#pragma once

#include <cstdint>

namespace swarm::collect {

inline constexpr std::int32_t kObjectLying = 0;      // on cell (a, b)
inline constexpr std::int32_t kObjectCarried = 1;    // by robot a (its agent id)
inline constexpr std::int32_t kObjectDelivered = 2;  // at its type's destination

}  // namespace swarm::collect
