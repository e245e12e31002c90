// The live view of a running swarm: a read-only DDS participant in the run's domain and partition
// that reads the simulator's clock (every robot's cell, each tick), the GCS's round starts (its
// fused map) and phase announcements, and keeps the newest of each for the viewer's WebSocket. A
// robot the clock says is dead is marked lost (/robots: grey, "NAME (lost)"; /log: when).
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

#include "foxglove_json.hpp"
#include "live_feed.hpp"
#include "swarm/comm/participant.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/planner/grid/grid.hpp"

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
  Setup setup_;
  FoxgloveFrame frame_;
  mutable std::mutex mutex_;
  // The newest of each, with a version that grows when it changes (0: none yet).
  std::uint32_t tick_ = 0;
  std::vector<planner::Cell> cells_;
  std::uint64_t cells_version_ = 0;
  std::vector<bool> lost_;  // per robot: the simulator has it dead
  std::uint64_t lost_version_ = 1;
  planner::OccupancyGrid map_;
  std::uint64_t map_tick_ = 0, map_version_ = 0;
  std::vector<std::pair<std::uint64_t, std::string>> log_;  // (ns, text)
  std::unique_ptr<comm::Participant> participant_;
  std::unique_ptr<Readers> readers_;
};

}  // namespace swarm::tools
