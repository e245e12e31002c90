// Typed DDS endpoints over the generated swarm::msgs types.
//
// Writer<T>::write serialises and sends one sample; Reader<T> hands every received sample to a
// callback on the DDS receive thread. Callbacks only translate and enqueue (STYLE.md 7): the
// agent's loop does the work.
#pragma once

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include "swarm/comm/participant.hpp"
#include "swarm/comm/pubsub_types.hpp"

namespace swarm::comm {

// Bytes a sample occupies on the wire: CDR payload plus the 4-byte encapsulation header.
template <class T>
std::size_t wire_size(const T& sample) {
  return T::getCdrSerializedSize(sample) + 4;
}

template <class T>
class Writer {
 public:
  Writer(Participant& p, const std::string& topic_name, const std::string& profile = "swarm_writer")
      : participant_(p) {
    auto* t = p.topic<typename PubSubTypeOf<T>::type>(topic_name);
    writer_ = p.publisher()->create_datawriter_with_profile(t, profile);
    if (writer_ == nullptr) throw std::runtime_error("cannot create a DDS writer for topic " + topic_name);
  }
  ~Writer() { participant_.publisher()->delete_datawriter(writer_); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void write(T& sample) {
    if (!writer_->write(&sample)) throw std::runtime_error("DDS write failed on " + writer_->get_topic()->get_name());
  }
  int matched() const {
    eprosima::fastdds::dds::PublicationMatchedStatus status;
    writer_->get_publication_matched_status(status);
    return status.current_count;
  }
  // Tells the readers this writer is alive (for MANUAL_BY_TOPIC liveliness; a write does too).
  void assert_liveliness() { writer_->assert_liveliness(); }
  // Blocks until every matched reader acknowledged everything written, or the timeout passes.
  bool wait_acknowledged(std::chrono::milliseconds timeout) {
    eprosima::fastrtps::Duration_t d(static_cast<double>(timeout.count()) / 1000.0);
    return writer_->wait_for_acknowledgments(d) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK;
  }

 private:
  Participant& participant_;
  eprosima::fastdds::dds::DataWriter* writer_ = nullptr;
};

template <class T>
class Reader : private eprosima::fastdds::dds::DataReaderListener {
 public:
  using Callback = std::function<void(T&&)>;
  Reader(Participant& p, const std::string& topic_name, Callback callback)
      : participant_(p), callback_(std::move(callback)) {
    auto* t = p.topic<typename PubSubTypeOf<T>::type>(topic_name);
    reader_ = p.subscriber()->create_datareader_with_profile(
        t, "swarm_reader", this, eprosima::fastdds::dds::StatusMask::data_available());
    if (reader_ == nullptr) throw std::runtime_error("cannot create a DDS reader for topic " + topic_name);
  }
  ~Reader() {
    reader_->set_listener(nullptr);
    participant_.subscriber()->delete_datareader(reader_);
  }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // Writers this reader has matched (its side of discovery).
  int matched() const {
    eprosima::fastdds::dds::SubscriptionMatchedStatus status;
    reader_->get_subscription_matched_status(status);
    return status.current_count;
  }

 private:
  void on_data_available(eprosima::fastdds::dds::DataReader* reader) override {
    T sample;
    eprosima::fastdds::dds::SampleInfo info;
    while (reader->take_next_sample(&sample, &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
      if (info.valid_data) callback_(std::move(sample));
    }
  }

  Participant& participant_;
  Callback callback_;
  eprosima::fastdds::dds::DataReader* reader_ = nullptr;
};

}  // namespace swarm::comm
