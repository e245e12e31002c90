// An in-process Bus (bus.hpp) for unit tests of the role nodes: no DDS traffic, no threads of its
// own, every sample handed to the matching readers synchronously inside write().
//
// One FakeNetwork stands for the DDS domain; one FakeBus per agent stands for its participant.
// Endpoints match by topic name as soon as both exist. Link emulation (delay, jitter, loss) is not
// here but in the Mailbox above the bus, exactly as over real DDS.
//
//   FakeNetwork net;
//   FakeBus sim_bus(net), leader_bus(net);
//   LockstepClock clock(sim_bus, topology, links);
//   LockstepAgent leader(leader_bus, topology, links, topology.leader(0));
//   net.disconnect(leader_bus);  // as a crash or a cut cable: its writers are lost to every reader
//   net.reconnect(leader_bus);   // a healed link: samples flow again
//
// Thread-safe: writes may come from several threads (a node's loop and its liveliness thread);
// callbacks run on the writing thread, outside the network's lock.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "swarm/comm/bus.hpp"

namespace swarm::comm {

class FakeBus;

class FakeNetwork {
 public:
  FakeNetwork() = default;
  FakeNetwork(const FakeNetwork&) = delete;
  FakeNetwork& operator=(const FakeNetwork&) = delete;

  // Cuts `bus` off: every reader elsewhere that matched one of its writers gets on_writer_lost,
  // and nothing it writes or is written to it arrives until reconnect().
  void disconnect(const FakeBus& bus);
  void reconnect(const FakeBus& bus);

  std::uint64_t samples_delivered() const;

 private:
  friend class FakeBus;
  struct WriterEntry {
    WriterId id;
    int bus;
    std::string topic;
  };
  struct ReaderEntry {
    std::uint64_t key;
    int bus;
    std::string topic;
    std::shared_ptr<ReaderCallbacks> callbacks;
    const MessageType* type;
  };

  int add_bus();
  WriterId add_writer(int bus, const std::string& topic);
  void remove_writer(WriterId id);
  std::uint64_t add_reader(int bus, const std::string& topic, const MessageType* type, ReaderCallbacks cb);
  void remove_reader(std::uint64_t key);
  void deliver(WriterId from, const void* sample);
  int matched_readers(WriterId writer) const;
  int matched_writers(std::uint64_t reader) const;

  mutable std::mutex mutex_;
  int buses_ = 0;
  std::vector<bool> disconnected_;
  std::vector<WriterEntry> writers_;
  std::vector<ReaderEntry> readers_;
  std::uint64_t next_id_ = 1;
  std::uint64_t delivered_ = 0;
};

class FakeBus : public Bus {
 public:
  explicit FakeBus(FakeNetwork& network);

  std::unique_ptr<RawWriter> make_writer(const std::string& topic, const MessageType& type,
                                         EndpointKind kind) override;
  std::unique_ptr<RawReader> make_reader(const std::string& topic, const MessageType& type, EndpointKind kind,
                                         ReaderCallbacks callbacks) override;

  int id() const { return id_; }
  FakeNetwork& network() { return network_; }

 private:
  FakeNetwork& network_;
  int id_;
};

}  // namespace swarm::comm
