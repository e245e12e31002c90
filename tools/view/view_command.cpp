// `swarm view RUN_DIR`: a run replayed in the browser (view_data.hpp, view_server.hpp).
#include <filesystem>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "run_input.hpp"
#include "swarm/record/record.hpp"
#include "live_view.hpp"
#include "observer_dds.hpp"
#include "view_data.hpp"
#include "view_server.hpp"

namespace swarm::tools {

namespace {

int attach(const ViewOptions& o, std::ostream& out, std::ostream& err) {
  const std::string me = "swarm view --attach";
  config::World world;
  try {
    world = config::resolve_world(config::load_scenario(o.scenario_path),
                                  std::filesystem::path(o.scenario_path).parent_path().string());
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }
  comm::DdsOptions dds = observer_dds("swarm-view", o.domain, o.partition, o.profile, o.discovery_server);
  if (!o.security_dir.empty()) {
    for (const std::string& file : {o.identity + ".pem", o.identity + ".key", std::string("ca.pem"), std::string("permissions.p7s")}) {
      if (!std::filesystem::exists(std::filesystem::path(o.security_dir) / file)) {
        err << me << ": --security-dir " << o.security_dir << " has no " << file
            << " (make one with scripts/make-certs.sh DIR --read-only " << o.identity << ", with the swarm's CA in DIR)\n";
        return 2;
      }
    }
    dds.security_dir = o.security_dir;
    dds.identity = o.identity;
  }
  std::unique_ptr<LiveView> view;
  try {
    view = std::make_unique<LiveView>(LiveView::setup_for(world, std::move(dds)));
  } catch (const std::exception& e) {
    err << me << ": cannot join domain " << o.domain << ": " << e.what() << "\n";
    return 1;
  }
  out << me << ": domain " << o.domain << ", partition '" << o.partition << "'"
      << (o.discovery_server.empty() ? "" : ", discovery server " + o.discovery_server)
      << (o.security_dir.empty() ? "" : ", DDS-Security as " + o.identity) << "\n";
  const ViewRoutes routes = {{"/", {"text/html; charset=utf-8", view_page()}},
                             {"/live.json", {"application/json", view->setup_json()}}};
  return serve(o.server, routes, out, err, view.get());
}

}  // namespace

int view_command(const ViewOptions& o, std::ostream& out, std::ostream& err) {
  if (o.attach) return attach(o, out, err);
  const std::string me = "swarm view";
  const std::optional<std::vector<swarm::record::Frame>> read = read_run(o.run_dir, me, err);
  if (!read) return 2;
  const std::vector<swarm::record::Frame>& frames = *read;
  std::string why;
  const std::optional<config::World> world = world_of_record(frames.front().header(), o.run_dir, why);
  if (!world) err << me << ": no ground truth to show: " << why << "\n";
  std::string json;
  try {
    json = replay_json(frames, world ? &world->truth : nullptr, world ? mission_layout(*world) : nlohmann::json::array()).dump();
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }
  const ViewRoutes routes = {{"/", {"text/html; charset=utf-8", view_page()}}, {"/run.json", {"application/json", json}}};
  return serve(o.server, routes, out, err);
}

}  // namespace swarm::tools
