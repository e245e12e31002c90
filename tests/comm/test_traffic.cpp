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
  account.received("patch_up", "member_leader", 30, false);
  account.received("patch_up", "member_leader", 50, true);
  const auto counts = account.snapshot();
  ASSERT_EQ(counts.size(), 2u);
  const TrafficCount& sense = counts.at({"sense", "sim_robot"});
  EXPECT_EQ(sense.sent_messages, 2u);
  EXPECT_EQ(sense.sent_bytes, 2888u);
  EXPECT_EQ(sense.received_messages, 0u);
  const TrafficCount& patch = counts.at({"patch_up", "member_leader"});
  EXPECT_EQ(patch.sent_messages, 1u);
  EXPECT_EQ(patch.sent_bytes, 30u);
  // A dropped message was still received (its bytes crossed the wire) and is counted as dropped.
  EXPECT_EQ(patch.received_messages, 2u);
  EXPECT_EQ(patch.received_bytes, 80u);
  EXPECT_EQ(patch.dropped_messages, 1u);
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
    for (int i = 0; i < kEach; ++i) account.received("sense", "sim_robot", 3, i % 4 == 0);
  });
  for (int i = 0; i < kEach; ++i) account.sent("sense", "sim_robot", 2);
  receiver.join();
  const TrafficCount c = account.snapshot().at({"sense", "sim_robot"});
  EXPECT_EQ(c.sent_messages, static_cast<std::uint64_t>(kEach));
  EXPECT_EQ(c.sent_bytes, 2u * kEach);
  EXPECT_EQ(c.received_messages, static_cast<std::uint64_t>(kEach));
  EXPECT_EQ(c.received_bytes, 3u * kEach);
  EXPECT_EQ(c.dropped_messages, static_cast<std::uint64_t>(kEach / 4));
}

}  // namespace
}  // namespace swarm::comm
