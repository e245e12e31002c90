#include "swarm/comm/traffic.hpp"

namespace swarm::comm {

void TrafficAccount::sent(const std::string& family, const std::string& link, std::uint64_t bytes,
                          std::size_t receivers) {
  std::lock_guard<std::mutex> lock(mutex_);
  TrafficCount& c = counts_[{family, link}];
  c.sent_messages += 1;
  c.addressed_messages += receivers;
  c.sent_bytes += bytes;
}

void TrafficAccount::received(const std::string& family, const std::string& link, std::uint64_t bytes,
                              std::uint32_t lost, bool dropped) {
  std::lock_guard<std::mutex> lock(mutex_);
  TrafficCount& c = counts_[{family, link}];
  if (!dropped) c.received_messages += 1;
  c.received_bytes += bytes * (dropped ? 1 : 1 + lost);
  c.lost_transmissions += lost;
  if (dropped) c.dropped_messages += 1;
}

std::map<TrafficAccount::Key, TrafficCount> TrafficAccount::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counts_;
}

}  // namespace swarm::comm
