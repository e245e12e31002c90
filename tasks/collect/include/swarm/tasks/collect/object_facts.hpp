// What the collect GCS knows of each object (CollectGcsTask's known_): `what` one of these, with
// its (a, b).
#pragma once

#include <cstdint>

namespace swarm::collect {

inline constexpr std::int32_t kObjectLying = 0;      // on cell (a, b)
inline constexpr std::int32_t kObjectCarried = 1;    // by robot a (its agent id)
inline constexpr std::int32_t kObjectDelivered = 2;  // at its type's destination

}  // namespace swarm::collect
