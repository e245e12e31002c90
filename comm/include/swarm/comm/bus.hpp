// The publish/subscribe interface every role reaches DDS through, with two implementations:
//   - Participant (participant.hpp): real eProsima Fast DDS, one per process;
//   - FakeBus (fake_bus.hpp): in-process and synchronous, for unit tests of the role nodes that run
//     in milliseconds without any DDS traffic.
// Everything above it (the lockstep protocol, link emulation with its delay and loss model,
// traffic accounting) is the same code on both, so a node tested on the fake behaves as it does
// over DDS.
//
// The interface is type-erased (samples travel as void* to a generated msgs type); the typed
// front end is endpoint.hpp's Writer<T> / Reader<T>:
//
//   Writer<msgs::Clock> w(bus, "clock");
//   Reader<msgs::Done> r(bus, "done", [](msgs::Done&& d, WriterId from) { ... },
//                        [](WriterId lost) { ... }, EndpointKind::Heartbeat);
//
// Contract for implementations:
//   - a reader's on_sample runs on any thread (DDS: its receive thread; fake: the writer's
//     thread, synchronously inside write()) and must only translate and enqueue (docs/style.md 7);
//   - on_writer_lost(w) runs when writer w stops being alive to this reader: its liveliness lease
//     ran out (EndpointKind::Heartbeat) or it was unmatched (its participant left or was cut off);
//   - matched() counts the endpoints on the other side that this endpoint currently sees.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "swarm/comm/peers.hpp"

namespace swarm::comm {

// Identifies one writer as its readers see it (DDS: its publication handle, hashed).
using WriterId = std::uint64_t;

// Which QoS profile an endpoint uses (deploy/fastdds_*.xml):
//   Data      - reliable, keep-all, volatile (swarm_writer / swarm_reader);
//   Heartbeat - as Data, plus a 1 s MANUAL_BY_TOPIC liveliness lease (swarm_heartbeat_*): the
//               lockstep Done messages, whose writer going quiet means the agent is lost.
// Watch: a reader outside the run (swarm view), best effort, so that the run's reliable writers
// neither resend to it nor wait for its acknowledgements; it may miss a sample.
enum class EndpointKind : std::uint8_t { Data, Heartbeat, Watch };

// What a bus needs to know about a message type, without naming it (pubsub_types.hpp makes one
// per generated type).
struct MessageType {
  const char* name;
  void* (*new_dds_type)();                      // a new Fast DDS TopicDataType (owned by the caller)
  std::shared_ptr<void> (*new_sample)();        // a default-constructed sample
  std::shared_ptr<void> (*copy)(const void*);   // a copy of a sample
};

class RawWriter {
 public:
  virtual ~RawWriter() = default;
  // Sends one sample (a pointer to the writer's message type). Throws std::runtime_error if the
  // bus refuses it.
  virtual void write(const void* sample) = 0;
  virtual int matched() const = 0;
  // Tells the readers this writer is alive (Heartbeat endpoints; a write does too).
  virtual void assert_liveliness() = 0;
  // Blocks until every matched reader acknowledged everything written, or the timeout passes.
  virtual bool wait_acknowledged(std::chrono::milliseconds timeout) = 0;
};

class RawReader {
 public:
  virtual ~RawReader() = default;
  virtual int matched() const = 0;
};

struct ReaderCallbacks {
  // `sample` points to a sample of the reader's type that the callee may move from.
  std::function<void(void* sample, WriterId from)> on_sample;
  std::function<void(WriterId lost)> on_writer_lost;  // optional
};

class Bus {
 public:
  virtual ~Bus() = default;
  virtual std::unique_ptr<RawWriter> make_writer(const std::string& topic, const MessageType& type,
                                                 EndpointKind kind) = 0;
  virtual std::unique_ptr<RawReader> make_reader(const std::string& topic, const MessageType& type,
                                                 EndpointKind kind, ReaderCallbacks callbacks) = 0;
  // The other participants this bus has seen and how far each got (peers.hpp): for the message of
  // a start-up that stalls. A bus without DDS discovery (the fake) has none.
  virtual std::vector<PeerState> peers() const { return {}; }
  // Whether peers must authenticate (DDS-Security) before any endpoint matches.
  virtual bool secure() const { return false; }
};

}  // namespace swarm::comm
