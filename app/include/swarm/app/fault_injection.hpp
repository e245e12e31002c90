// A robot process's own scheduled faults (scenario `faults`, or `swarm run --kill/--freeze`),
// applied at the start of a tick, before the robot acts:
//   kill   - the process dies as if SIGKILLed: the others must notice and go on without it;
//   freeze - the whole process (DDS's threads too) stops for some seconds of wall time, then
//            resumes: to its peers it is exactly a robot whose network was cut, so they declare it
//            lost, keep what they send it queued in DDS, and re-admit it when it speaks again.
// (`cut`, by contrast, is link emulation inside comm/: see link.hpp.)
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "swarm/config/scenario.hpp"

namespace swarm::app {

class FaultInjector {
 public:
  // The faults of `scenario` that name `agent` ("member-1-2", "leader-0").
  FaultInjector(const swarm::scenario::Scenario& scenario, const std::string& agent);
  // Crashes or freezes when a fault is due at `tick`; returns after a freeze.
  void at_tick(std::uint32_t tick);
  // Whether any fault names this agent (both act on the whole process).
  bool any() const { return kill_at_.has_value() || freeze_at_.has_value(); }

 private:
  std::string agent_;
  std::optional<std::uint32_t> kill_at_;
  std::optional<std::uint32_t> freeze_at_;
  double freeze_seconds_ = 0;
  bool frozen_ = false;
};

// The process crashes as a SIGKILL would, after saying so on stderr.
[[noreturn]] void crash_now(const std::string& who, std::uint32_t tick);
// The process stops (SIGSTOP, every thread) and a forked waker resumes it after `seconds`.
void freeze_now(const std::string& who, std::uint32_t tick, double seconds);

}  // namespace swarm::app
