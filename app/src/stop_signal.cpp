#include "swarm/app/stop_signal.hpp"

#include <pthread.h>
#include <signal.h>

#include <mutex>
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

std::shared_ptr<void> StopOnSignal::start(std::function<void()> on_stop) {
  struct Call {
    std::mutex mutex;
    std::function<void()> on_stop;
  };
  auto call = std::make_shared<Call>();
  call->on_stop = std::move(on_stop);
  // Detached: the process leaves by exit_after_work's _Exit, never by joining its threads.
  std::thread([call] {
    const sigset_t set = stop_signals();
    int sig = 0;
    while (sigwait(&set, &sig) != 0) {
    }
    std::lock_guard<std::mutex> lock(call->mutex);
    if (call->on_stop) call->on_stop();
  }).detach();
  // The handle: when it goes, `on_stop` is never called again.
  return std::shared_ptr<void>(nullptr, [call](void*) {
    std::lock_guard<std::mutex> lock(call->mutex);
    call->on_stop = nullptr;
  });
}

}  // namespace swarm::app
