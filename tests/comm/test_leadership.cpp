// The succession rule and the leader log (comm/leadership.hpp), with checked outcomes.
#include <gtest/gtest.h>

#include "swarm/comm/leadership.hpp"

namespace swarm::comm {
namespace {

std::vector<msgs::RobotState> robots(const std::vector<bool>& alive) {
  std::vector<msgs::RobotState> out;
  for (bool a : alive) {
    msgs::RobotState r;
    r.alive(a);
    out.push_back(r);
  }
  return out;
}

msgs::Clock clock_at(std::uint32_t tick, std::vector<AgentId> leaders) {
  msgs::Clock c;
  c.tick(tick);
  c.leaders(std::move(leaders));
  return c;
}

// 2 groups x 4 robots, 2 standbys: group 0 is robots 0..3 (candidates 0, 1, 2), group 1 is 4..7.
const Topology kTwoByFour(2, 4, 2);

TEST(Leadership, AGroupKeepsALivingLeader) {
  EXPECT_EQ(next_leaders(kTwoByFour, {0, 4}, robots({true, true, true, true, true, true, true, true})),
            (std::vector<AgentId>{0, 4}));
}

TEST(Leadership, TheLivingCandidateOfLowestIndexTakesOver) {
  // Group 0 loses robot 0: robot 1 leads. Group 1 loses 4 and its first standby 5: robot 6 leads.
  EXPECT_EQ(next_leaders(kTwoByFour, {0, 4}, robots({false, true, true, true, false, false, true, true})),
            (std::vector<AgentId>{1, 6}));
}

TEST(Leadership, ALeaderThatComesBackDoesNotTakeTheGroupBack) {
  // Robot 1 took over from 0; 0 is alive again: 1 keeps the group.
  EXPECT_EQ(next_leaders(kTwoByFour, {1, 4}, robots({true, true, true, true, true, true, true, true})),
            (std::vector<AgentId>{1, 4}));
}

TEST(Leadership, OnlyCandidatesLeadAndAGroupWithoutOneStaysWithItsLostLeader) {
  // Robots 0..2 of group 0 are lost; 3 is alive but no candidate (standbys = 2).
  EXPECT_EQ(next_leaders(kTwoByFour, {2, 4}, robots({false, false, false, true, true, true, true, true})),
            (std::vector<AgentId>{2, 4}));
  // No standbys: the group stays with its lost leader.
  const Topology none(1, 3, 0);
  EXPECT_EQ(next_leaders(none, {0}, robots({false, true, true})), (std::vector<AgentId>{0}));
}

TEST(Leadership, StandbysAreAtMostTheGroupsOtherRobots) {
  EXPECT_EQ(Topology(1, 3, 5).standbys(), 2);
  EXPECT_EQ(Topology(1, 1, 1).standbys(), 0);
  EXPECT_EQ(Topology(2, 4, 2).candidates(1), (std::vector<AgentId>{4, 5, 6}));
  EXPECT_EQ(Topology(2, 4, 1).all_candidates(), (std::vector<AgentId>{0, 1, 4, 5}));
  EXPECT_EQ(Topology(1, 3, 1).group_except(0, 1), (std::vector<AgentId>{0, 2}));
  EXPECT_TRUE(Topology(2, 4, 1).is_candidate(5));
  EXPECT_FALSE(Topology(2, 4, 1).is_candidate(6));
}

TEST(LeaderLog, JudgesAMessageByTheTickItWasSentAt) {
  LeaderLog log(kTwoByFour);
  log.observe(clock_at(0, {0, 4}));
  log.observe(clock_at(1, {0, 4}));
  log.observe(clock_at(2, {1, 4}));  // robot 1 takes group 0 over at tick 2
  log.observe(clock_at(3, {1, 4}));
  EXPECT_EQ(log.leader(0), 1);
  EXPECT_TRUE(log.led_at(0, 1));   // robot 0's message of tick 1: it led then
  EXPECT_FALSE(log.led_at(0, 2));  // ... of tick 2: deposed
  EXPECT_FALSE(log.led_at(1, 1));
  EXPECT_TRUE(log.led_at(1, 2));
  EXPECT_TRUE(log.led_at(1, 9));  // after the latest clock: as at the latest
  EXPECT_TRUE(log.led_at(4, 3));
  EXPECT_FALSE(log.led_at(5, 3));
  EXPECT_FALSE(log.led_at(8, 3));  // not a robot (the GCS)
  ASSERT_EQ(log.changes().size(), 1u);
  EXPECT_EQ(log.changes()[0].group, 0);
  EXPECT_EQ(log.changes()[0].from, 0);
  EXPECT_EQ(log.changes()[0].to, 1);
  EXPECT_EQ(log.changes()[0].tick, 2u);
}

TEST(LeaderLog, ATickSkippedAcrossAChangeAcceptsBothLeaders) {
  LeaderLog log(kTwoByFour);
  log.observe(clock_at(10, {0, 4}));
  log.observe(clock_at(20, {1, 4}));  // real time: ticks 11..19 were skipped; 1 led from one of them
  ASSERT_EQ(log.changes().size(), 1u);
  EXPECT_EQ(log.changes()[0].after, 10u);
  EXPECT_TRUE(log.led_at(0, 10));
  EXPECT_TRUE(log.led_at(0, 15));
  EXPECT_TRUE(log.led_at(1, 15));
  EXPECT_FALSE(log.led_at(2, 15));
  EXPECT_FALSE(log.led_at(1, 10));
  EXPECT_FALSE(log.led_at(0, 20));
}

TEST(LeaderLog, AClockWithoutLeadersChangesNothing) {
  LeaderLog log(kTwoByFour);
  log.observe(clock_at(0, {}));
  EXPECT_EQ(log.leaders(), (std::vector<AgentId>{0, 4}));
  EXPECT_TRUE(log.changes().empty());
}

}  // namespace
}  // namespace swarm::comm
