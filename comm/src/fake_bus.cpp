#include "swarm/comm/fake_bus.hpp"

#include <algorithm>
#include <utility>

namespace swarm::comm {

namespace {

class FakeWriter : public RawWriter {
 public:
  FakeWriter(WriterId id, std::function<void(WriterId, const void*)> deliver, std::function<int(WriterId)> matched,
             std::function<void(WriterId)> remove)
      : id_(id), deliver_(std::move(deliver)), matched_(std::move(matched)), remove_(std::move(remove)) {}
  ~FakeWriter() override { remove_(id_); }
  void write(const void* sample) override { deliver_(id_, sample); }
  int matched() const override { return matched_(id_); }
  void assert_liveliness() override {}
  bool wait_acknowledged(std::chrono::milliseconds) override { return true; }

 private:
  WriterId id_;
  std::function<void(WriterId, const void*)> deliver_;
  std::function<int(WriterId)> matched_;
  std::function<void(WriterId)> remove_;
};

class FakeReader : public RawReader {
 public:
  FakeReader(std::uint64_t key, std::function<int(std::uint64_t)> matched, std::function<void(std::uint64_t)> remove)
      : key_(key), matched_(std::move(matched)), remove_(std::move(remove)) {}
  ~FakeReader() override { remove_(key_); }
  int matched() const override { return matched_(key_); }

 private:
  std::uint64_t key_;
  std::function<int(std::uint64_t)> matched_;
  std::function<void(std::uint64_t)> remove_;
};

}  // namespace

int FakeNetwork::add_bus() {
  std::lock_guard<std::mutex> lock(mutex_);
  disconnected_.push_back(false);
  return buses_++;
}

WriterId FakeNetwork::add_writer(int bus, const std::string& topic) {
  std::lock_guard<std::mutex> lock(mutex_);
  const WriterId id = next_id_++;
  writers_.push_back({id, bus, topic});
  return id;
}

void FakeNetwork::remove_writer(WriterId id) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::erase_if(writers_, [&](const WriterEntry& w) { return w.id == id; });
}

std::uint64_t FakeNetwork::add_reader(int bus, const std::string& topic, const MessageType* type, ReaderCallbacks cb) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::uint64_t key = next_id_++;
  readers_.push_back({key, bus, topic, std::make_shared<ReaderCallbacks>(std::move(cb)), type});
  return key;
}

void FakeNetwork::remove_reader(std::uint64_t key) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::erase_if(readers_, [&](const ReaderEntry& r) { return r.key == key; });
}

void FakeNetwork::deliver(WriterId from, const void* sample) {
  std::vector<std::pair<std::shared_ptr<ReaderCallbacks>, const MessageType*>> to;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto w = std::find_if(writers_.begin(), writers_.end(), [&](const WriterEntry& e) { return e.id == from; });
    if (w == writers_.end() || disconnected_[w->bus]) return;
    for (const ReaderEntry& r : readers_) {
      if (r.topic == w->topic && !disconnected_[r.bus]) to.emplace_back(r.callbacks, r.type);
    }
    delivered_ += to.size();
  }
  // Each reader gets its own copy, as each DDS reader deserialises its own sample.
  for (auto& [cb, type] : to) {
    std::shared_ptr<void> copy = type->copy(sample);
    cb->on_sample(copy.get(), from);
  }
}

int FakeNetwork::matched_readers(WriterId writer) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto w = std::find_if(writers_.begin(), writers_.end(), [&](const WriterEntry& e) { return e.id == writer; });
  if (w == writers_.end() || disconnected_[w->bus]) return 0;
  return static_cast<int>(std::count_if(readers_.begin(), readers_.end(), [&](const ReaderEntry& r) {
    return r.topic == w->topic && !disconnected_[r.bus];
  }));
}

int FakeNetwork::matched_writers(std::uint64_t reader) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto r = std::find_if(readers_.begin(), readers_.end(), [&](const ReaderEntry& e) { return e.key == reader; });
  if (r == readers_.end() || disconnected_[r->bus]) return 0;
  return static_cast<int>(std::count_if(writers_.begin(), writers_.end(), [&](const WriterEntry& w) {
    return w.topic == r->topic && !disconnected_[w.bus];
  }));
}

void FakeNetwork::disconnect(const FakeBus& bus) {
  std::vector<std::pair<std::shared_ptr<ReaderCallbacks>, WriterId>> lost;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (disconnected_[bus.id()]) return;
    disconnected_[bus.id()] = true;
    for (const WriterEntry& w : writers_) {
      if (w.bus != bus.id()) continue;
      for (const ReaderEntry& r : readers_) {
        if (r.topic == w.topic && r.bus != bus.id() && !disconnected_[r.bus] && r.callbacks->on_writer_lost) {
          lost.emplace_back(r.callbacks, w.id);
        }
      }
    }
  }
  for (auto& [cb, id] : lost) cb->on_writer_lost(id);
}

void FakeNetwork::reconnect(const FakeBus& bus) {
  std::lock_guard<std::mutex> lock(mutex_);
  disconnected_[bus.id()] = false;
}

std::uint64_t FakeNetwork::samples_delivered() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return delivered_;
}

FakeBus::FakeBus(FakeNetwork& network) : network_(network), id_(network.add_bus()) {}

std::unique_ptr<RawWriter> FakeBus::make_writer(const std::string& topic, const MessageType&, EndpointKind) {
  FakeNetwork& net = network_;
  const WriterId id = net.add_writer(id_, topic);
  return std::make_unique<FakeWriter>(
      id, [&net](WriterId w, const void* s) { net.deliver(w, s); },
      [&net](WriterId w) { return net.matched_readers(w); }, [&net](WriterId w) { net.remove_writer(w); });
}

std::unique_ptr<RawReader> FakeBus::make_reader(const std::string& topic, const MessageType& type, EndpointKind,
                                                ReaderCallbacks callbacks) {
  FakeNetwork& net = network_;
  const std::uint64_t key = net.add_reader(id_, topic, &type, std::move(callbacks));
  return std::make_unique<FakeReader>(
      key, [&net](std::uint64_t r) { return net.matched_writers(r); }, [&net](std::uint64_t r) { net.remove_reader(r); });
}

}  // namespace swarm::comm
