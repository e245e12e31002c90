#include "swarm/comm/traffic.hpp"

#include "swarm/comm/link.hpp"

#include <algorithm>

namespace swarm::comm {

void TrafficAccount::sent(const std::string& family, const std::string& link, std::uint64_t bytes,
                          std::size_t receivers, std::optional<std::uint32_t> queued) {
  std::lock_guard<std::mutex> lock(mutex_);
  TrafficCount& c = counts_[{family, link}];
  c.sent_messages += 1;
  c.addressed_messages += receivers;
  c.sent_bytes += bytes;
  if (queued) {
    const std::size_t bin = std::min<std::size_t>(*queued, kQueueBins - 1);
    if (c.queued_ticks.size() <= bin) c.queued_ticks.resize(bin + 1, 0);
    ++c.queued_ticks[bin];
  }
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

std::vector<std::uint64_t> TrafficAccount::sent_bytes_by_link() const {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (int c = 0; c < kLinkClasses; ++c) n.push_back(link_name(static_cast<LinkClass>(c)));
    return n;
  }();
  std::vector<std::uint64_t> bytes(kLinkClasses, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [key, c] : counts_) {
    for (int l = 0; l < kLinkClasses; ++l) {
      if (key.second == names[static_cast<std::size_t>(l)]) bytes[static_cast<std::size_t>(l)] += c.sent_bytes;
    }
  }
  return bytes;
}

}  // namespace swarm::comm
