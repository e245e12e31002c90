// The leader's multi-agent path-finding task (issue 9): its robots drive the GCS's plan
// (tasks/mapf/mapf_gcs.hpp: the contract of the messages) by the plan's action-dependency graph
// (planner/mapf/adg.hpp).
//
// With the plan, the leader builds the graph for ALL planned robots (every leader builds the same
// one) and sends each of its robots its route without the waits, released only as far as the
// graph allows. Each tick it learns progress: every planned robot's from its cell in the clock
// (robot positions are shared in real time, docs/design.md), its own robots' also from their
// RouteProgress and the other groups' from the GCS's relay (which only confirm it: a robot whose
// look was missed, or a plan taken late, catches up through them); whenever a robot of its own
// may go further it sends a RouteRelease. It reports its own robots' progress and releases to the
// GCS (for the other leaders), Done when they have all arrived, and after a hold, Held once they
// all stand at their release. Late knowledge only makes robots wait longer: never collide, never
// deadlock (the graph of a valid plan has no cycle; rotations go as one step, planner/mapf/adg.hpp).
// With `execution: MAPF_EXECUTE_TIMED` each robot instead gets its whole timed path (waits
// included), released at once, to set off at the plan's start tick (the order's values[0]); a
// hold then stops them where they stand (an empty route each), and Held follows once the
// simulator has confirmed every stop.
// A standby that takes the group over mid-plan (took_over) cannot know how far each robot got
// along the old leader's routes, nor which releases are still on their way: it takes the plan
// without sending it, stops each of its robots where it stands (an empty route, which the
// simulator confirms as Stopped; timed, at the GCS's hold, with every other group) and reports
// Held once all have stopped; the GCS, which holds a plan whose group changed leader, then plans
// again from where every robot stands. A rotation ordered for a tick still to come goes first:
// its robots get their step of it (the other groups' robots make theirs then) and stand after it.
// A planned route's pick-up and drop steps (the traffic layer's collect stops) go with the route
// its robot drives, moved to the step the robot stands on at that time of the plan. Each report
// says how far a robot's acts are made: past its route's first step, as far as it got; on that
// step, once its member confirms the simulator took the part that carries the act (a robot lost
// before never made it). Done waits for them.
// A window that continues the plan (the traffic layer's next one, sent while this one is driven)
// is appended to every robot's timed path and the graph is built again over the grown plan: its
// old steps keep their needs and numbers, so progress and releases carry over, and each robot gets
// its route again under the same id, longer (member::RobotAgent::follow), driving on without a
// stop. A window that comes before the one it continues (jitter, a lost order sent again) waits
// for it, and so does a relay of progress for a plan not yet taken.
// No robot is released, nor its watch opened, past the limit the GCS relays with progress (a
// plan's first window is released whole): the GCS may cut the plan there. A window that starts
// before the plan's end cuts it there; every robot whose route changed gets it under a new id
// that replaces its earlier ones (task::Route::replaces), the same as far as it may have got, and
// drives on from where it stands.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "swarm/leader/group_task.hpp"
#include "swarm/planner/mapf/adg.hpp"
#include "swarm/planner/mapf/release_watch.hpp"

namespace swarm::leader {

class MapfGroupTask : public GroupTask {
 public:
  MapfGroupTask(const swarm::scenario::Mapf& config, int group);
  void start(GroupContext& ctx) override;
  void step(GroupContext& ctx) override;
  void on_order(const task::Order& order, GroupContext& ctx) override;
  void on_progress(int index, const planner::RouteProgress& p, GroupContext& ctx) override;
  void on_carrying(int index, const std::vector<std::uint32_t>& objects, GroupContext& ctx) override;
  void took_over(GroupContext&) override { adopting_ = true; }
  void gcs_back(GroupContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

  static constexpr std::uint32_t kRefreshTicks = 16;  // the whole report again, this often
  // How many gates a release's watch carries (planner/mapf/release_watch.hpp): enough for a
  // member to follow another through an aisle while the next release is on a delayed link.
  static constexpr std::size_t kWatchGates = 8;

 private:
  void take_plan(const task::Order& order, GroupContext& ctx);
  // Appends a continuing window (Work with kContinues) to the plan; false if it does not fit it.
  bool extend_plan(const task::Order& order, GroupContext& ctx);
  // Takes what waited for the plan just taken: continuations of it, progress relayed for it.
  void take_waiting(GroupContext& ctx);
  void take_progress(const std::vector<std::int32_t>& values);
  // How far robot k may drive now: as the graph allows, not past the limit.
  [[nodiscard]] std::uint32_t releasable(int k) const;
  // Robot k's route from its step `from` on, released as far as it is, with its acts still ahead.
  [[nodiscard]] task::Route route_from(std::size_t k, std::uint32_t from) const;
  // A seq of the current plan (its first window's up to its latest).
  [[nodiscard]] bool in_plan(std::uint32_t seq) const { return have_plan_ && seq >= chain_first_ && seq <= seq_; }
  // Every planned robot's progress as far as its cell in the clock shows it (robot positions are
  // shared in real time): a robot of another group is known to have left a cell the tick it did,
  // not once its leader's report has come round through the GCS.
  void see_positions(const GroupContext& ctx);
  // Sends a release to every robot of the group that may now go further.
  void release(GroupContext& ctx);
  void note(int k);  // robot k's progress, release and acts made go into the next report
  // How far robot k's acts are made: those at its route's steps below this (task contract,
  // tasks/mapf/mapf_gcs.hpp); and whether all of them are.
  [[nodiscard]] std::uint32_t acted(std::size_t k) const;
  [[nodiscard]] bool acts_done(std::size_t k) const;
  // Rotate order: this group's robots of rotation q make their step of it at `tick`.
  void rotate(int q, std::uint32_t tick, GroupContext& ctx);

  bool timed_;
  int group_;
  std::uint32_t seq_ = 0;
  std::uint32_t chain_first_ = 0;  // the seq of the plan's first window
  bool have_plan_ = false;
  std::vector<task::Order> waiting_;  // continuations and progress relays ahead of their plan
  std::vector<planner::mapf::Path> paths_;  // per plan index: the timed path (grown by continuations)
  bool holding_ = false;
  // The plan's time no robot is released past (the GCS's, relayed with progress): the GCS may cut
  // the plan there (tasks/mapf/mapf_gcs.hpp).
  std::uint32_t limit_ = 0;
  planner::mapf::Dependencies adg_;
  std::vector<std::vector<planner::Cell>> routes_;  // per plan index: what the robot drives
  // per plan index: the steps of its route at which the robot picks up / drops (the planned
  // route's, in steps of what it drives)
  std::vector<std::vector<std::uint32_t>> picks_, drops_;
  std::vector<int> robot_of_;                 // plan index -> robot id
  std::vector<int> index_of_;                 // plan index -> group index (-1: another group's)
  std::vector<std::uint32_t> progress_;       // per plan index: the route step it is known at
  std::vector<std::uint32_t> released_;       // per plan index: how far it may drive
  std::vector<std::uint32_t> acted_;          // per plan index (own robots): as its member confirmed
  // per plan index (own robots): the gates' releases of the watch last sent with a release
  std::vector<std::vector<std::uint32_t>> watched_;
  std::vector<std::uint32_t> route_id_;       // per plan index (own robots)
  // per plan index (own robots): the tick its route under route_id_ sets off at (0: at once). A
  // route grown by the next window keeps it: under jitter the grown version can reach the member
  // before the route it grows, and a rotation's robot that set off early would run into the robot
  // whose cell it takes.
  std::vector<std::uint32_t> route_start_;
  // per plan index (own robots): the first id of its routes from step base_ on (the routes that
  // grow or cut it replace from there)
  std::vector<std::uint32_t> first_route_;
  // per plan index (own robots): the route step its current route message starts at (a rotation
  // sends the rest of the route anew, with its start tick)
  std::vector<std::uint32_t> base_;
  std::vector<int> own_;                      // plan indices of this group's robots
  std::vector<std::int32_t> report_;          // (robot, step, release) triples to report
  // Taking over: the replayed orders build the plan's state but send nothing (adopting_); then
  // every own robot is stopped (so are they on a hold of a timed plan), and the robots whose stop
  // is not yet confirmed are `stopping_`.
  bool adopting_ = false;
  std::vector<int> stopping_;  // plan indices
  bool stopped_all_ = false;   // after a take-over: every own robot confirmed stopped
  // `except`: per plan index, robots not to stop (a rotation's, adopt_rotations).
  void stop_own_robots(GroupContext& ctx, const std::vector<bool>& except = {});
  // Taking over: the rotations ordered for this tick or later (kept from the replayed orders) are
  // sent to this group's robots; returns, per plan index, the robots that make a step of them.
  std::vector<bool> adopt_rotations(GroupContext& ctx);
  std::vector<std::pair<int, std::uint32_t>> adopted_rotations_;  // (rotation, tick), replayed
  bool reported_done_ = false;
  bool reported_held_ = false;
  // The grippers' word on the pick-ups (Report kPickResults, tasks/mapf/mapf_gcs.hpp): per group
  // index, what the robot holds as its member last said (with its progress, in the same message);
  // per plan index, how far its pick-ups are told, and the last told (sent again with the whole
  // state: a report can be lost); the entries not yet sent.
  void tell_picks(std::size_t k);
  std::vector<std::vector<std::uint32_t>> grippers_;
  std::vector<std::uint32_t> picks_told_;
  std::vector<std::vector<std::int32_t>> last_pick_told_;
  std::vector<std::int32_t> pick_results_;
  std::uint64_t releases_sent_ = 0;
  std::uint64_t watches_sent_ = 0;
  std::uint64_t plans_taken_ = 0;
  std::uint64_t plans_continued_ = 0;
  std::uint64_t plans_cut_ = 0;
};

}  // namespace swarm::leader
