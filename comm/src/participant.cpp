#include "swarm/comm/participant.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/qos/PublisherQos.hpp>
#include <fastdds/dds/subscriber/qos/SubscriberQos.hpp>

namespace swarm::comm {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;

std::string default_profile_path() {
  if (const char* p = std::getenv("SWARM_DDS_PROFILE"); p != nullptr && *p != '\0') return p;
  const char* data = std::getenv("SWARM_DATA_DIR");
  const std::string root = (data != nullptr && *data != '\0') ? data : SWARM_SOURCE_DIR;
  return root + "/deploy/fastdds_loopback.xml";
}

Participant::Participant(const DdsOptions& options) : options_(options) {
  const std::string profile = options.profile_path.empty() ? default_profile_path() : options.profile_path;
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
  participant_ = factory->create_participant(options.domain, qos);
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

Topic* Participant::create_topic(const std::string& name, TypeSupport type) {
  if (participant_->find_type(type.get_type_name()) == nullptr) {
    type.register_type(participant_);
  }
  Topic* t = participant_->create_topic(name, type.get_type_name(), TOPIC_QOS_DEFAULT);
  if (t == nullptr) throw std::runtime_error("cannot create DDS topic " + name);
  topics_[name] = t;
  return t;
}

}  // namespace swarm::comm
