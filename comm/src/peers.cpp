#include "swarm/comm/peers.hpp"

#include <cstdio>
#include <sstream>

#include <fastdds/rtps/participant/ParticipantDiscoveryInfo.h>

#include "peer_listener.hpp"

namespace swarm::comm {

namespace {

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f s", s);
  return b;
}

}  // namespace

std::string describe_peers(const std::vector<PeerState>& peers, bool secure) {
  if (peers.empty()) return "no DDS participant discovered";
  std::ostringstream out;
  for (std::size_t i = 0; i < peers.size(); ++i) {
    const PeerState& p = peers[i];
    out << (i ? "; " : "") << (p.name.empty() ? "(unnamed)" : p.name) << ": ";
    switch (p.step) {
      case PeerState::Step::Discovered:
        out << "discovered at " << seconds(p.discovered_s);
        if (secure) out << ", not authenticated " << seconds(p.now_s - p.discovered_s) << " later";
        break;
      case PeerState::Step::Authenticated: out << "authenticated at " << seconds(p.step_s); break;
      case PeerState::Step::Refused:
        out << "discovered at " << seconds(p.discovered_s) << ", authentication refused at " << seconds(p.step_s);
        break;
      case PeerState::Step::Gone: out << "discovered at " << seconds(p.discovered_s) << ", gone at " << seconds(p.step_s); break;
    }
  }
  return out.str();
}

PeerListener::PeerListener(std::string self, bool verbose) : self_(std::move(self)), verbose_(verbose) {}

double PeerListener::now_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void PeerListener::print(const std::string& line) const {
  std::fprintf(stderr, "%s: DDS %s\n", self_.c_str(), line.c_str());
}

std::vector<PeerState> PeerListener::peers() const {
  const double t = now_s();
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<PeerState> out;
  for (const auto& [guid, p] : peers_) {
    out.push_back(p);
    out.back().now_s = t;
  }
  return out;
}

void PeerListener::on_participant_discovery(eprosima::fastdds::dds::DomainParticipant*,
                                            eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) {
  using Status = eprosima::fastrtps::rtps::ParticipantDiscoveryInfo;
  std::ostringstream guid;
  guid << info.info.m_guid;
  const double t = now_s();
  std::string line;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    PeerState& p = peers_[guid.str()];
    switch (info.status) {
      case Status::DISCOVERED_PARTICIPANT:
        p = PeerState{info.info.m_participantName.to_string(), PeerState::Step::Discovered, t, t};
        line = "peer " + p.name + " (" + guid.str() + ") discovered at " + seconds(t);
        break;
      case Status::REMOVED_PARTICIPANT:
      case Status::DROPPED_PARTICIPANT:
        p.step = PeerState::Step::Gone;
        p.step_s = t;
        line = "peer " + p.name + " (" + guid.str() + ") gone at " + seconds(t);
        break;
      default: return;
    }
  }
  if (verbose_) print(line);
}

void PeerListener::onParticipantAuthentication(eprosima::fastdds::dds::DomainParticipant*,
                                               eprosima::fastrtps::rtps::ParticipantAuthenticationInfo&& info) {
  using Auth = eprosima::fastrtps::rtps::ParticipantAuthenticationInfo;
  std::ostringstream guid;
  guid << info.guid;
  const double t = now_s();
  const bool ok = info.status == Auth::AUTHORIZED_PARTICIPANT;
  PeerState p;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = peers_.find(guid.str());
    if (it == peers_.end()) it = peers_.emplace(guid.str(), PeerState{"", PeerState::Step::Discovered, t, t}).first;
    it->second.step = ok ? PeerState::Step::Authenticated : PeerState::Step::Refused;
    it->second.step_s = t;
    p = it->second;
  }
  const std::string who = "peer " + (p.name.empty() ? std::string("(unnamed)") : p.name) + " (" + guid.str() + ")";
  // A refusal is always worth a line: the peer will never match, and nothing else would say why.
  if (!ok) {
    print("security: " + who + " refused at " + seconds(t) + ", " + seconds(t - p.discovered_s) +
          " after its discovery: its identity or authentication handshake failed");
  } else if (verbose_) {
    print("security: " + who + " authenticated at " + seconds(t) + ", " + seconds(t - p.discovered_s) +
          " after its discovery");
  }
}

}  // namespace swarm::comm
