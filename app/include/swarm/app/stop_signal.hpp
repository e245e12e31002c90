// SIGINT and SIGTERM as a request, not a death: the simulator ends the run at its current tick
// when the launcher asks it to stop (an interrupt, a timeout, another process failing), so that
// every agent still reports and the GCS writes metrics.json for what was done.
//
//   app::StopOnSignal stop;                   // first, before any thread is started (DDS's too)
//   comm::LockstepClock clock(...);
//   stop.start([&] { clock.request_stop(); });
//
// The constructor blocks both signals in the calling thread, so every thread started after it
// inherits the block; start() waits for them on a thread of its own (sigwait) and calls `on_stop`
// once. A second signal is not waited for: the launcher ends a process that does not stop with
// SIGKILL.
#pragma once

#include <functional>

namespace swarm::app {

class StopOnSignal {
 public:
  StopOnSignal();
  void start(std::function<void()> on_stop);
};

}  // namespace swarm::app
