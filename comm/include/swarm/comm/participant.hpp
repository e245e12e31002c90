// The Fast DDS implementation of the Bus (bus.hpp): one DDS participant per process, with the run's
// isolation applied: its own domain id and a partition unique to the run, so parallel runs on one
// machine never see each other's samples. QoS comes from the XML profile (roles pass
// deploy/fastdds_loopback.xml by default, config::dds_profile_path()), not from code.
//
//   Participant p({.domain = 7, .partition = "swarm-123", .name = "gcs", .profile_path = profile});
//   Writer<msgs::Clock> w(p, "clock");
//   Reader<msgs::Done> r(p, "done", [](msgs::Done&& d) { ... });
//
// Construction throws std::runtime_error when a DDS entity cannot be created (a process edge).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "swarm/comm/bus.hpp"

namespace eprosima::fastdds::dds {
class DomainParticipant;
class Publisher;
class Subscriber;
class Topic;
}  // namespace eprosima::fastdds::dds

namespace swarm::comm {

class PeerListener;

struct DdsOptions {
  int domain = 0;
  std::string partition = "swarm";
  std::string name = "swarm";
  // The Fast DDS XML profile file (required; roles take config::dds_profile_path(): $SWARM_DDS_PROFILE,
  // else DATA/deploy/fastdds_loopback.xml).
  std::string profile_path;
  // "HOST:PORT" of a Fast DDS Discovery Server (fast-discovery-server, id 0): the participant is
  // its CLIENT instead of finding its peers by simple discovery. Empty = $SWARM_DISCOVERY_SERVER,
  // else simple discovery. Why: simple discovery announces every participant to every other, so its
  // traffic grows with the square of the process count; a server tells each client only about the
  // participants it shares a topic with.
  std::string discovery_server;
  // The RTPS participant id, which fixes the participant's ports (see the profile); -1 = Fast
  // DDS picks a free one (fine for a few participants; roles use their agent id).
  int participant_id = -1;
  // DDS-Security: a folder made by scripts/make-certs.sh. Set, the participant authenticates
  // with the certificate `identity` (IDENTITY.pem and .key there; default: `name`), checks the
  // signed governance and permissions, and encrypts as the governance says (PKI-DH,
  // Access-Permissions, AES-GCM-GMAC). Empty = no security.
  std::string security_dir;
  std::string identity;
  // Prints every peer's discovery and authentication as it happens (peers.hpp), and turns on Fast
  // DDS's warnings and, with security, its security log (DDS_LogTopic, to stderr): to find why a
  // secure start-up stalls. Roles set it from $SWARM_DDS_LOG=security.
  bool log_security = false;
};

// The discovery server a process uses when none is given (see DdsOptions::discovery_server).
std::string default_discovery_server();

class Participant : public Bus {
 public:
  explicit Participant(const DdsOptions& options);
  ~Participant() override;
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  std::unique_ptr<RawWriter> make_writer(const std::string& topic, const MessageType& type,
                                         EndpointKind kind) override;
  std::unique_ptr<RawReader> make_reader(const std::string& topic, const MessageType& type, EndpointKind kind,
                                         ReaderCallbacks callbacks) override;

  std::vector<PeerState> peers() const override;
  bool secure() const override { return !options_.security_dir.empty(); }

  const DdsOptions& options() const { return options_; }

 private:
  eprosima::fastdds::dds::Topic* topic(const std::string& name, const MessageType& type);

  DdsOptions options_;
  // Outlives participant_, which calls it (destroyed after it, in ~Participant's body).
  std::unique_ptr<PeerListener> listener_;
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
  std::map<std::string, eprosima::fastdds::dds::Topic*> topics_;
  std::mutex mutex_;
};

}  // namespace swarm::comm
