// The GCS's multi-agent path-finding task (issue 9; docs/papers.md section 3; planner/mapf/): every
// living robot drives to its goal cell, and no two robots ever meet.
//
// How the plan is conflict-free across groups: the GCS plans for ALL living robots at once (one
// MAPF instance; ECBS by default, config Mapf.solver) on the known map (the map file when the
// mission starts with mapf, else the fused map), with the cells of robots it does not plan for (lost,
// or in a group without its leader) as obstacles. The plan goes to every leader in one order.
//
// How it is driven under link delay: by its action-dependency graph (planner/mapf/adg.hpp;
// tasks/mapf/mapf_leader.hpp): a robot enters a cell only after the robots planned there before it have
// left, as its leader learns from their progress. A leader knows its own members' progress from
// their RouteProgress; the others' it learns from the GCS, which relays what every leader reports.
//
// Messages (the task's contract over task::Order / task::Report, app/task_messages.hpp):
//   Order Work, group kAllGroups, seq s: routes = the planned robots' timed paths (one cell per
//     tick, waits included); timed execution (Mapf.execution): values = [the start tick every
//     robot sets off at].
//   Order Work, seq s, values = [kContinues, f, T] (lifelong, by the graph): the plan f..s-1 grows
//     by a window: routes = the same robots, in the same order, from time T of the plan (its end,
//     where each robot's path ends) on. The plan is then seq s, its robots' progress and releases
//     count along the grown routes, and reports and relays of seqs f..s still hold for it.
//   Report (leader -> GCS): values = [s, robot, step, release, acted, robot, ...] for its robots
//     whose progress, release or acts changed; acted: the robot's picks and drops at its route's
//     steps below it are made (planner::RouteProgress::acted); state Done when all its robots of
//     plan s have arrived and made their acts; Held after a hold when they all stand still.
//   Report (leader -> GCS), values = [kPickResults, robot, x, y, n, o_1 .. o_n, robot, ...]: the
//     gripper's word on a pick-up: robot `robot`, its pick-up at cell (x, y) made, holds the n
//     objects o_i (what its member said with the progress that made it; none for a pick-up
//     followed by a drop before the member said so). Sent once, and again with the whole state.
//   Order Progress, kAllGroups: values = [s, L, robot, step, release, acted, ...], relayed; L, the
//     limit: no robot is to be released past the plan's time L (its first window is released
//     whole). The GCS raises L as the robots progress, always far enough ahead that none waits on
//     it, and may cut the plan at any time from the highest L it has sent (lifelong: a new
//     round's waypoints then follow from there, not from the plan's end).
//   Order Work, seq s, values = [kContinues, f, T] with T before the plan's end: the plan is cut
//     at T and grows from there; the robots whose routes change get them under a new id that
//     replaces the old (task::Route::replaces), the same as far as any may have got.
//   Order Hold, seq s: stop releasing plan s; each leader stops its robots where they stand (an
//     empty route each: a robot's release may reach windows ahead, and its member may open its
//     route further by itself, planner/mapf/release_watch.hpp); Held once all are confirmed.
//   Order Rotate, kAllGroups, seq s: values = [s, q, T]: the robots of the plan's
//     rotation q (planner/mapf/adg.hpp: robots moving round a cycle of cells in one time step)
//     make their step of it at tick T, all together. Driven by the graph, leaders never release a
//     rotation themselves: they learn of their releases in different ticks, and a robot that moved
//     early would run into one that has not left. The GCS knows every robot's progress (the
//     leaders' reports), so it names the rotations that may go, with a start tick late enough for
//     the order to reach every leader, its route every member and each robot's command the
//     simulator, which holds it for that tick (configured delays and jitter, and lost
//     transmissions repeated until one is later still only once in 100,000: comm/link.hpp).
// The first plan is made at the phase's start, from where the robots stand (a phase after another
// starts once they all stand still: gcs/gcs_node.hpp).
// A planned robot lost midway, or a group's leader replaced by its standby: the GCS holds the
// plan (every robot stops where it stands), waits until every group reports its robots still, and
// plans again from where the living robots stand (seq s + 1).
// Complete when every group of the current plan has reported Done; given up when a plan cannot be
// made (proven infeasible, or none within the time limit): the mission ends there, incomplete.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "swarm/gcs/gcs_task.hpp"
#include "swarm/planner/mapf/adg.hpp"
#include "swarm/planner/mapf/result.hpp"
#include "swarm/planner/traffic/traffic.hpp"

namespace swarm::gcs {

// The traffic planner's settings for a phase of a run: one seed per phase, so that a rehearsal of
// the layer (planner/traffic/rehearsal.hpp) plans what the driver will.
planner::traffic::Config traffic_config(std::uint64_t seed, std::uint32_t phase);
// What the layer plans a window on, from where the robots stand: `known` with every robot's cell
// free (a fused map may not have seen a cell under a robot) ...
planner::OccupancyGrid layer_map(const GcsContext& ctx, planner::OccupancyGrid known);
// ... and every robot standing still at its cell but those in `moving`, each given its goals
// (goals[r], in order). The driver plans with these, and a rehearsal must too to plan the same.
std::vector<planner::traffic::Agent> layer_agents(const GcsContext& ctx, const std::vector<int>& moving,
                                                  const std::vector<std::vector<planner::Cell>>& goals);
// Order Work's first value for a window that continues a plan (see the contract above).
inline constexpr std::int32_t kContinues = -1;
// A Report's first value for the grippers' word on pick-ups (see the contract above).
inline constexpr std::int32_t kPickResults = -2;

class MapfGcsTask : public GcsTask {
 public:
  // Where the robots go: called at every plan (the phase's start, and again after a loss) with the
  // map the plan is made on (the known map, every robot not planned for standing on its cell as an
  // obstacle) and the robots that may be planned for (living, in a led group); returns a goal per
  // robot id, {-1, -1} for a robot that is not to move. Absent: the phase's goals, or random ones.
  using GoalPicker = std::function<std::vector<planner::Cell>(const GcsContext& ctx, const planner::OccupancyGrid& map,
                                                              const std::vector<int>& robots)>;

  MapfGcsTask(const swarm::scenario::Mapf& config, std::uint32_t phase, bool map_given, GoalPicker goals = {});

  // Lifelong, the traffic layer (docs/traffic.md): each robot takes a sequence of stops (a coverage
  // route's cells, a tour's pick-ups and drops) and the robots are driven in windows of `window`
  // steps that the traffic planner makes (planner/traffic/traffic.hpp: no conflict, dead robots
  // planned around). The first window is a plan; each next one is planned from where that plan
  // leaves the robots while it is still driven, and continues it (Work with kContinues), up to
  // kPlanSteps; then, or after a hold, the next plan starts from where the robots stand. A stop's
  // act goes with the window's route as a pick-up or drop step at the time the robot stands on
  // it. The picker gives every robot id its sequence (empty: none; such a robot may still be
  // pushed aside) at the phase's start, after a loss (the living robots it is given), and at
  // restart(); `why` says which. Every stop behind a robot is handed to `done` once known: when
  // the robot's reported progress passes it, and at the end of its plan (or of one cut short by
  // a loss) as far as the robot got. Complete when every sequence is done; given up after a run
  // of windows in which no robot moved or reached a goal.
  // The longest a plan grows to by windows that continue it, in time steps: its routes go to the
  // robots whole each time it grows.
  static constexpr int kPlanSteps = 256;
  struct Stop {
    enum class Act : std::uint8_t { kNone, kPick, kDrop };
    planner::Cell cell;
    Act act = Act::kNone;
  };
  using RoutePicker = std::function<std::vector<std::vector<Stop>>(
      const GcsContext& ctx, const planner::OccupancyGrid& map, const std::vector<int>& robots, const char* why)>;
  // Every route's cells as stops without an act.
  [[nodiscard]] static std::vector<std::vector<Stop>> passing(const std::vector<std::vector<planner::Cell>>& routes);
  // Robot `robot` is past `stop`: it stood on it (`reached`), or the stop was skipped as unreachable.
  using StopDone = std::function<void(int robot, const Stop& stop, bool reached)>;
  struct Lifelong {
    RoutePicker routes;
    int window = 16;                                      // steps per window
    planner::MotionModel motion = planner::MotionModel::four();  // the phase's robots'
    StopDone done;                                        // may be empty
    // The gripper's word on a pick-up (Report kPickResults): robot `robot`, its pick-up at `at`
    // made, holds `objects`. May be empty.
    std::function<void(int robot, planner::Cell at, const std::vector<std::uint32_t>& objects)> picked;
    // The map grows while the robots drive (exploration): every window plans on the fused map of
    // its tick, not the phase's first.
    bool map_grows = false;
  };
  MapfGcsTask(const swarm::scenario::Mapf& config, std::uint32_t phase, bool map_given, Lifelong lifelong);
  // Lifelong, once complete: asks the picker for new sequences and drives them.
  void restart(GcsContext& ctx, const char* why);
  // Lifelong: the picker has new sequences (a new planning round's waypoints). A plan that can grow
  // takes them up in its next window, planned from its end: each robot drives the rest of the plan
  // and goes on without a stop. Otherwise, once the window being driven has run half its steps, it
  // is held with every robot stopped where it stands, and the next is planned from there with the
  // picker's sequences (at once if the drive was complete, at its end if it ends first).
  void repick(GcsContext& ctx, const char* why);
  // The phase is about to end while the robots still drive (exploration done): no rotation is
  // ordered any more, and `rotating` says whether one ordered is still to go. A phase that ended
  // before would switch some leaders to the next before their robots' step of it, and the others'
  // robots would run into them. A Hold waits for it too (a robot lost, a new round): it would stop
  // the robots whose stop reached them before the rotation's tick, and not the others. No rotation
  // is ordered once a robot is lost, so the Hold waits a few ticks at most.
  void wind_down() { winding_down_ = true; }
  [[nodiscard]] bool rotating(std::uint32_t tick) const { return tick <= last_rotation_tick_; }
  void start(GcsContext& ctx) override;
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return complete_; }
  // A plan that could not be made (proven infeasible, or no plan within the limit even from
  // LaCAM): the same robots on the same map give the same answer, so the phase ends there.
  [[nodiscard]] std::string given_up() const override { return failed_ ? failure_ : std::string(); }
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  void on_report(const task::Report& r, GcsContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;
  // The goal of every robot id in the current plan ({-1, -1}: none).
  [[nodiscard]] const std::vector<planner::Cell>& goals() const { return goals_; }
  [[nodiscard]] const std::vector<int>& planned() const { return planned_; }

 private:
  // Plans for the living robots (falling back to LaCAM when the configured solver times out) and
  // sends the plan; a plan that is not solved is recorded and nothing is driven.
  void plan(GcsContext& ctx, const char* why);
  // Lifelong: the next window from where the robots stand (picking sequences anew unless `why` is
  // kNextWindow).
  void plan_window(GcsContext& ctx, const char* why);
  // Lifelong, when every group has finished a window: the goals it reached are done; plans the
  // next one, or completes.
  void window_done(GcsContext& ctx);
  // Lifelong: the stops behind each planned robot leave its sequence (and go to stop_done_), as
  // far as its reported progress goes, or, once the window is `over`, further along its route to
  // the cell it stands on.
  void credit_window(const GcsContext& ctx, bool over);
  // Lifelong: a repick waiting, and the window old enough: hold it, stopping every robot.
  void cut_for_repick(GcsContext& ctx);
  // Lifelong, by the graph: once the leading robot is within half a window (and the links' round
  // trip) of the plan's end, the next window is planned from the plan's end and sent as its
  // continuation, so the robots drive on without waiting for the slowest (docs/traffic.md).
  [[nodiscard]] bool time_to_extend(const GcsContext& ctx) const;
  // How old the reported progress may be plus how long an order takes to reach every member, in
  // ticks: how far a robot may have got, past its reported progress, when an order sent now
  // reaches it.
  [[nodiscard]] int lag(const GcsContext& ctx) const;
  // Lifelong, by the graph: raises limit_ to stay ahead of every robot by lag() without the links'
  // jitter; true if it rose.
  bool raise_limit(const GcsContext& ctx);
  // Lifelong, at a repick: the plan time the next window may start from, before the plan's end
  // (the limit), or the end; the stops the plan gets each robot past after it leave the plan.
  int cut_plan();
  // Lifelong, by the graph: the plan may grow by a window (below kPlanSteps, the robots it plans for
  // still the ones that may move).
  [[nodiscard]] bool can_grow(const GcsContext& ctx) const;
  // The living robots of led groups, in increasing id: the others stand where they are.
  [[nodiscard]] static std::vector<int> may_move(const GcsContext& ctx);
  void extend_window(GcsContext& ctx);
  // Lifelong: robot `robot`'s pick-ups and drops in the window from the plan's time `from` on, in
  // steps of its part of the plan from there.
  void add_acts(int robot, task::PlannedRoute& route, int from) const;
  // Lifelong: a window planned from the plan's time `at` (0: a new plan) becomes the plan's part
  // from there; false if the phase is given up as idle.
  bool take_window(const planner::traffic::Window& w, int at);
  // A new plan's bookkeeping: its number, and which groups are in it under which leaders.
  void begin_plan(const GcsContext& ctx);
  // A plan that does not continue the last one: begin_plan, and a new chain. Progress reported
  // along the old chain and not yet relayed is dropped: relayed under the new plan's number, it
  // would be read as progress along the new routes, and release robots into cells not yet free.
  void begin_chain(const GcsContext& ctx);
  void note_plan(GcsContext& ctx, const char* why, const planner::mapf::Result& res);  // metrics + log
  // `continues`: res.paths are the grown plan, whose new window starts at time *continues.
  void send_plan(GcsContext& ctx, const planner::mapf::Result& res, std::optional<int> continues = std::nullopt);
  void send_order(GcsContext& ctx, task::OrderKind kind, std::vector<std::int32_t> values = {});
  // The simulator's tick a timed plan or a rotation sets off in: late enough for an order sent now
  // to reach every leader, its routes every member and their commands the simulator, with the
  // configured delays and jitter, and loss (comm::sure_arrival_tick).
  std::uint32_t start_tick(const GcsContext& ctx) const;
  void order_rotations(GcsContext& ctx);  // the rotations that may go now, ordered once each
  std::vector<planner::Cell> random_goals(const GcsContext& ctx) const;

  swarm::scenario::Mapf config_;
  std::uint32_t phase_;
  bool map_given_;
  GoalPicker pick_goals_;
  planner::OccupancyGrid known_;
  std::vector<planner::Cell> goals_;  // per robot id
  std::vector<int> planned_;          // robot ids in the current plan
  std::vector<bool> group_in_plan_, group_done_, group_held_;
  std::uint32_t seq_ = 0;
  bool holding_ = false;
  bool failed_ = false;  // the last plan could not be made: nothing to drive
  std::string failure_;  // why
  std::vector<int> plan_leaders_;  // per group: its leader when the current plan was made
  bool complete_ = false;
  std::uint32_t start_tick_ = 0;
  int arrived_ = 0;
  std::vector<std::int32_t> relay_;  // progress triples to relay this tick
  // Driven by the graph: the plan's graph, every planned robot's progress as reported, and which
  // rotations were ordered.
  bool by_graph_ = false;
  planner::mapf::Dependencies adg_;
  std::vector<std::uint32_t> progress_;  // per plan index: the route step it was last reported at
  std::vector<std::uint32_t> acted_;     // per plan index: its acts are made at the steps below this
  std::uint32_t limit_ = 0;              // the plan's time no robot is released past (the relays' L)
  std::uint64_t route_steps_ = 0;        // the current plan's route steps, all robots
  std::vector<bool> rotation_ordered_;
  std::uint32_t rotations_ordered_ = 0;
  std::uint32_t last_rotation_tick_ = 0;  // the latest tick an ordered rotation goes at
  bool winding_down_ = false;
  planner::mapf::Result first_;      // the first plan's numbers (after any fallback)
  bool have_first_ = false;
  nlohmann::json plans_ = nlohmann::json::array();

  // Lifelong (window_ > 0).
  RoutePicker pick_routes_;
  StopDone stop_done_;
  decltype(Lifelong::picked) picked_;
  int window_ = 0;
  bool map_grows_ = false;
  const char* repick_ = nullptr;    // new sequences wait (repick's `why`)
  const char* hold_why_ = nullptr;  // a hold's reason other than a loss (the next plan's `why`)
  std::uint32_t window_tick_ = 0;   // the tick the current window was sent
  planner::MotionModel motion_ = planner::MotionModel::four();
  std::vector<std::vector<Stop>> sequences_;    // per robot id: the stops still ahead
  // per robot id: for each stop the current plan's windows get it past, the plan's time step at
  // which it stands on it (-1: skipped as unreachable)
  std::vector<std::vector<int>> window_reached_;
  // per plan index: the current plan's timed path (its windows one after another, all as long)
  std::vector<planner::mapf::Path> window_paths_;
  std::uint32_t chain_first_ = 0;  // the seq of the current plan's first window
  bool no_continuation_ = false;    // the current plan cannot grow (its next window found none)
  std::uint64_t windows_continued_ = 0;
  std::uint64_t repicks_continued_ = 0;  // new sequences taken up by a window that continues the plan
  std::uint64_t repicks_held_ = 0;       // new sequences that held the plan, stopping every robot
  std::uint64_t plans_cut_ = 0;          // repicks that cut the plan before its end
  std::uint64_t steps_cut_ = 0;          // the plan steps they cut, in all
  std::unique_ptr<planner::traffic::Planner> traffic_;
  std::uint64_t windows_ = 0;
  std::uint64_t goals_done_ = 0;
  std::uint64_t goals_skipped_ = 0;
  int idle_windows_ = 0;  // windows in a row in which no robot reached a goal or moved
};

}  // namespace swarm::gcs
