// `swarm view RUN_DIR`: a run replayed in the browser (view_data.hpp, view_server.hpp).
#include <optional>

#include "commands.hpp"
#include "run_input.hpp"
#include "swarm/record/record.hpp"
#include "view_data.hpp"
#include "view_server.hpp"

namespace swarm::tools {

int view_command(const ViewOptions& o, std::ostream& out, std::ostream& err) {
  const std::string me = "swarm view";
  const std::optional<std::vector<swarm::record::Frame>> read = read_run(o.run_dir, me, err);
  if (!read) return 2;
  const std::vector<swarm::record::Frame>& frames = *read;
  std::string why;
  const std::optional<config::World> world = world_of_record(frames.front().header(), o.run_dir, why);
  if (!world) err << me << ": no ground truth to show: " << why << "\n";
  std::string json;
  try {
    json = replay_json(frames, world ? &world->truth : nullptr).dump();
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }
  const ViewRoutes routes = {{"/", {"text/html; charset=utf-8", view_page()}}, {"/run.json", {"application/json", json}}};
  return serve(o.server, routes, out, err);
}

}  // namespace swarm::tools
