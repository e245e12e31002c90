// The DDS options of a participant that watches a swarm from outside it (`swarm probe`,
// `swarm view --attach`, `swarm run --view`): the swarm's domain, partition and discovery, its
// own name, and ports Fast DDS picks (it is no agent of the run).
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
  dds.participant_id = -1;
  return dds;
}

}  // namespace swarm::tools
