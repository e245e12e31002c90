// The leader's coverage task (issue 8): its group's share of the map (an Order from the GCS,
// tasks/cover/cover_gcs.hpp) is divided among the group's living robots with DARP, from where they stand,
// and each robot gets a route that covers its region (spanning-tree coverage, or plowing /
// Group-k: the scenario's cover.order), which it follows exactly. In the flat variant the GCS
// sends the routes themselves.
//
// Then the leader keeps the group going: it follows coverage from the robots' cells in the clock
// (a cell covered by any robot counts); a robot whose route stalls (another robot in its way for
// cover.stall_ticks ticks) gets a detour; when a member is lost, or comes back, the still-uncovered
// cells of the share are divided again among the living robots from where they are, while they
// keep driving; when every robot's route has ended with cells still uncovered, those go to the
// nearest robots; and when the share is covered the leader reports the group done.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/leader/group_task.hpp"
#include "swarm/planner/coverage/coverage_tracker.hpp"
#include "swarm/planner/coverage/cover_routes.hpp"

namespace swarm::leader {

class CoverGroupTask : public GroupTask {
 public:
  CoverGroupTask(const swarm::scenario::Cover& config, const app::RoleSetup& setup, int group);
  void start(GroupContext& ctx) override;
  void step(GroupContext& ctx) override;
  void on_order(const task::Order& order, GroupContext& ctx) override;
  void on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) override;
  void member_lost(int index, GroupContext& ctx) override;
  void member_back(int index, GroupContext& ctx) override;
  void gcs_back(GroupContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  // Divides the share's uncovered cells among the living robots and sends each its route.
  void divide(GroupContext& ctx, const char* why);
  void send(GroupContext& ctx, int index, std::vector<planner::Cell> route);

  struct Robot {
    std::uint32_t route_id = 0;
    std::vector<planner::Cell> route;
    std::uint32_t step = 0;
    planner::RouteState state = planner::RouteState::None;
    std::uint32_t moved_tick = 0;  // when its step last changed
    bool busy() const { return state == planner::RouteState::Active; }
  };

  swarm::scenario::Cover config_;
  std::uint64_t seed_;
  int group_;
  int footprint_;
  bool have_share_ = false;
  std::uint32_t order_seq_ = 0;
  std::uint32_t tick_ = 0;
  planner::OccupancyGrid known_;
  std::vector<std::uint8_t> share_;
  planner::CoverageTracker tracker_;
  std::vector<Robot> robots_;
  bool reported_done_ = false;
  std::uint32_t divisions_count_ = 0;
  std::uint64_t detours_ = 0;   // stalled robots sent round a robot in the way
  std::uint64_t backoffs_ = 0;  // stalled robots told to wait (no way round)
  std::uint64_t leftover_rounds_ = 0;
  std::uint32_t last_leftover_tick_ = 0;
  nlohmann::json divisions_ = nlohmann::json::array();
};

}  // namespace swarm::leader
