// The leader's collection task (issue 10): its group's objects (a TaskOrder of object numbers,
// gcs/collect_task.hpp) are split among the living robots (each object to the nearest robot with
// room left) and each robot gets a tour from the tour planner (planner/tour.hpp: type by type, the
// distance + angle variant, each type's order searched exactly), driven as a route with its
// pick-up and drop steps. From the robots' progress the leader knows what is picked up and
// delivered. A member lost midway: what it had not delivered (what it carried lies beside it,
// planner::put_down_cell) goes to the living robots, each taking it on in a new tour once its
// current one ends.
// After its tour a robot drives back to its start cell, out of the others' way. A robot whose
// route has not advanced for a while (robots contending for one free cell: the
// simulator refuses both) waits a number of ticks unique to it and goes on, so one goes first.
// When every object of the group is delivered the leader reports the group done.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/leader/group_task.hpp"

namespace swarm::leader {

class CollectGroupTask : public GroupTask {
 public:
  CollectGroupTask(const swarm::scenario::Collect& config, const comm::RoleSetup& setup, int group, bool map_given);
  void start(GroupContext& ctx) override;
  void step(GroupContext& ctx) override;
  void on_order(const msgs::TaskOrder& order, GroupContext& ctx) override;
  void on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) override;
  void member_lost(int index, GroupContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  // A tour for robot `index` over its pending objects, from where it stands.
  void plan(int index, GroupContext& ctx);
  // Robot `index` is stuck: sends it round the robots in its way, or (no way round) the rest of
  // its route after `waits` ticks of waiting.
  void reroute(int index, int waits, GroupContext& ctx);
  void send(int index, GroupContext& ctx, std::vector<planner::Cell> cells);

  struct Robot {
    std::uint32_t route_id = 0;
    std::uint32_t step = 0;
    std::uint32_t moved_tick = 0;     // when its step last changed
    std::vector<planner::Cell> cells;  // its route
    bool busy = false;
    std::vector<int> pending;                              // objects to take on in its next tour
    std::vector<std::pair<int, std::uint32_t>> picks;      // (object, route step) of its tour
    std::vector<std::pair<int, std::uint32_t>> delivers;   // (object, route step of its drop)
    double length_cells = 0;
    int rotation_eighths = 0;
    int tours = 0;
  };
  enum class State : std::uint8_t { Waiting, Carried, Delivered };

  int group_;
  bool map_given_;
  config::CollectWorld world_;
  std::uint32_t seq_ = 0;
  bool have_order_ = false;
  bool reported_ = false;
  std::vector<int> mine_;                 // the group's objects
  std::vector<planner::Cell> where_;      // per object: where it lies (for re-planning)
  std::vector<State> state_;              // per object, as far as the leader knows
  std::vector<Robot> robots_;
  std::uint64_t reassigned_ = 0;
  std::uint64_t backoffs_ = 0;
  std::uint64_t detours_ = 0;
  static constexpr std::uint32_t kDone = 0xFFFFFFFF;  // a pick or drop step already acted on
};

}  // namespace swarm::leader
