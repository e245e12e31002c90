// One DDS participant per process, with the run's isolation applied: its own domain id and a
// partition unique to the run, so parallel runs on one machine never see each other's samples.
// QoS comes from the XML profile (deploy/fastdds_loopback.xml by default), not from code.
//
//   Participant p({.domain = 7, .partition = "swarm-123", .name = "gcs"});
//   Writer<msgs::Clock> w(p, "clock");
//   Reader<msgs::Done> r(p, "done", [](msgs::Done&& d) { ... });
//
// Construction throws std::runtime_error when a DDS entity cannot be created (a process edge).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

namespace swarm::comm {

struct DdsOptions {
  int domain = 0;
  std::string partition = "swarm";
  std::string name = "swarm";
  // Fast DDS XML profile file; empty = $SWARM_DDS_PROFILE, else DATA/deploy/fastdds_loopback.xml.
  std::string profile_path;
};

// The profile file a process uses when none is given (see DdsOptions::profile_path).
std::string default_profile_path();

class Participant {
 public:
  explicit Participant(const DdsOptions& options);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  // The topic `name` of type T's PubSubType, created on first use.
  template <class PubSubT>
  eprosima::fastdds::dds::Topic* topic(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = topics_.find(name);
    if (it != topics_.end()) return it->second;
    eprosima::fastdds::dds::TypeSupport type(new PubSubT());
    return create_topic(name, type);
  }

  eprosima::fastdds::dds::Publisher* publisher() { return publisher_; }
  eprosima::fastdds::dds::Subscriber* subscriber() { return subscriber_; }
  const DdsOptions& options() const { return options_; }

 private:
  eprosima::fastdds::dds::Topic* create_topic(const std::string& name,
                                              eprosima::fastdds::dds::TypeSupport type);

  DdsOptions options_;
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
  std::map<std::string, eprosima::fastdds::dds::Topic*> topics_;
  std::mutex mutex_;
};

}  // namespace swarm::comm
