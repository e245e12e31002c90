// What a message suffers between two agents, per link class (docs/design.md, "Link emulation").
//
// Lockstep semantics, all in ticks and decided deterministically from the run's seed:
// - A message an agent sends at tick t is acted on at t + 1 + delay (+ jitter) at the earliest:
//   agents act in parallel within a tick, so nothing sent at t can be seen at t. The simulator's
//   scans are the exception: taken at the start of tick t, they are seen at t + delay.
// - Bandwidth: each sender has one token bucket per link class; a message of B bytes occupies the
//   link for B / rate simulated seconds after the previous one, and is acted on no earlier than
//   the tick during which its last byte arrives (its end time rounded up to a tick boundary).
// - Loss: each receiver loses a transmission with the link's probability, drawn from a hash of
//   (seed, sender, topic, sequence number, receiver, attempt), so a broadcast is lost
//   independently at each receiver and the outcome does not depend on arrival order. Reliable
//   topics behave as DDS reliability does on a lossy link: a lost transmission is repeated
//   retransmit_ticks later, until one gets through. Best-effort topics lose the message.
// Real-time mode counts in milliseconds of wall time instead: delay_ms, and retransmissions
// retransmit_ticks ticks of tick_ms apart.
// Not thread-safe: one LinkSender per sending agent, used from its own loop.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarm::comm {

enum class LinkClass : std::uint8_t { SimRobot, MemberLeader, LeaderGcs, Telemetry, Control };
inline constexpr int kLinkClasses = 5;

std::string link_name(LinkClass c);  // "sim_robot", "member_leader", "leader_gcs", "telemetry", "control"

struct LinkParams {
  std::uint32_t delay_ticks = 0;
  std::uint32_t jitter_ticks = 0;
  double loss = 0.0;
  double bandwidth_bytes_per_s = 0.0;  // 0 = unlimited
  std::uint32_t retransmit_ticks = 2;
  double delay_ms = 0.0;  // real-time mode
};

enum class Delivery : std::uint8_t { Reliable, BestEffort };

// An agent's radio links (member<->leader, leader<->GCS) are down for ticks [from, to): what
// it sends or is sent meanwhile is held and arrives when the link heals, at tick `to`.
struct LinkCut {
  std::uint16_t agent = 0;
  std::uint32_t from = 0;
  std::uint32_t to = 0;
};

// The parameters of every link class in a run; Telemetry and Control are always ideal.
struct LinkTable {
  std::array<LinkParams, kLinkClasses> params{};
  double tick_seconds = 0.2;
  std::uint64_t seed = 1;
  bool realtime = false;
  double tick_ms = 50.0;  // real-time mode: wall milliseconds per tick
  std::vector<LinkCut> cuts;
  const LinkParams& operator[](LinkClass c) const { return params[static_cast<int>(c)]; }
  LinkParams& operator[](LinkClass c) { return params[static_cast<int>(c)]; }
};

// 64-bit mixing (splitmix64 finaliser): the one hash every deterministic draw in comm uses.
std::uint64_t mix64(std::uint64_t x);
std::uint64_t hash_combine(std::uint64_t seed, std::uint64_t value);
std::uint64_t hash_string(const std::string& s);  // FNV-1a

class LinkSender {
 public:
  explicit LinkSender(const LinkTable& table) : table_(table) {}
  // The tick at which a message of `bytes` sent now may be acted on. `from_clock_master` marks the
  // simulator's per-tick sensor data (no inherent one-tick lag).
  std::uint32_t deliver_tick(LinkClass link, std::uint32_t tick, std::size_t bytes,
                             std::uint64_t topic_hash, std::uint32_t seq, bool from_clock_master);
  // What the last deliver_tick's message waits behind the ones before it on a capped link: the
  // ticks its cap adds (0 when the link is free); nullopt when its link has no cap.
  [[nodiscard]] std::optional<std::uint32_t> last_queued_ticks() const { return last_queued_; }

 private:
  const LinkTable& table_;
  std::array<double, kLinkClasses> busy_until_s_{};  // token bucket: when the link is free again
  std::optional<std::uint32_t> last_queued_;
};

// Receiver side: is this transmission (attempt 0 = the first) of the message lost?
bool link_drops(const LinkTable& table, LinkClass link, std::uint16_t sender, std::uint64_t topic_hash,
                std::uint32_t seq, std::uint16_t receiver, std::uint32_t attempt = 0);
// The earliest tick a message stamped `tick` between these agents on `link` may arrive, given
// the run's cuts (`deliver_tick` when no cut applies).
std::uint32_t after_cuts(const LinkTable& table, LinkClass link, std::uint16_t sender, std::uint16_t receiver,
                         std::uint32_t tick, std::uint32_t deliver_tick);

// The last tick at which a message sent at `tick` on a link with these parameters can be acted on
// in lockstep, with no loss, bandwidth limit or cut: tick + 1 + delay + jitter. Tasks that wait
// for everything already sent to arrive (a hand-over, a common start tick) wait until then.
std::uint32_t last_arrival_tick(const LinkParams& p, std::uint32_t tick);
// The same on a lossy link, allowing for as many repeats of a reliable message as make its being
// later still less likely than kLateOdds: for tasks whose robots must all act at one tick.
inline constexpr double kLateOdds = 1e-5;
std::uint32_t sure_arrival_tick(const LinkParams& p, std::uint32_t tick);

// How many transmissions of the message are lost before one gets through (at most 64).
std::uint32_t lost_transmissions(const LinkTable& table, LinkClass link, std::uint16_t sender,
                                 std::uint64_t topic_hash, std::uint32_t seq, std::uint16_t receiver);

}  // namespace swarm::comm
