// The MessageType (bus.hpp) of each generated message type: its name and how to make its Fast DDS
// TopicDataType (fastddsgen names the pair T and TPubSubType), a sample and a copy. Endpoints are
// then written Writer<msgs::Clock> rather than with both generated names.
#pragma once

#include <memory>

#include "swarm/comm/bus.hpp"
#include "swarm_msgs.h"
#include "swarm_msgsPubSubTypes.h"

namespace swarm::comm {

template <class T>
struct PubSubTypeOf;

template <class T>
const MessageType& message_type() {
  static const MessageType type{
      PubSubTypeOf<T>::name,
      []() -> void* { return new typename PubSubTypeOf<T>::type(); },
      []() -> std::shared_ptr<void> { return std::make_shared<T>(); },
      [](const void* s) -> std::shared_ptr<void> { return std::make_shared<T>(*static_cast<const T*>(s)); }};
  return type;
}

#define SWARM_PUBSUB(T)                                  \
  template <>                                            \
  struct PubSubTypeOf<swarm::msgs::T> {                  \
    using type = swarm::msgs::T##PubSubType;             \
    static constexpr const char* name = "swarm::msgs::" #T; \
  }
SWARM_PUBSUB(Clock);
SWARM_PUBSUB(Done);
SWARM_PUBSUB(Sense);
SWARM_PUBSUB(MotionCommand);
SWARM_PUBSUB(MapPatch);
SWARM_PUBSUB(RoundStart);
SWARM_PUBSUB(Heartbeat);
SWARM_PUBSUB(PlanReport);
SWARM_PUBSUB(PlannedRoute);
SWARM_PUBSUB(AgentReport);
SWARM_PUBSUB(PhaseStart);
SWARM_PUBSUB(TaskOrder);
SWARM_PUBSUB(TaskReport);
SWARM_PUBSUB(Route);
SWARM_PUBSUB(RouteRelease);
SWARM_PUBSUB(RouteProgress);
#undef SWARM_PUBSUB

}  // namespace swarm::comm
