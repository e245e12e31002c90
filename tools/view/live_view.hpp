// The live view of a running swarm: a read-only DDS participant in the run's domain and partition
// that keeps the newest of what it reads for the viewer's WebSocket:
//   clock        every robot's cell (/tf), whether it lives and who leads each group (/robots: a
//                lost robot grey, "NAME (lost)"; one that took a group over "NAME (leads group G)";
//                /log: when), and the run's tally (/status: conflicts, blocked moves, the phase's
//                progress, bytes sent per link class)
//   round        the GCS's fused map (/map)
//   phase        phase announcements (/status, /log)
//   motion       each robot's route as commanded, with its pick and drop cells (/routes:
//                route/NAME, picks/NAME, drops/NAME)
//   planned      the routes the GCS planned (cover's division: each robot's whole route over its
//                region; mapf's timed paths with their waits): /routes plan/NAME
//   plan_report  each group's frontier cells and the global segments it chose from (/frontiers)
// /routes and /frontiers send only the robots and groups that changed since a connection's last
// frame (a SceneUpdate entity replaces the one of the same id), so 200 robots stay cheap.
//
// It never writes and never joins the lockstep barrier: the clock master waits only for the run's
// own agents (comm/lockstep.hpp), and the readers' callbacks only copy the newest sample under a
// lock, so the run's reliable writers never wait on it. A run with the view gives the same record
// as without (tests: integration_view).
//
//   LiveView view(setup);                 // joins the domain
//   serve(options, routes, out, err, &view, &stop);
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "foxglove_json.hpp"
#include "live_feed.hpp"
#include "swarm/comm/participant.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm_msgs.h"

namespace swarm::tools {

class LiveView : public LiveFeed {
 public:
  struct Setup {
    comm::DdsOptions dds;
    std::vector<std::string> names;  // robot names by id
    int robots_per_group = 1;
    planner::OccupancyGrid frame;    // the map's size and frame (its cells are not used)
    const planner::OccupancyGrid* truth = nullptr;  // the map file's cells, or none
    std::uint64_t tick_ns = 50'000'000;
    std::string title;  // e.g. "maze1, seed 1, explore"
    nlohmann::json layout = nlohmann::json::array();  // mission_layout(world)
    std::vector<std::string> tasks;                     // the mission's phases' tasks
  };
  // The setup for watching a run of `world` (its map, team and tick length) over `dds`.
  static Setup setup_for(const config::World& world, comm::DdsOptions dds);
  explicit LiveView(Setup setup);
  ~LiveView() override;
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  [[nodiscard]] std::vector<LiveChannel> channels() const override;
  [[nodiscard]] std::vector<LiveMessage> since(std::vector<std::uint64_t>& cursor) const override;
  [[nodiscard]] std::string setup_json() const override;

 private:
  struct Readers;
  struct Route {
    std::uint32_t id = 0;
    std::vector<planner::Cell> cells, picks, drops;
    std::uint64_t version = 0;  // version_ when it changed
  };
  // The entities of one robot's route ("route") or plan ("plan") on /routes.
  void add_route_entities(nlohmann::json& entities, const std::string& kind, std::size_t robot, const Route& r,
                          std::uint64_t ns) const;
  struct Plan {
    std::vector<planner::Cell> frontiers, segments;
    std::uint64_t version = 0;
  };
  void on_clock(const msgs::Clock& c);  // callers hold mutex_
  [[nodiscard]] nlohmann::json status_json() const;
  [[nodiscard]] nlohmann::json routes_since(std::uint64_t seen, std::uint64_t ns) const;
  [[nodiscard]] nlohmann::json frontiers_since(std::uint64_t seen, std::uint64_t ns) const;

  Setup setup_;
  FoxgloveFrame frame_;
  nlohmann::json layout_;  // the mission's fixed objects and drop points (view_data.hpp)
  mutable std::mutex mutex_;
  // The newest of each, with a version that grows when it changes (0: none yet).
  std::uint64_t version_ = 0;  // the last version given out
  std::uint32_t tick_ = 0;
  std::vector<planner::Cell> cells_;
  std::uint64_t cells_version_ = 0;
  msgs::RunTally tally_;
  std::vector<std::uint64_t> sent_bytes_;
  std::vector<bool> lost_;  // per robot: the simulator has it dead
  std::vector<int> took_over_;  // per robot: the group it leads in its first leader's place, or -1
  std::vector<std::uint16_t> leaders_;  // per group, as the latest clock says
  std::uint64_t lost_version_ = 1;
  std::int64_t phase_ = -1;
  std::string task_;
  bool settling_ = false;
  std::vector<Route> routes_;  // per robot
  std::vector<Route> plans_of_;  // per robot: the GCS's plan for it in this phase (id: the phase)
  std::vector<Plan> plans_;    // per group
  std::uint64_t routes_version_ = 0, plans_version_ = 0;
  planner::OccupancyGrid map_;
  std::uint64_t map_tick_ = 0, map_version_ = 0;
  std::vector<std::pair<std::uint64_t, std::string>> log_;  // (ns, text)
  std::unique_ptr<comm::Participant> participant_;
  std::unique_ptr<Readers> readers_;
};

}  // namespace swarm::tools
