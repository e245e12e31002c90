#include "swarm/app/fault_injection.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <ctime>
#include <iostream>

namespace swarm::app {

FaultInjector::FaultInjector(const swarm::scenario::Scenario& scenario, const std::string& agent) : agent_(agent) {
  for (const auto& f : scenario.faults()) {
    if (f.agent() != agent) continue;
    if (f.has_kill_at_tick()) kill_at_ = f.kill_at_tick();
    if (f.has_freeze_at_tick()) {
      freeze_at_ = f.freeze_at_tick();
      freeze_seconds_ = f.freeze_seconds();
    }
  }
}

void FaultInjector::at_tick(std::uint32_t tick) {
  if (kill_at_ && tick >= *kill_at_) crash_now(agent_, tick);
  // ">=": in real time an agent may skip ticks, the one named included.
  if (freeze_at_ && !frozen_ && tick >= *freeze_at_) {
    frozen_ = true;
    freeze_now(agent_, tick, freeze_seconds_);
  }
}

void crash_now(const std::string& who, std::uint32_t tick) {
  std::cerr << who << ": crashing at tick " << tick << " (fault injection: kill)" << std::endl;
  std::raise(SIGKILL);
  std::abort();
}

void freeze_now(const std::string& who, std::uint32_t tick, double seconds) {
  std::cerr << who << ": freezing at tick " << tick << " for " << seconds << " s (fault injection: freeze)"
            << std::endl;
  const pid_t self = ::getpid();
  const pid_t waker = ::fork();
  if (waker < 0) {
    std::cerr << who << ": cannot fork the waker; not freezing" << std::endl;
    return;
  }
  if (waker == 0) {
    // The child of a multi-threaded process: async-signal-safe calls only.
    timespec left{static_cast<time_t>(seconds), static_cast<long>(std::fmod(seconds, 1.0) * 1e9)};
    while (::nanosleep(&left, &left) < 0 && errno == EINTR) {
    }
    ::kill(self, SIGCONT);
    ::_exit(0);
  }
  ::kill(self, SIGSTOP);  // stops every thread of this process until the waker's SIGCONT
  while (::waitpid(waker, nullptr, 0) < 0 && errno == EINTR) {
  }
  std::cerr << who << ": resumed after the freeze" << std::endl;
}

}  // namespace swarm::app
