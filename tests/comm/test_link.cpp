#include "swarm/comm/link.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <vector>

namespace swarm::comm {
namespace {

const std::uint64_t kTopic = hash_string("patch_up_g0");

TEST(Link, NamesOfTheLinkClasses) {
  EXPECT_EQ(link_name(LinkClass::SimRobot), "sim_robot");
  EXPECT_EQ(link_name(LinkClass::MemberLeader), "member_leader");
  EXPECT_EQ(link_name(LinkClass::LeaderGcs), "leader_gcs");
  EXPECT_EQ(link_name(LinkClass::Telemetry), "telemetry");
  EXPECT_EQ(link_name(LinkClass::Control), "control");
}

TEST(Link, Mix64IsTheSplitmix64Finaliser) {
  // splitmix64's first output for the seed 0 (its state is advanced by the golden gamma first).
  EXPECT_EQ(mix64(0), 0xe220a8397b1dcdafULL);
  EXPECT_NE(hash_combine(1, 2), hash_combine(2, 1));
}

// Regression: the offset basis once lost its last digit, so hash_string was not FNV-1a.
TEST(Link, HashStringIsFnv1a64) {
  // The offset basis for "", and the published value for "a".
  EXPECT_EQ(hash_string(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(hash_string("a"), 0xaf63dc4c8601ec8cULL);
}

TEST(Link, AgentsDeliverAtTickPlusOnePlusDelayTheClockMasterAtTickPlusDelay) {
  LinkTable table;
  table[LinkClass::MemberLeader].delay_ticks = 3;
  table[LinkClass::SimRobot].delay_ticks = 2;
  LinkSender sender(table);
  EXPECT_EQ(sender.deliver_tick(LinkClass::MemberLeader, 10, 100, kTopic, 0, false), 14u);  // 10+1+3
  EXPECT_EQ(sender.deliver_tick(LinkClass::MemberLeader, 10, 100, kTopic, 1, true), 13u);   // 10+3
  EXPECT_EQ(sender.deliver_tick(LinkClass::SimRobot, 0, 5000, kTopic, 2, true), 2u);        // 0+2
  EXPECT_EQ(sender.deliver_tick(LinkClass::SimRobot, 0, 5000, kTopic, 3, false), 3u);       // 0+1+2
  // Telemetry and Control default to ideal links: the next tick.
  EXPECT_EQ(sender.deliver_tick(LinkClass::Telemetry, 7, 1, kTopic, 4, false), 8u);
  EXPECT_EQ(sender.deliver_tick(LinkClass::Control, 7, 1, kTopic, 5, true), 7u);
}

TEST(Link, JitterStaysWithinItsRangeAndIsReproducible) {
  LinkTable table;
  table.seed = 42;
  table[LinkClass::LeaderGcs].delay_ticks = 2;
  table[LinkClass::LeaderGcs].jitter_ticks = 3;
  LinkSender a(table);
  LinkSender b(table);
  std::vector<std::uint32_t> extra;
  std::set<std::uint32_t> values;
  for (std::uint32_t seq = 0; seq < 1000; ++seq) {
    const std::uint32_t t = a.deliver_tick(LinkClass::LeaderGcs, 5, 64, kTopic, seq, false);
    ASSERT_GE(t, 5u + 1 + 2) << seq;
    ASSERT_LE(t, 5u + 1 + 2 + 3) << seq;
    extra.push_back(t - 8);
    values.insert(t - 8);
    // A second sender with the same table (another run of the same scenario) draws the same.
    EXPECT_EQ(b.deliver_tick(LinkClass::LeaderGcs, 5, 64, kTopic, seq, false), t) << seq;
  }
  EXPECT_EQ(values, (std::set<std::uint32_t>{0, 1, 2, 3}));  // 1000 draws hit all four values
  // Another seed draws differently.
  LinkTable other = table;
  other.seed = 43;
  LinkSender c(other);
  int same = 0;
  for (std::uint32_t seq = 0; seq < 1000; ++seq) {
    same += c.deliver_tick(LinkClass::LeaderGcs, 5, 64, kTopic, seq, false) - 8 == extra[seq];
  }
  EXPECT_LT(same, 400);  // independent draws agree about 1 in 4 times
}

TEST(Link, LastArrivalTickIsTheLatestTickAnyDrawDelivers) {
  LinkTable table;
  table[LinkClass::MemberLeader].delay_ticks = 2;
  table[LinkClass::MemberLeader].jitter_ticks = 3;
  EXPECT_EQ(last_arrival_tick(table[LinkClass::MemberLeader], 5), 11u);  // 5 + 1 + 2 + 3
  EXPECT_EQ(last_arrival_tick(LinkParams{}, 5), 6u);                     // an ideal link: next tick
  LinkSender sender(table);
  std::uint32_t latest = 0;
  for (std::uint32_t seq = 0; seq < 200; ++seq) {
    latest = std::max(latest, sender.deliver_tick(LinkClass::MemberLeader, 5, 64, kTopic, seq, false));
  }
  EXPECT_EQ(latest, last_arrival_tick(table[LinkClass::MemberLeader], 5));
}

// On a lossy link a reliable message is repeated every retransmit_ticks: the sure arrival allows
// for as many repeats as make a later one rarer than kLateOdds. 5 % loss: 4 transmissions all lost
// once in 160,000 (0.05^4), so 3 repeats, 6 ticks; 1 %: 2 repeats (0.01^3 = 1e-6).
TEST(Link, SureArrivalAllowsForRepeatsOfLostTransmissions) {
  LinkParams p;
  p.delay_ticks = 2;
  EXPECT_EQ(sure_arrival_tick(p, 5), last_arrival_tick(p, 5));  // no loss: nothing repeated
  p.loss = 0.05;
  EXPECT_EQ(sure_arrival_tick(p, 5), 8u + 3 * 2);
  p.loss = 0.01;
  EXPECT_EQ(sure_arrival_tick(p, 5), 8u + 2 * 2);
  // Drawn: of 20,000 messages at 5 % loss none arrives later than that.
  LinkTable table;
  table[LinkClass::LeaderGcs].loss = 0.05;
  std::uint32_t most = 0;
  for (std::uint32_t seq = 0; seq < 20000; ++seq) {
    most = std::max(most, lost_transmissions(table, LinkClass::LeaderGcs, 1, kTopic, seq, 2));
  }
  EXPECT_LE(most, 3u);
}

TEST(Link, BandwidthQueuesMessagesBehindEachOther) {
  // 100 B/s, 0.2 s per tick: a 30-byte message occupies the link 0.3 s = 1.5 ticks. Three sent at
  // tick 0 leave one after another; their last bytes are out 1.5, 3.0 and 4.5 ticks after the
  // start of tick 0, so they arrive during ticks 1, 2 and 4 and are acted on at the boundaries
  // 2, 3 and 5 (later than t + 1, so the one-tick lag adds nothing), for an agent and for the
  // clock master alike.
  LinkTable table;
  table.tick_seconds = 0.2;
  table[LinkClass::MemberLeader].bandwidth_bytes_per_s = 100.0;
  LinkSender agent(table);
  // What the cap added to each, beyond tick + 1: 1, 2 and 4 ticks.
  EXPECT_EQ(agent.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 0, false), 2u);
  EXPECT_EQ(agent.last_queued_ticks(), 1u);
  EXPECT_EQ(agent.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 1, false), 3u);
  EXPECT_EQ(agent.last_queued_ticks(), 2u);
  EXPECT_EQ(agent.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 2, false), 5u);
  EXPECT_EQ(agent.last_queued_ticks(), 4u);
  // Each link class has its own bucket: an unlimited class is not held up by the queue, and has
  // no queue to report.
  EXPECT_EQ(agent.deliver_tick(LinkClass::LeaderGcs, 0, 30, kTopic, 0, false), 1u);
  EXPECT_FALSE(agent.last_queued_ticks().has_value());
  // Once the queue has drained (0.9 s < tick 10 = 2.0 s) a message starts at its own tick:
  // 2.0 + 0.3 = 2.3 s = 11.5 ticks -> boundary 12, 1 tick after tick + 1.
  EXPECT_EQ(agent.deliver_tick(LinkClass::MemberLeader, 10, 30, kTopic, 3, false), 12u);
  EXPECT_EQ(agent.last_queued_ticks(), 1u);
  // A message small enough to be out within its tick waits for nothing: 10 B = 0.1 s at tick 20.
  EXPECT_EQ(agent.deliver_tick(LinkClass::MemberLeader, 20, 10, kTopic, 4, false), 21u);
  EXPECT_EQ(agent.last_queued_ticks(), 0u);

  LinkSender sim(table);
  EXPECT_EQ(sim.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 0, true), 2u);
  EXPECT_EQ(sim.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 1, true), 3u);
  EXPECT_EQ(sim.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 2, true), 5u);

  // The delay is added after the queue.
  table[LinkClass::MemberLeader].delay_ticks = 2;
  LinkSender delayed(table);
  EXPECT_EQ(delayed.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 0, false), 4u);
  EXPECT_EQ(delayed.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 1, false), 5u);
  EXPECT_EQ(delayed.deliver_tick(LinkClass::MemberLeader, 0, 30, kTopic, 2, false), 7u);
}

TEST(Link, LossDropsItsShareDeterministicallyAndIndependentlyPerReceiver) {
  LinkTable table;
  table.seed = 9;
  table[LinkClass::MemberLeader].loss = 0.3;
  constexpr int kDraws = 10000;
  int lost_1 = 0;
  int lost_both = 0;
  int lost_other_sender = 0;
  for (std::uint32_t seq = 0; seq < kDraws; ++seq) {
    const bool to_1 = link_drops(table, LinkClass::MemberLeader, 0, kTopic, seq, 1);
    const bool to_2 = link_drops(table, LinkClass::MemberLeader, 0, kTopic, seq, 2);
    // The same question gives the same answer, whatever the order of asking.
    ASSERT_EQ(link_drops(table, LinkClass::MemberLeader, 0, kTopic, seq, 1), to_1);
    lost_1 += to_1;
    lost_both += to_1 && to_2;
    lost_other_sender += to_1 && link_drops(table, LinkClass::MemberLeader, 3, kTopic, seq, 1);
  }
  // Share of drops within +-2 % of p = 0.3; independent receivers (and senders) lose the same
  // message with probability p^2 = 0.09.
  EXPECT_NEAR(lost_1 / static_cast<double>(kDraws), 0.3, 0.02);
  EXPECT_NEAR(lost_both / static_cast<double>(kDraws), 0.09, 0.02);
  EXPECT_NEAR(lost_other_sender / static_cast<double>(kDraws), 0.09, 0.02);

  // p = 0.5 as well.
  table[LinkClass::MemberLeader].loss = 0.5;
  int lost_half = 0;
  for (std::uint32_t seq = 0; seq < kDraws; ++seq) {
    lost_half += link_drops(table, LinkClass::MemberLeader, 0, kTopic, seq, 1);
  }
  EXPECT_NEAR(lost_half / static_cast<double>(kDraws), 0.5, 0.02);
}

TEST(Link, LostTransmissionsCountsTheLostAttemptsBeforeTheFirstThatGetsThrough) {
  LinkTable table;
  table.seed = 5;
  table[LinkClass::MemberLeader].loss = 0.5;
  constexpr int kDraws = 10000;
  int none = 0;
  int one = 0;
  for (std::uint32_t seq = 0; seq < kDraws; ++seq) {
    const std::uint32_t lost = lost_transmissions(table, LinkClass::MemberLeader, 1, kTopic, seq, 0);
    // Attempt 0 is the plain draw; attempts 0 .. lost-1 are lost, attempt `lost` gets through.
    ASSERT_EQ(link_drops(table, LinkClass::MemberLeader, 1, kTopic, seq, 0, 0),
              link_drops(table, LinkClass::MemberLeader, 1, kTopic, seq, 0));
    for (std::uint32_t a = 0; a < lost; ++a) {
      ASSERT_TRUE(link_drops(table, LinkClass::MemberLeader, 1, kTopic, seq, 0, a)) << seq << " " << a;
    }
    ASSERT_FALSE(link_drops(table, LinkClass::MemberLeader, 1, kTopic, seq, 0, lost)) << seq;
    none += lost == 0;
    one += lost == 1;
  }
  // Geometric with p = 0.5: P(0 lost) = 0.5, P(1 lost) = 0.25.
  EXPECT_NEAR(none / static_cast<double>(kDraws), 0.5, 0.02);
  EXPECT_NEAR(one / static_cast<double>(kDraws), 0.25, 0.02);
  // Loss 1 never gets through: capped at 64 attempts. Loss 0 loses nothing.
  table[LinkClass::MemberLeader].loss = 1.0;
  EXPECT_EQ(lost_transmissions(table, LinkClass::MemberLeader, 1, kTopic, 0, 0), 64u);
  EXPECT_EQ(lost_transmissions(table, LinkClass::LeaderGcs, 1, kTopic, 0, 0), 0u);
}

TEST(Link, LossZeroNeverDropsAndLossOneAlwaysDoes) {
  LinkTable table;
  table[LinkClass::LeaderGcs].loss = 1.0;
  for (std::uint32_t seq = 0; seq < 1000; ++seq) {
    EXPECT_FALSE(link_drops(table, LinkClass::MemberLeader, 0, kTopic, seq, 1));
    EXPECT_TRUE(link_drops(table, LinkClass::LeaderGcs, 0, kTopic, seq, 1));
  }
}

}  // namespace
}  // namespace swarm::comm
