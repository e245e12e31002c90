#include "swarm/comm/participant.hpp"

#include <netdb.h>
#include <sys/socket.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <regex>
#include <stdexcept>
#include <vector>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/PublisherQos.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/SubscriberQos.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastdds/rtps/attributes/ServerAttributes.h>
#include <fastdds/dds/log/Log.hpp>

#include "peer_listener.hpp"

namespace swarm::comm {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;

std::string default_discovery_server() {
  const char* s = std::getenv("SWARM_DISCOVERY_SERVER");
  return s != nullptr ? s : "";
}

namespace {

// Makes `qos` a client of the discovery server at "HOST:PORT" (server id 0, the GUID prefix that
// fast-discovery-server -i 0 uses). Everything else (transports, leases) stays as the profile says.
void use_discovery_server(DomainParticipantQos& qos, const std::string& server) {
  eprosima::fastdds::rtps::RemoteServerList_t servers;
  if (!eprosima::fastdds::rtps::load_environment_server_info(server, servers) || servers.empty()) {
    // Fast DDS resolves a host name itself; a well-formed HOST:PORT it refuses has a host that
    // does not resolve (e.g. a container started before the discovery service exists).
    const auto colon = server.rfind(':');
    const std::string host = colon == std::string::npos ? server : server.substr(0, colon);
    addrinfo hints{};
    hints.ai_family = AF_INET;
    addrinfo* found = nullptr;
    const bool well_formed = colon != std::string::npos && colon > 0 && colon + 1 < server.size() &&
                             server.find_first_not_of("0123456789", colon + 1) == std::string::npos;
    if (well_formed && ::getaddrinfo(host.c_str(), nullptr, &hints, &found) != 0) {
      throw std::runtime_error("discovery server '" + server + "': cannot resolve the host name '" + host + "'");
    }
    if (found != nullptr) ::freeaddrinfo(found);
    throw std::runtime_error("bad discovery server address '" + server + "' (expected HOST:PORT, e.g. 127.0.0.1:11811)");
  }
  auto& discovery = qos.wire_protocol().builtin.discovery_config;
  discovery.discoveryProtocol = eprosima::fastrtps::rtps::DiscoveryProtocol_t::CLIENT;
  discovery.m_DiscoveryServers = servers;
  qos.wire_protocol().builtin.initialPeersList.clear();
}

// The DDS-Security plugins' properties for `identity`'s files in `dir` (make-certs.sh's layout).
void use_security(DomainParticipantQos& qos, const std::string& dir, const std::string& identity) {
  const std::filesystem::path d = std::filesystem::absolute(dir);
  for (const std::string& f : std::vector<std::string>{"ca.pem", identity + ".pem", identity + ".key", "governance.p7s", "permissions.p7s"}) {
    if (!std::filesystem::exists(d / f)) {
      throw std::runtime_error("security folder " + d.string() + " has no " + f +
                               " (make it with scripts/make-certs.sh " + d.string() + " " + identity + " ...)");
    }
  }
  const auto file = [&](const std::string& f) { return "file://" + (d / f).string(); };
  auto& p = qos.properties().properties();
  p.emplace_back("dds.sec.auth.plugin", "builtin.PKI-DH");
  p.emplace_back("dds.sec.auth.builtin.PKI-DH.identity_ca", file("ca.pem"));
  p.emplace_back("dds.sec.auth.builtin.PKI-DH.identity_certificate", file(identity + ".pem"));
  p.emplace_back("dds.sec.auth.builtin.PKI-DH.private_key", file(identity + ".key"));
  p.emplace_back("dds.sec.access.plugin", "builtin.Access-Permissions");
  p.emplace_back("dds.sec.access.builtin.Access-Permissions.permissions_ca", file("ca.pem"));
  p.emplace_back("dds.sec.access.builtin.Access-Permissions.governance", file("governance.p7s"));
  p.emplace_back("dds.sec.access.builtin.Access-Permissions.permissions", file("permissions.p7s"));
  p.emplace_back("dds.sec.crypto.plugin", "builtin.AES-GCM-GMAC");
}

// Fast DDS's own security log (the DDS_LogTopic plugin: failed validations, bad tokens, ...) to
// this process's stderr, where its other lines go. Fast DDS 2.9's Debian build has no info-level
// log, so the handshake's progress comes from PeerListener instead.
void use_security_log(DomainParticipantQos& qos) {
  auto& p = qos.properties().properties();
  p.emplace_back("dds.sec.log.plugin", "builtin.DDS_LogTopic");
  p.emplace_back("dds.sec.log.builtin.DDS_LogTopic.logging_level", "DEBUG_LEVEL");
  p.emplace_back("dds.sec.log.builtin.DDS_LogTopic.log_file", "/dev/stderr");
  p.emplace_back("dds.sec.log.builtin.DDS_LogTopic.distribute", "false");
}

const char* writer_profile(EndpointKind kind) {
  return kind == EndpointKind::Heartbeat ? "swarm_heartbeat_writer" : "swarm_writer";
}
const char* reader_profile(EndpointKind kind) {
  if (kind == EndpointKind::Watch) return "swarm_watch_reader";
  return kind == EndpointKind::Heartbeat ? "swarm_heartbeat_reader" : "swarm_reader";
}

// A publication handle as the bus's WriterId: the 16-byte GUID folded into 64 bits (the GUID
// prefix differs per participant, the entity id per writer; collisions are astronomically rare).
WriterId writer_id(const InstanceHandle_t& h) {
  std::uint64_t a = 0, b = 0;
  for (int i = 0; i < 8; ++i) a = (a << 8) | h.value[i];
  for (int i = 8; i < 16; ++i) b = (b << 8) | h.value[i];
  return a ^ (b * 0x9e3779b97f4a7c15ULL);
}

class DdsWriter : public RawWriter {
 public:
  DdsWriter(Publisher* publisher, Topic* topic, EndpointKind kind) : publisher_(publisher) {
    writer_ = publisher->create_datawriter_with_profile(topic, writer_profile(kind));
    if (writer_ == nullptr) throw std::runtime_error("cannot create a DDS writer for topic " + topic->get_name());
  }
  ~DdsWriter() override { publisher_->delete_datawriter(writer_); }

  void write(const void* sample) override {
    if (!writer_->write(const_cast<void*>(sample))) {
      throw std::runtime_error("DDS write failed on " + writer_->get_topic()->get_name());
    }
  }
  int matched() const override {
    PublicationMatchedStatus status;
    writer_->get_publication_matched_status(status);
    return status.current_count;
  }
  void assert_liveliness() override { writer_->assert_liveliness(); }
  bool wait_acknowledged(std::chrono::milliseconds timeout) override {
    eprosima::fastrtps::Duration_t d(static_cast<double>(timeout.count()) / 1000.0);
    return writer_->wait_for_acknowledgments(d) == ReturnCode_t::RETCODE_OK;
  }

 private:
  Publisher* publisher_;
  DataWriter* writer_ = nullptr;
};

class DdsReader : public RawReader, private DataReaderListener {
 public:
  DdsReader(Subscriber* subscriber, Topic* topic, const MessageType& type, EndpointKind kind, ReaderCallbacks cb)
      : subscriber_(subscriber), type_(type), cb_(std::move(cb)) {
    StatusMask mask = StatusMask::data_available();
    if (cb_.on_writer_lost) mask << StatusMask::liveliness_changed() << StatusMask::subscription_matched();
    reader_ = subscriber->create_datareader_with_profile(topic, reader_profile(kind), this, mask);
    if (reader_ == nullptr) throw std::runtime_error("cannot create a DDS reader for topic " + topic->get_name());
  }
  ~DdsReader() override {
    reader_->set_listener(nullptr);
    subscriber_->delete_datareader(reader_);
  }
  int matched() const override {
    SubscriptionMatchedStatus status;
    reader_->get_subscription_matched_status(status);
    return status.current_count;
  }

 private:
  void on_data_available(DataReader* reader) override {
    SampleInfo info;
    for (;;) {
      std::shared_ptr<void> sample = type_.new_sample();
      if (reader->take_next_sample(sample.get(), &info) != ReturnCode_t::RETCODE_OK) break;
      if (info.valid_data) cb_.on_sample(sample.get(), writer_id(info.publication_handle));
    }
  }
  void on_liveliness_changed(DataReader*, const LivelinessChangedStatus& status) override {
    if (status.not_alive_count_change > 0) cb_.on_writer_lost(writer_id(status.last_publication_handle));
  }
  // A crashed process's writer disappears when its participant's lease runs out.
  void on_subscription_matched(DataReader*, const SubscriptionMatchedStatus& status) override {
    if (status.current_count_change < 0) cb_.on_writer_lost(writer_id(status.last_publication_handle));
  }

  Subscriber* subscriber_;
  const MessageType& type_;
  ReaderCallbacks cb_;
  DataReader* reader_ = nullptr;
};

}  // namespace

Participant::Participant(const DdsOptions& options) : options_(options) {
  const std::string& profile = options.profile_path;
  if (profile.empty()) throw std::runtime_error("no Fast DDS profile given (DdsOptions::profile_path)");
  if (!std::filesystem::exists(profile)) {
    throw std::runtime_error("Fast DDS profile " + profile + " does not exist (set --profile or SWARM_DDS_PROFILE)");
  }
  auto* factory = DomainParticipantFactory::get_instance();
  if (factory->load_XML_profiles_file(profile) != ReturnCode_t::RETCODE_OK) {
    throw std::runtime_error("Fast DDS could not load the XML profile " + profile);
  }
  DomainParticipantQos qos;
  if (factory->get_participant_qos_from_profile("swarm_participant", qos) != ReturnCode_t::RETCODE_OK) {
    throw std::runtime_error("profile " + profile + " has no participant profile named swarm_participant");
  }
  qos.name(options.name);
  if (options.participant_id >= 0) qos.wire_protocol().participant_id = options.participant_id;
  if (!options.security_dir.empty()) {
    use_security(qos, options.security_dir, options.identity.empty() ? options.name : options.identity);
    if (options.log_security) use_security_log(qos);
  }
  if (options.log_security) {
    // Participant discovery and authentication only; info where Fast DDS was built with it
    // (Debian's 2.9 is not). Not the crypto plugin's "No key material yet": a warning per sample
    // sent before a peer's keys arrived (~8,000 lines per role and run), which drowns the rest and
    // slows the very start-up it is meant to show.
    Log::SetVerbosity(Log::Kind::Info);
    Log::SetCategoryFilter(std::regex("^(SECURITY(?!_CRYPTO).*|RTPS_PDP.*)$"));
  }
  const std::string server = options.discovery_server.empty() ? default_discovery_server() : options.discovery_server;
  if (!server.empty()) use_discovery_server(qos, server);
  listener_ = std::make_unique<PeerListener>(options.name, options.log_security);
  participant_ = factory->create_participant(options.domain, qos, listener_.get(), StatusMask::none());
  if (participant_ == nullptr) {
    throw std::runtime_error("cannot create a DDS participant in domain " + std::to_string(options.domain));
  }
  // The partition keeps this run's samples away from any other run sharing the domain.
  PublisherQos pub_qos = PUBLISHER_QOS_DEFAULT;
  pub_qos.partition().push_back(options.partition.c_str());
  publisher_ = participant_->create_publisher(pub_qos);
  SubscriberQos sub_qos = SUBSCRIBER_QOS_DEFAULT;
  sub_qos.partition().push_back(options.partition.c_str());
  subscriber_ = participant_->create_subscriber(sub_qos);
  if (publisher_ == nullptr || subscriber_ == nullptr) {
    throw std::runtime_error("cannot create the DDS publisher/subscriber");
  }
}

Participant::~Participant() {
  if (participant_ == nullptr) return;
  participant_->delete_contained_entities();
  DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

std::vector<PeerState> Participant::peers() const { return listener_->peers(); }

Topic* Participant::topic(const std::string& name, const MessageType& type) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = topics_.find(name);
  if (it != topics_.end()) return it->second;
  TypeSupport support(static_cast<TopicDataType*>(type.new_dds_type()));
  if (participant_->find_type(support.get_type_name()) == nullptr) support.register_type(participant_);
  Topic* t = participant_->create_topic(name, support.get_type_name(), TOPIC_QOS_DEFAULT);
  if (t == nullptr) throw std::runtime_error("cannot create DDS topic " + name);
  topics_[name] = t;
  return t;
}

std::unique_ptr<RawWriter> Participant::make_writer(const std::string& name, const MessageType& type,
                                                    EndpointKind kind) {
  return std::make_unique<DdsWriter>(publisher_, topic(name, type), kind);
}

std::unique_ptr<RawReader> Participant::make_reader(const std::string& name, const MessageType& type,
                                                    EndpointKind kind, ReaderCallbacks callbacks) {
  return std::make_unique<DdsReader>(subscriber_, topic(name, type), type, kind, std::move(callbacks));
}

}  // namespace swarm::comm
