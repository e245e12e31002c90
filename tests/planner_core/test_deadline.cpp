// deadline_after: a time limit never wraps into a deadline already past.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "swarm/planner/grid/deadline.hpp"
#include "swarm/planner/mapf/result.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using swarm::planner::deadline_after;

TEST(DeadlineAfter, ALimitPastTheClocksRangeIsNoLimit) {
  const Clock::time_point now = Clock::now();
  // 1e10 s is 1e19 ns: converted as is it would wrap below now and stop a search at once.
  EXPECT_EQ(deadline_after(1e10, now), Clock::time_point::max());
  EXPECT_EQ(deadline_after(1e300, now), Clock::time_point::max());
  EXPECT_EQ(deadline_after(std::numeric_limits<double>::infinity(), now), Clock::time_point::max());
}

TEST(DeadlineAfter, OrdinaryLimitsAreExact) {
  const Clock::time_point now = Clock::now();
  EXPECT_EQ(deadline_after(1.5, now) - now, std::chrono::milliseconds(1500));
  EXPECT_EQ(deadline_after(1e6, now) - now, std::chrono::seconds(1000000));
  EXPECT_EQ(deadline_after(0, now), now);
  EXPECT_EQ(deadline_after(-3, now), now);
  EXPECT_EQ(deadline_after(std::nan(""), now), now);
}

TEST(DeadlineAfter, AStopConditionOfAHugeLimitIsNotReached) {
  EXPECT_FALSE(swarm::planner::mapf::StopCondition::after(1e10).reached());
  EXPECT_FALSE(swarm::planner::mapf::StopCondition::after(std::numeric_limits<double>::infinity()).reached());
  EXPECT_TRUE(swarm::planner::mapf::StopCondition::after(0).reached());
}

}  // namespace
