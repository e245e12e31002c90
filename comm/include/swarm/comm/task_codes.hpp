// The codes of the task seam's generic messages (idl/swarm_msgs.idl TaskOrder, TaskReport), shared
// by the GCS's and the leaders' side of every task. What the other fields carry is each task's
// own contract (gcs/<task>_task.hpp).
#pragma once

#include <cstdint>

namespace swarm::comm::task {

// TaskOrder.group: an order for every group (one message instead of one per group).
inline constexpr std::uint16_t kAllGroups = 0xFFFF;

// TaskOrder.kind
inline constexpr std::uint8_t kOrderWork = 0;      // the group's work
inline constexpr std::uint8_t kOrderProgress = 1;  // other groups' route progress, relayed by the GCS
inline constexpr std::uint8_t kOrderHold = 2;      // stop handing out work; report kHeld when still
inline constexpr std::uint8_t kOrderRotate = 3;    // mapf: robots that move round a cycle, at one tick
inline constexpr std::uint8_t kOrderResume = 4;    // collect: a group's work for a leader that took it over

// TaskReport.state
inline constexpr std::uint8_t kWorking = 0;
inline constexpr std::uint8_t kDone = 1;  // the group's work is done
inline constexpr std::uint8_t kHeld = 2;  // after kOrderHold: every robot of the group stands still

// collect: what is known of an object (TaskReport and kOrderResume values: object, what, a, b).
inline constexpr std::int32_t kObjectLying = 0;      // on cell (a, b)
inline constexpr std::int32_t kObjectCarried = 1;    // by robot a (its agent id)
inline constexpr std::int32_t kObjectDelivered = 2;  // at its type's destination

}  // namespace swarm::comm::task
