// SIGINT and SIGTERM as a request, not a death: the simulator ends the run at its current tick
// when the launcher asks it to stop (an interrupt, a timeout, another process failing), so that
// every agent still reports and the GCS writes metrics.json for what was done.
//
//   app::StopOnSignal stop;                   // first, before any thread is started (DDS's too)
//   comm::LockstepClock clock(...);
//   const auto calling = stop.start([&] { clock.request_stop(); });  // until `calling` goes
//
// The constructor blocks both signals in the calling thread, so every thread started after it
// inherits the block; start() waits for them on a thread of its own (sigwait) and calls `on_stop`
// once, as long as the handle it returns lives (declare it after what `on_stop` uses, so it goes
// first). A second signal is not waited for: the launcher ends a process that does not stop with
// SIGKILL.
#pragma once

#include <functional>
#include <memory>

namespace swarm::app {

class StopOnSignal {
 public:
  StopOnSignal();
  [[nodiscard]] std::shared_ptr<void> start(std::function<void()> on_stop);
};

}  // namespace swarm::app
