// `swarm run --view`: the live view (live_view.hpp) and its server (view_server.hpp) on a thread of
// their own beside the run, from before its processes start until they have all stopped.
#pragma once

#include <atomic>
#include <memory>
#include <ostream>
#include <thread>

#include "run_launch.hpp"

namespace swarm::tools {

class LiveView;

class LiveRunView {
 public:
  LiveRunView();
  ~LiveRunView();  // stop()s
  // Joins the run's domain and starts serving: 0 once the page can be opened; 2 when the address
  // cannot be listened on (the run should not start), 1 when the DDS participant cannot be made,
  // with a message on `err`.
  int start(const RunOptions& options, const PreparedRun& run, std::ostream& out, std::ostream& err);
  void stop();

 private:
  std::unique_ptr<LiveView> view_;
  std::thread server_;
  std::atomic<bool> stop_{false}, listening_{false}, ended_{false};
  int status_ = 0;
};

}  // namespace swarm::tools
