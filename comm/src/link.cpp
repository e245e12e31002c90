#include "swarm/comm/link.hpp"

#include <algorithm>
#include <cmath>

namespace swarm::comm {

std::string link_name(LinkClass c) {
  switch (c) {
    case LinkClass::SimRobot: return "sim_robot";
    case LinkClass::MemberLeader: return "member_leader";
    case LinkClass::LeaderGcs: return "leader_gcs";
    case LinkClass::Telemetry: return "telemetry";
    case LinkClass::Control: return "control";
  }
  return "unknown";
}

std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t hash_combine(std::uint64_t seed, std::uint64_t value) { return mix64(seed ^ mix64(value)); }

std::uint64_t hash_string(const std::string& s) {
  std::uint64_t h = 14695981039346656037ULL;  // FNV-1a 64 offset basis
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
  return h;
}

namespace {
// A uniform draw in [0, 1) from 53 bits of the hash: the same on every machine.
double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0); }
}  // namespace

std::uint32_t LinkSender::deliver_tick(LinkClass link, std::uint32_t tick, std::size_t bytes,
                                       std::uint64_t topic_hash, std::uint32_t seq, bool from_clock_master) {
  const LinkParams& p = table_[link];
  const std::uint32_t lag = from_clock_master ? 0 : 1;
  std::uint32_t ready = tick + lag;
  last_queued_.reset();
  if (p.bandwidth_bytes_per_s > 0) {
    // Token bucket of one message: the link is busy until the previous message has gone out.
    double& busy = busy_until_s_[static_cast<int>(link)];
    const double now = tick * table_.tick_seconds;
    busy = std::max(busy, now) + static_cast<double>(bytes) / p.bandwidth_bytes_per_s;
    // Acted on in the tick during which its last byte arrives (an unlimited link's message,
    // "arriving" at once, is acted on at tick + lag).
    const auto done_tick = static_cast<std::uint32_t>(std::ceil(busy / table_.tick_seconds - 1e-9));
    last_queued_ = done_tick > ready ? done_tick - ready : 0;
    ready = std::max(ready, done_tick);
  }
  std::uint32_t jitter = 0;
  if (p.jitter_ticks > 0) {
    const std::uint64_t h = hash_combine(hash_combine(table_.seed, topic_hash), seq);
    jitter = static_cast<std::uint32_t>(h % (p.jitter_ticks + 1));
  }
  return ready + p.delay_ticks + jitter;
}

std::uint32_t last_arrival_tick(const LinkParams& p, std::uint32_t tick) {
  return tick + 1 + p.delay_ticks + p.jitter_ticks;
}

std::uint32_t sure_arrival_tick(const LinkParams& p, std::uint32_t tick) {
  std::uint32_t repeats = 0;
  // Each transmission is lost with probability `loss`: repeats + 1 of them all lost, loss^(repeats + 1).
  for (double late = p.loss; late > kLateOdds && repeats < 64; late *= p.loss) ++repeats;
  return last_arrival_tick(p, tick) + repeats * p.retransmit_ticks;
}

bool link_drops(const LinkTable& table, LinkClass link, std::uint16_t sender, std::uint64_t topic_hash,
                std::uint32_t seq, std::uint16_t receiver, std::uint32_t attempt) {
  const double loss = table[link].loss;
  if (loss <= 0) return false;
  std::uint64_t h = hash_combine(table.seed ^ 0x5157a11ULL, topic_hash);
  h = hash_combine(h, (static_cast<std::uint64_t>(sender) << 48) ^ (static_cast<std::uint64_t>(receiver) << 32) ^ seq);
  if (attempt > 0) h = hash_combine(h, attempt);
  return unit(h) < loss;
}

std::uint32_t after_cuts(const LinkTable& table, LinkClass link, std::uint16_t sender, std::uint16_t receiver,
                         std::uint32_t tick, std::uint32_t deliver_tick) {
  if (link != LinkClass::MemberLeader && link != LinkClass::LeaderGcs) return deliver_tick;
  for (const LinkCut& c : table.cuts) {
    const bool involved = c.agent == sender || c.agent == receiver;
    // Sent while cut, or due while cut: it waits for the link to heal.
    if (involved && ((tick >= c.from && tick < c.to) || (deliver_tick >= c.from && deliver_tick < c.to))) {
      deliver_tick = std::max(deliver_tick, c.to);
    }
  }
  return deliver_tick;
}

std::uint32_t lost_transmissions(const LinkTable& table, LinkClass link, std::uint16_t sender,
                                 std::uint64_t topic_hash, std::uint32_t seq, std::uint16_t receiver) {
  std::uint32_t lost = 0;
  while (lost < 64 && link_drops(table, link, sender, topic_hash, seq, receiver, lost)) ++lost;
  return lost;
}

}  // namespace swarm::comm
