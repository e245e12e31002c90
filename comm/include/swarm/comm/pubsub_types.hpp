// Maps each generated message type to its generated PubSubType (fastddsgen names them T and
// TPubSubType), so endpoints are written Writer<msgs::Clock> rather than with both names.
#pragma once

#include "swarm_msgs.h"
#include "swarm_msgsPubSubTypes.h"

namespace swarm::comm {

template <class T>
struct PubSubTypeOf;

#define SWARM_PUBSUB(T) \
  template <>           \
  struct PubSubTypeOf<swarm::msgs::T> { using type = swarm::msgs::T##PubSubType; }
SWARM_PUBSUB(Clock);
SWARM_PUBSUB(Done);
SWARM_PUBSUB(Sense);
SWARM_PUBSUB(MotionCommand);
SWARM_PUBSUB(MapPatch);
SWARM_PUBSUB(RoundStart);
SWARM_PUBSUB(Assignment);
SWARM_PUBSUB(MemberStatus);
SWARM_PUBSUB(GroupStatus);
SWARM_PUBSUB(Heartbeat);
SWARM_PUBSUB(PlanReport);
SWARM_PUBSUB(AgentReport);
#undef SWARM_PUBSUB

}  // namespace swarm::comm
