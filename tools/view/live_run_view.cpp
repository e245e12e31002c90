#include "live_run_view.hpp"

#include <chrono>

#include "live_view.hpp"
#include "observer_dds.hpp"
#include "view_server.hpp"

namespace swarm::tools {

LiveRunView::LiveRunView() = default;
LiveRunView::~LiveRunView() { stop(); }

int LiveRunView::start(const RunOptions& options, const PreparedRun& run, std::ostream& out, std::ostream& err) {
  const RunLaunch& l = run.launch;
  comm::DdsOptions dds = observer_dds("swarm-view", l.domain_id, l.partition, l.dds_profile, l.discovery_server);
  dds.security_dir = l.security_dir;  // --secure: the watcher's read-only certificate (make-certs.sh)
  dds.identity = kViewerIdentity;
  LiveView::Setup setup = LiveView::setup_for(run.world, std::move(dds));
  try {
    view_ = std::make_unique<LiveView>(std::move(setup));
  } catch (const std::exception& e) {
    err << "swarm run: the live view cannot join the run's DDS domain: " << e.what() << "\n";
    return 1;
  }
  ViewServerOptions server;
  server.bind = options.view_bind;
  server.port = options.view_port;
  server_ = std::thread([this, server, &out, &err] {
    const ViewRoutes routes = {{"/", {"text/html; charset=utf-8", view_page()}},
                               {"/live.json", {"application/json", view_->setup_json()}}};
    status_ = serve(server, routes, out, err, view_.get(), &stop_, &listening_);
    ended_.store(true);
  });
  while (!listening_.load() && !ended_.load()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (ended_.load()) {
    server_.join();
    return status_ != 0 ? status_ : 1;
  }
  out << "swarm run: to watch from another shell: swarm view --attach --scenario " << l.scenario_path << " --domain "
      << l.domain_id << " --partition " << l.partition
      << (l.discovery_server.empty() ? "" : " --discovery-server " + l.discovery_server)
      << (l.security_dir.empty() ? "" : " --security-dir " + l.security_dir) << " --view-port " << options.view_port + 1
      << std::endl;
  return 0;
}

void LiveRunView::stop() {
  stop_.store(true);
  if (server_.joinable()) server_.join();
  view_.reset();
}

}  // namespace swarm::tools
