// Traffic accounting: messages and bytes per topic family and link class, as each agent saw them.
// Bytes are the CDR-serialised payload size plus the 4-byte encapsulation header (what DDS puts in
// the RTPS DATA submessage), so a bandwidth experiment needs no packet capture.
// Thread-safe: receive callbacks and the agent's loop both count.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace swarm::comm {

struct TrafficCount {
  std::uint64_t sent_messages = 0;
  std::uint64_t sent_bytes = 0;
  std::uint64_t addressed_messages = 0;  // each sent message once per receiver it was meant for
  std::uint64_t received_messages = 0;
  std::uint64_t received_bytes = 0;
  std::uint64_t lost_transmissions = 0;  // emulated losses, retransmitted on reliable topics
  std::uint64_t dropped_messages = 0;    // messages lost for good (best-effort topics)
  // On a link with a bandwidth cap: queued_ticks[d] = the messages sent that waited d ticks behind
  // earlier ones (the last entry: kQueueBins - 1 or more); empty on an uncapped link.
  std::vector<std::uint64_t> queued_ticks;
};
inline constexpr std::size_t kQueueBins = 64;

class TrafficAccount {
 public:
  using Key = std::pair<std::string, std::string>;  // (topic family, link name)
  // `queued`: the ticks a bandwidth cap held the message (LinkSender::last_queued_ticks).
  void sent(const std::string& family, const std::string& link, std::uint64_t bytes, std::size_t receivers = 1,
            std::optional<std::uint32_t> queued = std::nullopt);
  // A message that arrived after `lost` lost transmissions (each counted as received bytes too:
  // they crossed the link); `dropped` = lost for good.
  void received(const std::string& family, const std::string& link, std::uint64_t bytes, std::uint32_t lost,
                bool dropped);
  std::map<Key, TrafficCount> snapshot() const;
  // Bytes sent so far per link class, indexed by comm::LinkClass (link.hpp): kLinkClasses entries.
  std::vector<std::uint64_t> sent_bytes_by_link() const;

 private:
  mutable std::mutex mutex_;
  std::map<Key, TrafficCount> counts_;
};

}  // namespace swarm::comm
