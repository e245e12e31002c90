// Outages: the intervals behind metrics.json's faults (lost robots, unreachable leaders).
#include <gtest/gtest.h>

#include "swarm/gcs/outages.hpp"

namespace swarm::gcs {
namespace {

TEST(Outages, OpensOnDownAndClosesOnUp) {
  Outages o(3);
  for (std::uint32_t k = 0; k < 10; ++k) o.observe(1, k >= 4 && k < 7, k, k);
  ASSERT_EQ(o.intervals().size(), 1u);
  EXPECT_EQ(o.intervals()[0].who, 1);
  EXPECT_EQ(o.intervals()[0].from, 4u);
  EXPECT_EQ(o.intervals()[0].to, 7u);
  EXPECT_FALSE(o.down(1));
  EXPECT_EQ(o.down_count(), 0);
}

TEST(Outages, SinceDatesTheIntervalBackAndNeverAfterTheTick) {
  Outages o(2);
  o.observe(0, true, 12, 15);  // silent since tick 12, noticed at 15
  o.observe(1, true, 30, 20);  // a `since` in the future is clamped to the tick
  EXPECT_EQ(o.intervals()[0].from, 12u);
  EXPECT_EQ(o.intervals()[1].from, 20u);
  EXPECT_EQ(o.down_count(), 2);
}

TEST(Outages, RepeatedOutagesOfOneAgentAreSeparateIntervalsInOrder) {
  Outages o(2);
  o.observe(0, true, 5, 5);
  o.observe(1, true, 6, 6);
  o.observe(0, false, 0, 9);
  o.observe(0, true, 20, 20);
  ASSERT_EQ(o.intervals().size(), 3u);
  EXPECT_EQ(o.intervals()[0].to, 9u);
  EXPECT_EQ(o.intervals()[1].who, 1);
  EXPECT_FALSE(o.intervals()[1].to.has_value());
  EXPECT_EQ(o.intervals()[2].from, 20u);
  EXPECT_FALSE(o.intervals()[2].to.has_value());
  EXPECT_TRUE(o.down(0));
  EXPECT_TRUE(o.down(1));
}

}  // namespace
}  // namespace swarm::gcs
