// swarm-sim's node: the World driven by the lockstep clock. Each tick it applies the motion
// commands due, moves the robots, sends each robot its scan, publishes the clock, and waits for
// every agent; it stops the run when the GCS declares the mission complete or at max_ticks.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "swarm/comm/lockstep.hpp"
#include "swarm/comm/role.hpp"
#include "swarm/sim/world.hpp"

namespace swarm::sim {

class SimNode {
 public:
  SimNode(comm::LockstepClock& clock, const comm::RoleSetup& setup);
  // The whole run; returns the last tick.
  std::uint32_t run();
  std::string report_json() const;

 private:
  std::vector<msgs::RobotState> states() const;

  comm::LockstepClock& clock_;
  World world_;
  std::uint32_t max_ticks_;
  std::vector<comm::Mailbox::Outlet<msgs::Sense>*> sense_;
  std::optional<std::uint32_t> steps_to_99_;
  std::vector<std::pair<std::uint32_t, double>> curve_;  // (tick, explored fraction)
  std::vector<bool> alive_;
  std::uint32_t last_tick_ = 0;
  bool complete_ = false;
};

}  // namespace swarm::sim
