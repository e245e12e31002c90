// The leader's collection task (issue 10): its group's objects (an Order of object numbers,
// tasks/collect/collect_gcs.hpp) are split among the living robots (each object to the nearest robot with
// room left) and each robot gets a tour from the tour planner (planner/tours/tour.hpp: type by type, the
// distance + angle variant, each type's order searched exactly), driven as a route with its
// pick-up and drop steps. From the robots' progress the leader knows what is picked up and
// delivered. A member lost midway: what it had not delivered (what it carried lies beside it,
// planner::put_down_cell) goes to the living robots, each taking it on in a new tour once its
// current one ends.
// After its tour a robot drives back to its start cell, out of the others' way. A robot whose
// route has not advanced for a while (robots contending for one free cell: the
// simulator refuses both) waits a number of ticks unique to it and goes on, so one goes first.
// When every object of the group is delivered the leader reports the group done.
//
// What it knows of each object goes to the GCS as it changes (Report Working, values = [seq,
// then per object: object, what, a, b], what = collect::kObject*, object_facts.hpp), so that a standby that takes
// the group over (took_over) can resume it: it waits for the GCS's Resume order (the group's
// objects not delivered, as last reported) and for its robots' grippers (on_carrying: members send
// what they hold to a new leader), then believes the grippers first: an object a living robot holds
// is carried by it; one the report says a robot held that holds it no more was delivered (robots
// drop only at their tour's destinations); one a lost robot held lies where the simulator put it
// down (planner::put_down_cell, computed at the take-over from the robots' cells then); any other
// lies where last reported. Then every living robot gets a new tour.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/tasks/collect/collect_world.hpp"
#include "swarm/leader/group_task.hpp"

namespace swarm::leader {

class CollectGroupTask : public GroupTask {
 public:
  // Phase `index` of the mission: its objects and destinations are setup.world.phase_data[index].
  CollectGroupTask(const swarm::scenario::Collect& config, const app::RoleSetup& setup, int group,
                   std::uint32_t index);
  void start(GroupContext& ctx) override;
  void step(GroupContext& ctx) override;
  void on_order(const task::Order& order, GroupContext& ctx) override;
  void on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) override;
  void member_lost(int index, GroupContext& ctx) override;
  void on_carrying(int index, const std::vector<std::uint32_t>& objects, GroupContext& ctx) override;
  void took_over(GroupContext& ctx) override;
  void gcs_back(GroupContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  // What the group knows of the map: the given map (config::map_given) or the group map.
  [[nodiscard]] const planner::OccupancyGrid& known_map(const GroupContext& ctx) const;
  // The map tours are planned on: known_map with lost robots' cells blocked.
  [[nodiscard]] planner::OccupancyGrid planning_map(const GroupContext& ctx) const;
  // A tour for robot `index` over its pending objects, from where it stands.
  void plan(int index, GroupContext& ctx);
  // Robot `index` is stuck: sends it round the robots in its way, or (no way round) the rest of
  // its route after `waits` ticks of waiting.
  void reroute(int index, int waits, GroupContext& ctx);
  void send(int index, GroupContext& ctx, std::vector<planner::Cell> cells);
  // Objects `ids` to the living robots: each to the nearest one with room left.
  void share(const std::vector<int>& ids, GroupContext& ctx);
  // A take-over: the resume order's objects, judged as the header says, then new tours.
  void resume(GroupContext& ctx);
  // What changed since the last report goes to the GCS.
  void report_changes(GroupContext& ctx);

  // Robot `index` has reached `step` of its route: its picks and drops up to there are made.
  void reached(int index, std::uint32_t step);
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
  tasks::CollectWorld world_;
  std::uint32_t seq_ = 0;
  bool have_order_ = false;
  bool reported_ = false;
  std::vector<int> mine_;                 // the group's objects
  std::vector<planner::Cell> where_;      // per object: where it lies (for re-planning)
  std::vector<State> state_;              // per object, as far as the leader knows
  std::vector<int> carrier_;              // per object: the group index of the robot it is on, or -1
  // What the GCS was last told of each object (what, a, b), to report only changes.
  std::vector<std::array<std::int32_t, 3>> told_;
  // Taking over: the resume order (kept until it can be applied), the grippers heard since the
  // take-over, where each robot lost by then left what it held, and from which tick on the
  // members' grippers have been heard (member<->leader delays allowed for).
  bool resuming_ = false;
  std::optional<task::Order> resume_order_;
  std::vector<std::optional<std::vector<std::uint32_t>>> holds_;  // per group index
  std::vector<std::optional<planner::Cell>> put_down_;           // per group index
  std::uint32_t grippers_heard_by_ = 0;
  std::uint64_t resumes_ = 0;
  std::vector<Robot> robots_;
  std::uint64_t reassigned_ = 0;
  std::uint64_t backoffs_ = 0;
  std::uint64_t detours_ = 0;
  static constexpr std::uint32_t kDone = 0xFFFFFFFF;  // a pick or drop step already acted on
};

}  // namespace swarm::leader
