// The lockstep protocol on the in-process FakeBus: the same LockstepClock and LockstepAgent code
// as over DDS, stepped in one thread.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "swarm/comm/fake_bus.hpp"
#include "swarm/comm/lockstep.hpp"

namespace swarm::comm {
namespace {

std::vector<msgs::RobotState> one_robot() {
  msgs::RobotState r;
  r.alive(true);
  return {r};
}

msgs::Done done_of(AgentId agent, std::uint32_t tick, int agents) {
  msgs::Done d;
  d.agent(agent);
  d.tick(tick);
  d.sent(std::vector<std::uint32_t>(static_cast<std::size_t>(agents), 0));
  return d;
}

// Regression: an agent that rejoined late (its Done messages for ticks long past arriving as it
// caught up) left a done marker per past tick in the clock for ever. Over a 100,000-tick run with
// such a rejoin the clock and the agents hold no per-tick bookkeeping beyond the tick at hand.
TEST(LockstepFake, ALateRejoinLeavesNoPerTickBookkeepingOverALongRun) {
  ::setenv("SWARM_STALL_TIMEOUT", "2", 0);
  const Topology t(1, 1);  // robot 0, the GCS 1, the simulator 2
  LinkTable links;
  FakeNetwork net;
  FakeBus sim_bus(net), robot_bus(net), gcs_bus(net), rejoined_bus(net);
  LockstepClock clock(sim_bus, t, links);
  LockstepAgent robot(robot_bus, t, links, 0);
  LockstepAgent gcs(gcs_bus, t, links, t.gcs());
  robot.announce_ready();
  gcs.announce_ready();
  clock.wait_ready();

  constexpr std::uint32_t kLost = 10, kBack = 50'000, kEnd = 100'000;
  std::unique_ptr<Writer<msgs::Done>> late;
  for (std::uint32_t k = 0; k < kEnd; ++k) {
    clock.begin_tick(k);
    clock.publish_clock(k, one_robot(), false);
    if (k < kLost) {
      ASSERT_NE(robot.begin_tick(), nullptr);
      robot.end_tick();
    }
    if (k == kLost) {
      net.disconnect(robot_bus);  // lost: its heartbeat writer is gone
      ASSERT_TRUE(clock.is_lost(0));
    }
    if (k == kBack) {
      // It comes back (a new session) and works through every tick it missed.
      late = std::make_unique<Writer<msgs::Done>>(rejoined_bus, topic::kDone, EndpointKind::Heartbeat);
      for (std::uint32_t old = kLost; old < kBack; ++old) late->write(done_of(0, old, t.agents()));
      ASSERT_FALSE(clock.is_lost(0));
    }
    if (late) late->write(done_of(0, k, t.agents()));
    ASSERT_NE(gcs.begin_tick(), nullptr);
    gcs.end_tick();
    ASSERT_FALSE(clock.wait_done(k));
    ASSERT_LE(clock.done_ticks_held(), 1u) << "tick " << k;
  }
  EXPECT_EQ(clock.done_ticks_held(), 0u);
  EXPECT_EQ(gcs.arrival_ticks_held(), 0u);
  ASSERT_EQ(clock.losses().size(), 1u);
  EXPECT_EQ(clock.losses()[0].tick, kLost);
  EXPECT_EQ(clock.losses()[0].rejoined_tick, kBack);
}

// A restarted GCS (lockstep.hpp "Restart"): the first process journals what its handlers got; it
// dies at tick 10 and the run goes on without it; a new process replays the journal (its handler
// sees exactly what the dead one saw, its sends muted), announces itself, is admitted at the next
// clock (counted_from) and counts only what is stamped from then on, so the barrier never waits for
// what the dead process had heard; ten more ticks run, and the loss is recorded as a restart.
TEST(LockstepFake, ARestartedAgentReplaysItsJournalAndRejoinsAtTheNextClock) {
  ::setenv("SWARM_STALL_TIMEOUT", "2", 0);
  const Topology t(1, 1);  // robot 0, the GCS 1, the simulator 2
  LinkTable links;
  FakeNetwork net;
  FakeBus sim_bus(net), robot_bus(net), gcs_bus(net), restarted_bus(net);
  LockstepClock clock(sim_bus, t, links);
  LockstepAgent robot(robot_bus, t, links, 0);
  auto& to_gcs = robot.advertise<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, {t.gcs()});
  std::vector<std::uint32_t> heard;  // the stamp ticks of what the first GCS process handled
  auto gcs = std::make_unique<LockstepAgent>(gcs_bus, t, links, t.gcs());
  gcs->subscribe<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs,
                                  [&](const msgs::Heartbeat& h) { heard.push_back(h.header().tick()); });
  auto& from_gcs = gcs->advertise<msgs::Heartbeat>("gcs_out", LinkClass::LeaderGcs, {0});
  robot.subscribe<msgs::Heartbeat>("gcs_out", LinkClass::LeaderGcs, [](const msgs::Heartbeat&) {});
  const std::string journal = ::testing::TempDir() + "/restart_test.journal";
  std::remove(journal.c_str());
  gcs->journal_to(journal);
  robot.announce_ready();
  gcs->announce_ready();
  clock.wait_ready();

  auto robot_tick = [&] {
    ASSERT_NE(robot.begin_tick(), nullptr);
    msgs::Heartbeat h;
    to_gcs.send(h);
    robot.end_tick();
  };
  for (std::uint32_t k = 0; k < 10; ++k) {
    clock.begin_tick(k);
    clock.publish_clock(k, one_robot(), false);
    robot_tick();
    ASSERT_NE(gcs->begin_tick(), nullptr);
    msgs::Heartbeat h;
    from_gcs.send(h);
    gcs->end_tick();
    ASSERT_FALSE(clock.wait_done(k));
  }
  net.disconnect(gcs_bus);  // the process dies at tick 10
  ASSERT_TRUE(clock.is_lost(t.gcs()));
  for (std::uint32_t k = 10; k < 20; ++k) {
    clock.begin_tick(k);
    clock.publish_clock(k, one_robot(), false);
    robot_tick();
    ASSERT_FALSE(clock.wait_done(k));
  }
  const std::vector<std::uint32_t> before = heard;
  ASSERT_EQ(before.size(), 9u);  // stamped 0..8: each is handled the tick after it was sent

  // The new process: the same subscriptions, then the journal, then the run.
  std::vector<std::uint32_t> replayed;
  LockstepAgent again(restarted_bus, t, links, t.gcs());
  again.subscribe<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs,
                                   [&](const msgs::Heartbeat& h) { replayed.push_back(h.header().tick()); });
  auto& from_again = again.advertise<msgs::Heartbeat>("gcs_out", LinkClass::LeaderGcs, {0});
  int steps = 0;
  const std::vector<JournalRestart> r = again.replay_journal(journal, [&](const msgs::Clock&) {
    ++steps;
    msgs::Heartbeat h;
    from_again.send(h);  // muted: the robot must not receive it twice
  });
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].replayed_ticks, 10u);
  EXPECT_EQ(steps, 10);
  EXPECT_EQ(replayed, before);
  EXPECT_EQ(again.traffic().snapshot().size(), 2u);  // the replayed sends and receipts are counted
  again.rejoin();
  again.announce_ready();
  // The clock master admits it at the first clock half a second after its hello (its peers' DDS
  // writers must have matched its readers): tick 20 here.
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  for (std::uint32_t k = 20; k < 30; ++k) {
    clock.begin_tick(k);
    clock.publish_clock(k, one_robot(), false);
    robot_tick();
    const msgs::Clock* c = again.begin_tick();
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->tick(), k);
    EXPECT_EQ(c->counted_from().at(t.gcs()), 20u);
    again.end_tick();
    ASSERT_FALSE(clock.wait_done(k));
  }
  // From tick 21 on it handles the robot's messages stamped from 20 on: none from its outage.
  EXPECT_EQ(replayed.size(), before.size() + 9);
  EXPECT_EQ(replayed.back(), 28u);
  ASSERT_EQ(clock.losses().size(), 1u);
  EXPECT_EQ(clock.losses()[0].tick, 10u);
  EXPECT_EQ(clock.losses()[0].rejoined_tick, 20u);
  EXPECT_TRUE(clock.losses()[0].restarted);
  // The journal now holds the replayed ticks, the restart and the new ticks.
  const JournalContents j = read_journal(journal);
  EXPECT_EQ(j.ticks.size(), 20u);
  ASSERT_EQ(j.restarts.size(), 1u);
  EXPECT_EQ(j.restarts[0].replayed_ticks, 10u);

  // The clock's traffic for watchers: every agent's sent bytes per link class, through the
  // restart (the new process counted its replayed sends, so nothing is lost or counted twice).
  clock.begin_tick(30);
  msgs::RunTally tally;
  tally.vertex_conflicts(3);
  clock.publish_clock(30, one_robot(), false, tally);
  const msgs::Clock* c = again.begin_tick();
  ASSERT_NE(c, nullptr);
  const auto leader_gcs = static_cast<std::size_t>(LinkClass::LeaderGcs);
  ASSERT_EQ(c->sent_bytes().size(), static_cast<std::size_t>(kLinkClasses));
  const std::uint64_t heartbeat = wire_size(msgs::Heartbeat{});
  EXPECT_EQ(robot.traffic().sent_bytes_by_link()[leader_gcs], 30 * heartbeat);
  // The new GCS process counted the 10 sends it replayed from the dead one's journal (muted) and
  // sent none since: its count carries on from the dead process's, which is not added again.
  EXPECT_EQ(again.traffic().sent_bytes_by_link()[leader_gcs], 10 * heartbeat);
  EXPECT_EQ(c->sent_bytes()[leader_gcs], 40 * heartbeat);
  EXPECT_EQ(c->sent_bytes()[static_cast<std::size_t>(LinkClass::MemberLeader)], 0u);
  EXPECT_EQ(c->tally().vertex_conflicts(), 3u);
}

// A bus whose DDS peers are as a stuck secure start-up left them: the simulator discovered but
// never authenticated.
class StuckSecureBus : public FakeBus {
 public:
  using FakeBus::FakeBus;
  std::vector<PeerState> peers() const override {
    return {{"gcs", PeerState::Step::Authenticated, 0.05, 0.10, 1.0},
            {"sim", PeerState::Step::Discovered, 0.04, 0.04, 1.0}};
  }
  bool secure() const override { return true; }
};

// A role whose start-up stalls names the peer it could not authenticate and the step, not only
// the topic that never matched.
TEST(LockstepFake, AStalledStartUpNamesThePeerThatNeverAuthenticated) {
  ::setenv("SWARM_STALL_TIMEOUT", "1", 1);
  const Topology t(1, 1);
  LinkTable links;
  FakeNetwork net;
  StuckSecureBus robot_bus(net);  // no simulator on the network at all
  LockstepAgent robot(robot_bus, t, links, 0);
  try {
    robot.announce_ready();
    FAIL() << "announce_ready returned without a simulator";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "leader-0: DDS discovery did not complete in 1 s; still waiting for the simulator (done, clock). "
                 "DDS peers: gcs: authenticated at 0.10 s; sim: discovered at 0.04 s, not authenticated 0.96 s later");
  }
  ::setenv("SWARM_STALL_TIMEOUT", "2", 1);
}

// An agent that writes and reads one topic (a candidate leader: its member side reads what its
// leader side writes) is matched by itself at once. Its readiness must wait for the other agents'
// endpoints all the same: a peer slow to match (a late DDS-Security handshake) would otherwise
// miss the messages of tick 0, and both would wait at tick 1 for ever.
struct ReadinessProbe : LockstepAgent {
  using LockstepAgent::LockstepAgent;
  using LockstepAgent::outlets_matched;
};

TEST(LockstepFake, AnAgentsOwnEndpointsDoNotMakeItReady) {
  const Topology t(1, 2);  // leader-0 (agent 0) and member-0-1 (agent 1)
  LinkTable links;
  FakeNetwork net;
  FakeBus leader_bus(net);
  ReadinessProbe leader(leader_bus, t, links, 0);
  leader.advertise<msgs::Route>("route_0", LinkClass::MemberLeader, {1});
  leader.subscribe<msgs::Route>("route_0", LinkClass::MemberLeader, [](const msgs::Route&) {},
                                Delivery::Reliable, 1);
  std::string missing;
  EXPECT_FALSE(leader.outlets_matched(&missing));  // only itself on the topic
  EXPECT_EQ(missing, "route_0 (0 of 1 writers)");

  FakeBus member_bus(net);
  ReadinessProbe member(member_bus, t, links, 1);
  member.subscribe<msgs::Route>("route_0", LinkClass::MemberLeader, [](const msgs::Route&) {},
                                Delivery::Reliable, 1);
  EXPECT_FALSE(leader.outlets_matched(&missing));  // the member reads, but writes nothing yet
  EXPECT_EQ(missing, "route_0 (0 of 1 writers)");
  member.advertise<msgs::Route>("route_0", LinkClass::MemberLeader, {0});
  EXPECT_TRUE(leader.outlets_matched(&missing));
  EXPECT_TRUE(member.outlets_matched(&missing));
}

}  // namespace
}  // namespace swarm::comm
