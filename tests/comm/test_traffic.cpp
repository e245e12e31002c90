#include "swarm/comm/traffic.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace swarm::comm {
namespace {

TEST(Traffic, CountsPerTopicFamilyAndLink) {
  TrafficAccount account;
  account.sent("sense", "sim_robot", 1444);
  account.sent("sense", "sim_robot", 1444);
  account.sent("patch_up", "member_leader", 30);
  account.received("patch_up", "member_leader", 30, 0, false);
  const auto counts = account.snapshot();
  ASSERT_EQ(counts.size(), 2u);
  const TrafficCount& sense = counts.at({"sense", "sim_robot"});
  EXPECT_EQ(sense.sent_messages, 2u);
  EXPECT_EQ(sense.sent_bytes, 2888u);
  EXPECT_EQ(sense.received_messages, 0u);
  EXPECT_EQ(sense.received_bytes, 0u);
  const TrafficCount& patch = counts.at({"patch_up", "member_leader"});
  EXPECT_EQ(patch.sent_messages, 1u);
  EXPECT_EQ(patch.sent_bytes, 30u);
  EXPECT_EQ(patch.received_messages, 1u);
  EXPECT_EQ(patch.received_bytes, 30u);
  EXPECT_EQ(patch.lost_transmissions, 0u);
  EXPECT_EQ(patch.dropped_messages, 0u);
}

TEST(Traffic, RetransmissionsAndDropsCountTheBytesThatCrossedTheLink) {
  TrafficAccount account;
  // Reliable: a 50-byte message got through on the third transmission: 3 x 50 bytes crossed.
  account.received("status", "member_leader", 50, 2, false);
  // Best effort: a 40-byte message lost for good: its one transmission crossed, nothing arrived.
  account.received("status", "member_leader", 40, 1, true);
  const TrafficCount c = account.snapshot().at({"status", "member_leader"});
  EXPECT_EQ(c.received_messages, 1u);
  EXPECT_EQ(c.received_bytes, 150u + 40u);
  EXPECT_EQ(c.lost_transmissions, 2u + 1u);
  EXPECT_EQ(c.dropped_messages, 1u);
}

TEST(Traffic, TheSameFamilyOnTwoLinksIsTwoEntries) {
  TrafficAccount account;
  account.sent("patch", "member_leader", 10);
  account.sent("patch", "leader_gcs", 20);
  const auto counts = account.snapshot();
  EXPECT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts.at({"patch", "member_leader"}).sent_bytes, 10u);
  EXPECT_EQ(counts.at({"patch", "leader_gcs"}).sent_bytes, 20u);
}

TEST(Traffic, ConcurrentCountingLosesNothing) {
  TrafficAccount account;
  constexpr int kEach = 20000;
  std::thread receiver([&] {
    for (int i = 0; i < kEach; ++i) account.received("sense", "sim_robot", 3, i % 4 == 0 ? 1 : 0, false);
  });
  for (int i = 0; i < kEach; ++i) account.sent("sense", "sim_robot", 2);
  receiver.join();
  const TrafficCount c = account.snapshot().at({"sense", "sim_robot"});
  EXPECT_EQ(c.sent_messages, static_cast<std::uint64_t>(kEach));
  EXPECT_EQ(c.sent_bytes, 2u * kEach);
  EXPECT_EQ(c.received_messages, static_cast<std::uint64_t>(kEach));
  // A quarter of the messages needed one retransmission: 5 transmissions per 4 messages.
  EXPECT_EQ(c.received_bytes, 3u * (kEach + kEach / 4));
  EXPECT_EQ(c.lost_transmissions, static_cast<std::uint64_t>(kEach / 4));
  EXPECT_EQ(c.dropped_messages, 0u);
}

TEST(Traffic, ABandwidthCapsQueueIsCountedPerTicksWaited) {
  TrafficAccount account;
  account.sent("round", "leader_gcs", 100);  // uncapped: no histogram
  for (const std::uint32_t waited : {0U, 0U, 2U, 5U, 500U}) account.sent("patch_gcs", "leader_gcs", 10, 1, waited);
  const auto counts = account.snapshot();
  EXPECT_TRUE(counts.at({"round", "leader_gcs"}).queued_ticks.empty());
  const std::vector<std::uint64_t>& q = counts.at({"patch_gcs", "leader_gcs"}).queued_ticks;
  ASSERT_EQ(q.size(), kQueueBins);  // 500 ticks lands in the last bin
  EXPECT_EQ(q[0], 2u);
  EXPECT_EQ(q[2], 1u);
  EXPECT_EQ(q[5], 1u);
  EXPECT_EQ(q[kQueueBins - 1], 1u);
}

}  // namespace
}  // namespace swarm::comm
