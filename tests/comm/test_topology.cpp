#include "swarm/comm/topology.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace swarm::comm {
namespace {

TEST(Topology, AgentIdsFollowGroupsTimesRobots) {
  // 2 groups x 3 robots: robots 0..5 (group 0: 0 1 2, group 1: 3 4 5), GCS 6, simulator 7.
  const Topology t(2, 3);
  EXPECT_EQ(t.groups(), 2);
  EXPECT_EQ(t.robots_per_group(), 3);
  EXPECT_EQ(t.robots(), 6);
  EXPECT_EQ(t.agents(), 8);
  EXPECT_EQ(t.gcs(), 6);
  EXPECT_EQ(t.sim(), 7);
  EXPECT_EQ(t.robot(1, 2), 5);
  EXPECT_EQ(t.leader(0), 0);
  EXPECT_EQ(t.leader(1), 3);
  EXPECT_EQ(t.group_of(5), 1);
  EXPECT_EQ(t.index_of(5), 2);
  EXPECT_EQ(t.group_of(2), 0);
  EXPECT_EQ(t.index_of(3), 0);
  EXPECT_TRUE(t.is_robot(5));
  EXPECT_FALSE(t.is_robot(6));
  EXPECT_FALSE(t.is_robot(7));
  EXPECT_EQ(t.group_except(1, t.leader(1)), (std::vector<AgentId>{4, 5}));
  EXPECT_EQ(t.leaders(), (std::vector<AgentId>{0, 3}));
  EXPECT_EQ(t.robot_ids(), (std::vector<AgentId>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(t.all_but_sim(), (std::vector<AgentId>{0, 1, 2, 3, 4, 5, 6}));
}

TEST(Topology, OneRobotGroupsHaveNoMembers) {
  const Topology t(3, 1);
  EXPECT_EQ(t.leaders(), (std::vector<AgentId>{0, 1, 2}));
  EXPECT_TRUE(t.group_except(2, t.leader(2)).empty());
  EXPECT_EQ(t.gcs(), 3);
  EXPECT_EQ(t.sim(), 4);
  EXPECT_EQ(t.name_of(2), "leader-2");
}

TEST(Topology, NamesForLogsAndReports) {
  const Topology t(2, 3);
  EXPECT_EQ(t.name_of(0), "leader-0");
  EXPECT_EQ(t.name_of(3), "leader-1");
  EXPECT_EQ(t.name_of(1), "member-0-1");
  EXPECT_EQ(t.name_of(5), "member-1-2");
  EXPECT_EQ(t.name_of(6), "gcs");
  EXPECT_EQ(t.name_of(7), "sim");
  EXPECT_EQ(t.name_of(9), "agent-9");
}

TEST(Topology, TopicNamesPerRecipient) {
  EXPECT_EQ(topic::sense(12), "sense_12");
  EXPECT_EQ(topic::patch_up(3), "patch_up_g3");
  EXPECT_EQ(topic::patch_down(0), "patch_down_g0");
  EXPECT_EQ(topic::route(1), "route_g1");
  EXPECT_EQ(topic::progress(10), "progress_g10");
}

TEST(Topology, TopicFamilyStripsThePerRecipientSuffix) {
  EXPECT_EQ(topic::family("sense_12"), "sense");
  EXPECT_EQ(topic::family("patch_up_g3"), "patch_up");
  EXPECT_EQ(topic::family("patch_down_g0"), "patch_down");
  EXPECT_EQ(topic::family("progress_g10"), "progress");
  EXPECT_EQ(topic::family("clock"), "clock");
  EXPECT_EQ(topic::family("patch_gcs"), "patch_gcs");
  EXPECT_EQ(topic::family("task_order"), "task_order");
  // Digits not behind "_" or "_g" are part of the name.
  EXPECT_EQ(topic::family("log12"), "log12");
  EXPECT_EQ(topic::family("tag7"), "tag7");
  EXPECT_EQ(topic::family("7"), "7");
  EXPECT_EQ(topic::family(""), "");
}

}  // namespace
}  // namespace swarm::comm
