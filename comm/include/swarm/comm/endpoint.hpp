// Typed endpoints over a Bus (bus.hpp), for the generated swarm::msgs types.
//
// Writer<T>::write sends one sample; Reader<T> hands every received sample to a callback on
// whatever thread the bus delivers on. Callbacks only translate and enqueue (docs/style.md 7): the
// agent's loop does the work.
//
//   Writer<msgs::Clock> w(bus, "clock");
//   Reader<msgs::Clock> r(bus, "clock", [](msgs::Clock&& c) { queue.push(std::move(c)); });
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "swarm/comm/bus.hpp"
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
  Writer(Bus& bus, const std::string& topic_name, EndpointKind kind = EndpointKind::Data)
      : raw_(bus.make_writer(topic_name, message_type<T>(), kind)) {}

  void write(const T& sample) { raw_->write(&sample); }
  int matched() const { return raw_->matched(); }
  void assert_liveliness() { raw_->assert_liveliness(); }
  bool wait_acknowledged(std::chrono::milliseconds timeout) { return raw_->wait_acknowledged(timeout); }

 private:
  std::unique_ptr<RawWriter> raw_;
};

template <class T>
class Reader {
 public:
  using Callback = std::function<void(T&&)>;
  using CallbackFrom = std::function<void(T&&, WriterId)>;

  Reader(Bus& bus, const std::string& topic_name, Callback callback, EndpointKind kind = EndpointKind::Data)
      : Reader(bus, topic_name, [cb = std::move(callback)](T&& s, WriterId) { cb(std::move(s)); }, {}, kind) {}
  Reader(Bus& bus, const std::string& topic_name, CallbackFrom callback, std::function<void(WriterId)> on_writer_lost,
         EndpointKind kind) {
    ReaderCallbacks cb;
    cb.on_sample = [callback = std::move(callback)](void* sample, WriterId from) {
      callback(std::move(*static_cast<T*>(sample)), from);
    };
    cb.on_writer_lost = std::move(on_writer_lost);
    raw_ = bus.make_reader(topic_name, message_type<T>(), kind, std::move(cb));
  }

  // Writers this reader has matched (its side of discovery).
  int matched() const { return raw_->matched(); }

 private:
  std::unique_ptr<RawReader> raw_;
};

}  // namespace swarm::comm
