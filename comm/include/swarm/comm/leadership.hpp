// Who leads each group, tick by tick: a group survives its leader (docs/design.md "Faults").
//
// The succession rule (next_leaders): a group keeps its leader while the clock shows that robot
// alive. When it is lost, the living candidate of lowest index (topology.hpp: indices
// 0..standbys) takes over, and keeps the group even when the old leader comes back: that one then
// serves as a member, so two robots never lead one group at one tick. A group with no living
// candidate stays with its lost leader (leaderless) until a candidate comes back.
//
// The clock master applies the rule and writes the result into every Clock (leaders[g]): every
// process reads the same answer for the same tick, however late it processes that tick (a frozen
// process catching up included), instead of each keeping the loss history itself.
//
// LeaderLog: the leaderships a process has seen in the clocks it processed, to judge a message by
// the tick it was sent at: a robot's message counts as its group leader's only if that robot led
// the group at the message's stamp tick (a deposed leader's late messages are dropped). In real
// time a process that fell behind skips clocks; for a tick it skipped across a change of leader
// it cannot tell which of the two led, and accepts both.
//
//   LeaderLog log(topology);
//   log.observe(clock);                                  // every tick, in order
//   if (!log.led_at(msg.header().sender(), msg.header().tick())) drop(msg);
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/comm/topology.hpp"
#include "swarm_msgs.h"

namespace swarm::comm {

// The leaders at the next tick, from the current ones and the robots' alive flags (per robot id).
std::vector<AgentId> next_leaders(const Topology& t, const std::vector<AgentId>& current,
                                  const std::vector<msgs::RobotState>& robots);

// Group `group`'s leader in `clock` (a clock without leaders, a test's hand-made one: the first).
AgentId leader_in(const msgs::Clock& clock, const Topology& t, int group);

class LeaderLog {
 public:
  explicit LeaderLog(const Topology& t);
  // A clock without leaders (a test's hand-made clock) leaves them as they were; one seen already
  // changes nothing (a handler may observe the current clock before the step does).
  void observe(const msgs::Clock& clock);

  AgentId leader(int group) const { return current_[static_cast<std::size_t>(group)]; }
  const std::vector<AgentId>& leaders() const { return current_; }
  // Whether `robot` led its group at `tick` (ticks after the latest clock: as at the latest).
  bool led_at(AgentId robot, std::uint32_t tick) const;

  struct Change {
    int group = 0;
    AgentId from = 0;
    AgentId to = 0;
    std::uint32_t tick = 0;   // the first clock seen with `to` leading
    std::uint32_t after = 0;  // the last clock seen before it (tick - 1 unless clocks were skipped)
  };
  const std::vector<Change>& changes() const { return changes_; }

 private:
  Topology topology_;
  std::optional<std::uint32_t> last_tick_;
  std::vector<AgentId> current_;
  std::vector<Change> changes_;
};

}  // namespace swarm::comm
