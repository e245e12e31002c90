// The participant listener behind Participant::peers(): it records each remote participant's
// discovery and authentication (peers.hpp), prints a refused authentication at once, and, with
// `verbose` (SWARM_DDS_LOG=security), prints every such event with its time.
#pragma once

#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <fastdds/dds/domain/DomainParticipantListener.hpp>

#include "swarm/comm/peers.hpp"

namespace swarm::comm {

class PeerListener : public eprosima::fastdds::dds::DomainParticipantListener {
 public:
  // `self`: this process's name, which starts every line it prints.
  PeerListener(std::string self, bool verbose);

  std::vector<PeerState> peers() const;

  void on_participant_discovery(eprosima::fastdds::dds::DomainParticipant* participant,
                                eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override;
  void onParticipantAuthentication(eprosima::fastdds::dds::DomainParticipant* participant,
                                   eprosima::fastrtps::rtps::ParticipantAuthenticationInfo&& info) override;

 private:
  double now_s() const;
  void print(const std::string& line) const;

  const std::string self_;
  const bool verbose_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  mutable std::mutex mutex_;
  // By GUID (its text form): the peer's name arrives with its discovery, its authentication by GUID only.
  std::map<std::string, PeerState> peers_;
};

}  // namespace swarm::comm
