// The lockstep protocol on the in-process FakeBus: the same LockstepClock and LockstepAgent code
// as over DDS, stepped in one thread.
#include <gtest/gtest.h>

#include <cstdlib>
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

}  // namespace
}  // namespace swarm::comm
