// The DDS options of a participant that watches a swarm from outside it (`swarm probe`,
// `swarm view --attach`, `swarm run --view`): the swarm's domain, partition and discovery, its
// own name, and the highest participant id the profile's ports allow. Every agent of a run takes
// its agent id as participant id (its ports), so a watcher that let Fast DDS pick the first free
// id, started before the run's processes, would take an agent's ports, and the agent, binding them
// too, would receive the watcher's traffic.
inline constexpr int kObserverParticipantId = 239;
#pragma once

#include <string>

#include "swarm/comm/participant.hpp"
#include "swarm/config/scenario.hpp"

namespace swarm::tools {

// `profile` "" = config::dds_profile_path(); `discovery_server` "" = simple discovery.
inline comm::DdsOptions observer_dds(const std::string& name, int domain, const std::string& partition,
                                     const std::string& profile, const std::string& discovery_server) {
  comm::DdsOptions dds;
  dds.domain = domain;
  dds.partition = partition;
  dds.name = name;
  dds.profile_path = profile.empty() ? config::dds_profile_path() : profile;
  dds.discovery_server = discovery_server;
  dds.participant_id = kObserverParticipantId;
  return dds;
}

}  // namespace swarm::tools
