// The leader's side of the task seam (docs/design.md "Missions, phases and tasks").
//
// A mission is a list of phases; the GCS starts each (PhaseStart) and judges it done. A leader runs
// one GroupTask per phase of the scenario's mission, made at start-up by the task registry, and
// hands it the group's life while its phase is current:
//   start(ctx)            the phase begins (phase 0 at tick 0; later ones when PhaseStart arrives)
//   step(ctx)             every tick of the phase, after the due messages' handlers ran and
//                         before the leader's own robot acts
//   on_order / on_round / on_progress / on_carrying
//                         the messages of the current phase, routed by the node
//   member_lost / member_back
//                         a member the simulator declared lost, or one whose link healed
//   gcs_back(ctx)         the GCS restarted (it heard nothing for a while): re-send its state
//   took_over(ctx)        this robot has just taken the group over from a lost leader (a standby,
//                         comm/leadership.hpp): called once, right after start() and before the
//                         GCS's orders of the phase, which the standby kept, are replayed; the
//                         members may be half-way along routes the old leader sent
//   numbers()             the task's own numbers for the leader's end-of-run report
// What a task may do goes through the GroupContext: the group map, the living members and the
// robots' true cells (the clock), and outlets that send routes, releases and reports, all plain C++ (app/task_messages.hpp). The node owns every topic (created once at start-up, as DDS discovery
// must be complete before tick 0), the map merging, the map relays to members and GCS, the
// heartbeat and the leader's own robot; a task never touches DDS.
//
// Adding a task: tasks/api/include/swarm/tasks/task_row.hpp (a folder tasks/<name>/ with its GCS
// part, this leader part and its simulator judge, and one registry row). Members know no task:
// they follow routes.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarm/app/role.hpp"
#include "swarm/app/task_messages.hpp"
#include "swarm/leader/group_map.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/route.hpp"
#include "swarm/planner/mapf/release_watch.hpp"

namespace swarm::leader {

// Sending, for a task (the node stamps and routes: index ctx.self is the leader's own robot).
struct GroupOutlets {
  // Gives the route a number of its own (route ids never repeat in a run) and returns it.
  std::function<std::uint32_t(int index, const task::Route&)> route;
  // Robot `index` may drive its route `route_id` as far as step `release`, and as far as `watch`
  // opens it (planner/mapf/release_watch.hpp: watched robots by agent id, gates in steps of the
  // route as sent; the leader's own robot needs none, its leader looks every tick).
  std::function<void(int index, std::uint32_t route_id, std::uint32_t release, const planner::mapf::Watch& watch)>
      release;
  std::function<void(const task::Report&)> report;
  std::function<void(const task::PlanTelemetry&)> plan_telemetry;  // for the run record's pictures
};

struct GroupContext {
  const app::RoleSetup& setup;
  int group = 0;
  int self = 0;  // the leader's own index in the group (0 unless a standby took over)
  std::uint32_t phase = 0;
  const task::Clock& clock;
  const std::vector<bool>& alive;  // per index of the group (the leader's own, `self`, always)
  GroupMap& map;
  GroupOutlets& out;

  const comm::Topology& topology() const { return setup.topology; }
  // Robot `index` of the group: its true cell, shared in real time in the clock.
  planner::Cell cell_of(int index) const { return clock.robots[setup.topology.robot(group, index)].cell; }
  std::vector<int> living() const;
  // Where group g's leader of this tick is (the clock names it: comm/leadership.hpp).
  planner::Cell leader_cell(int g) const;
};

class GroupTask {
 public:
  virtual ~GroupTask() = default;
  virtual void start(GroupContext& ctx) = 0;
  virtual void step(GroupContext& ctx) = 0;
  virtual void on_order(const task::Order&, GroupContext&) {}
  virtual void on_round(std::uint32_t /*round*/, GroupContext&) {}
  // Progress of a member's route (index 0: the leader's own robot, polled by the node each tick).
  virtual void on_progress(int /*index*/, const planner::RouteProgress&, GroupContext&) {}
  // What a robot holds, from its gripper's sensor (with its progress; index `self`: the leader's
  // own robot, whenever it changes).
  virtual void on_carrying(int /*index*/, const std::vector<std::uint32_t>& /*objects*/, GroupContext&) {}
  virtual void member_lost(int /*index*/, GroupContext&) {}
  virtual void member_back(int /*index*/, GroupContext&) {}
  virtual void took_over(GroupContext&) {}
  // The GCS's process restarted and is back in the run (gcs/gcs_node.hpp "Restart"); it heard
  // nothing meanwhile: send it again what it needs of this task's state (the node sends the group
  // map).
  virtual void gcs_back(GroupContext&) {}
  [[nodiscard]] virtual nlohmann::json numbers() const = 0;
  // Whether numbers() also go at the top level of the leader's report (exploration's: the
  // exploration tables read rounds_planned and planning_seconds there).
  [[nodiscard]] virtual bool numbers_at_top_level() const { return false; }
};

// Makes group `group`'s task of phase `index` of the mission (the phase's settings from
// config::mission_phases): the task registry's tasks::group_task (tasks/registry.hpp).
using GroupTaskFactory = std::function<std::unique_ptr<GroupTask>(
    const swarm::scenario::Phase& phase, const app::RoleSetup& setup, int group, std::uint32_t index)>;

}  // namespace swarm::leader
