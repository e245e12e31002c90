#include "swarm/app/stop_signal.hpp"

#include <pthread.h>
#include <signal.h>

#include <thread>

namespace swarm::app {
namespace {

sigset_t stop_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

}  // namespace

StopOnSignal::StopOnSignal() {
  const sigset_t set = stop_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

void StopOnSignal::start(std::function<void()> on_stop) {
  // Detached: the process leaves by exit_after_work's _Exit, never by joining its threads.
  std::thread([on_stop = std::move(on_stop)] {
    const sigset_t set = stop_signals();
    int sig = 0;
    while (sigwait(&set, &sig) != 0) {
    }
    on_stop();
  }).detach();
}

}  // namespace swarm::app
