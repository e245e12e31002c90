#include "swarm/leader/leader_node.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "swarm/comm/convert.hpp"
#include "swarm/comm/task_codes.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/member/member_node.hpp"
#include "swarm/planner/map_patch.hpp"

namespace swarm::leader {

using comm::LinkClass;
using planner::Cell;
namespace topic = comm::topic;

std::vector<int> GroupContext::living() const {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(alive.size()); ++i) {
    if (alive[static_cast<std::size_t>(i)]) out.push_back(i);
  }
  return out;
}

LeaderNode::LeaderNode(comm::LockstepAgent& agent, const comm::RoleSetup& setup, int group)
    : agent_(agent),
      setup_(setup),
      topology_(setup.topology),
      group_(group),
      encoding_(comm::patch_encoding(setup.world.scenario.map_encoding())),
      map_(setup.world.truth.width(), setup.world.truth.height(), setup.world.truth.resolution()),
      robot_(setup.world.truth.width(), setup.world.truth.height(), setup.world.truth.resolution()),
      alive_(setup.topology.robots_per_group(), true),
      patch_gcs_(agent.advertise<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, {topology_.gcs()})),
      heartbeat_(agent.advertise<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, {topology_.gcs()})),
      motion_(agent.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {topology_.sim()})) {
  for (const auto& phase : config::mission_phases(setup.world.scenario)) {
    tasks_.push_back(make_group_task(phase, setup, group));
  }
  const auto members = topology_.members(group);
  const int n_members = static_cast<int>(members.size());
  auto& group_status =
      agent.advertise<msgs::GroupStatus>(topic::kGroupStatus, LinkClass::LeaderGcs, {topology_.gcs()});
  auto& plan_report = agent.advertise<msgs::PlanReport>(topic::kPlanReport, LinkClass::Telemetry, {topology_.gcs()});
  auto& task_report = agent.advertise<msgs::TaskReport>(topic::kTaskReport, LinkClass::LeaderGcs, {topology_.gcs()});
  comm::Mailbox::Outlet<msgs::Assignment>* assign = nullptr;
  comm::Mailbox::Outlet<msgs::Route>* route = nullptr;
  comm::Mailbox::Outlet<msgs::RouteRelease>* release = nullptr;
  if (!members.empty()) {
    patch_down_ = &agent.advertise<msgs::MapPatch>(topic::patch_down(group), LinkClass::MemberLeader, members);
    assign = &agent.advertise<msgs::Assignment>(topic::assign(group), LinkClass::MemberLeader, members);
    route = &agent.advertise<msgs::Route>(topic::route(group), LinkClass::MemberLeader, members);
    release = &agent.advertise<msgs::RouteRelease>(topic::release(group), LinkClass::MemberLeader, members);
  }
  // The task's outlets; index 0 is the leader's own robot, which is told directly.
  outlets_.route = [this, route](int index, msgs::Route& r) {
    r.robot(topology_.robot(group_, index));
    r.phase(phase_);
    r.route_id(++route_ids_);
    if (index == 0) {
      member::follow_route(robot_, r);
    } else if (route != nullptr) {
      route->send(r);
    }
    return r.route_id();
  };
  outlets_.release = [this, release](int index, msgs::RouteRelease& r) {
    r.robot(topology_.robot(group_, index));
    if (index == 0) {
      robot_.release(r.route_id(), r.release());
    } else if (release != nullptr) {
      release->send(r);
    }
  };
  outlets_.report = [this, &task_report](msgs::TaskReport& r) {
    r.phase(phase_);
    r.group(static_cast<std::uint16_t>(group_));
    task_report.send(r);
  };
  outlets_.assignment = [assign](msgs::Assignment& a) {
    if (assign != nullptr) assign->send(a);
  };
  outlets_.group_status = [&group_status](msgs::GroupStatus& s) { group_status.send(s); };
  outlets_.plan_report = [&plan_report](msgs::PlanReport& p) { plan_report.send(p); };

  // Subscription order fixes the order in which same-tick messages are handled.
  agent.subscribe<msgs::Sense>(topic::sense(agent.self()), LinkClass::SimRobot, [this](const msgs::Sense& s) {
    learn(map_.observe(robot_.sense({s.x(), s.y()}, s.ranges(), s.max_range(), comm::route_progress(s))), true);
  }, comm::Delivery::BestEffort, 1);  // a lost scan is not repeated; the next one is newer
  if (!members.empty()) {
    agent.subscribe<msgs::MapPatch>(topic::patch_up(group), LinkClass::MemberLeader, [this](const msgs::MapPatch& p) {
      learn(map_.observe(comm::decode_patch(p.data(), robot_.map().size())), true);
    }, comm::Delivery::Reliable, n_members);
    agent.subscribe<msgs::MemberStatus>(topic::status(group), LinkClass::MemberLeader,
                                        [this](const msgs::MemberStatus& s) { statuses_.push_back(s); },
                                        comm::Delivery::Reliable, n_members);
    agent.subscribe<msgs::RouteProgress>(topic::progress(group), LinkClass::MemberLeader,
                                         [this](const msgs::RouteProgress& p) { progress_.push_back(p); },
                                         comm::Delivery::Reliable, n_members);
  }
  agent.subscribe<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs, [this](const msgs::RoundStart& r) {
    planner::OccupancyGrid global(r.width(), r.height(), map_.group().resolution());
    comm::decode_map(r.map_rle(), static_cast<planner::PatchEncoding>(r.encoding()), global);
    learn(map_.adopt_global(global), false);
    round_ = r.round();
  }, comm::Delivery::Reliable, 1);
  agent.subscribe<msgs::PhaseStart>(topic::kPhase, LinkClass::LeaderGcs,
                                    [this](const msgs::PhaseStart& p) { next_phase_ = p.phase(); },
                                    comm::Delivery::Reliable, 1);
  agent.subscribe<msgs::TaskOrder>(topic::kTaskOrder, LinkClass::LeaderGcs, [this](const msgs::TaskOrder& o) {
    if (o.group() == group_ || o.group() == comm::task::kAllGroups) orders_.push_back(o);
  }, comm::Delivery::Reliable, 1);
}

void LeaderNode::learn(const std::vector<planner::CellChange>& fresh, bool own_observation) {
  if (fresh.empty()) return;
  if (own_observation) to_gcs_.insert(to_gcs_.end(), fresh.begin(), fresh.end());
  to_members_.insert(to_members_.end(), fresh.begin(), fresh.end());
  robot_.learn(fresh);
}

void LeaderNode::track_members(GroupContext& ctx) {
  // A member the simulator lost gets no more work and nobody waits for it; one that comes back
  // (its link healed) is planned for again.
  for (int i = 1; i < topology_.robots_per_group(); ++i) {
    const bool alive = ctx.clock.robots()[topology_.robot(group_, i)].alive();
    if (alive == alive_[static_cast<std::size_t>(i)]) continue;
    alive_[static_cast<std::size_t>(i)] = alive;
    const std::string name = topology_.name_of(topology_.robot(group_, i));
    if (!alive) {
      members_lost_.push_back({name, ctx.clock.tick(), std::nullopt});
      tasks_[phase_]->member_lost(i, ctx);
    } else {
      if (auto it = std::find_if(members_lost_.rbegin(), members_lost_.rend(),
                                 [&](const MemberLoss& l) { return l.name == name; });
          it != members_lost_.rend()) {
        it->rejoined_tick = ctx.clock.tick();
      }
      tasks_[phase_]->member_back(i, ctx);
    }
    std::fprintf(stderr, "%s: %s %s at tick %u\n", topology_.name_of(agent_.self()).c_str(), name.c_str(),
                 alive ? "is back; planning for it again" : "lost; planning without it", ctx.clock.tick());
  }
}

void LeaderNode::dispatch(GroupContext& ctx) {
  GroupTask& task = *tasks_[phase_];
  for (const auto& o : orders_) {
    if (o.phase() != phase_) continue;
    try {
      task.on_order(o, ctx);  // decodes the order's cells, maps and routes
    } catch (const std::exception& e) {
      agent_.drop_malformed(comm::topic::kTaskOrder, o.header().sender(), e.what());
    }
  }
  orders_.clear();
  for (const auto& s : statuses_) task.on_member_status(s, ctx);
  statuses_.clear();
  for (const auto& p : progress_) {
    task.on_progress(topology_.index_of(p.robot()), {p.route_id(), p.step(), static_cast<planner::RouteState>(p.state())},
                     ctx);
  }
  progress_.clear();
  if (round_) {
    task.on_round(*round_, ctx);
    round_.reset();
  }
}

void LeaderNode::step(const msgs::Clock& clock) {
  if (next_phase_ && *next_phase_ < tasks_.size()) {
    phase_ = *next_phase_;
    started_ = false;
  }
  next_phase_.reset();
  GroupContext ctx{setup_, group_, phase_, clock, alive_, map_, robot_, outlets_};
  if (!started_) {
    tasks_[phase_]->start(ctx);
    started_ = true;
  }
  track_members(ctx);
  msgs::Heartbeat beat;
  beat.group(static_cast<std::uint16_t>(group_));
  heartbeat_.send(beat);
  dispatch(ctx);
  tasks_[phase_]->step(ctx);

  const member::RobotAgent::Step s = robot_.step(ctx.clock.tick());
  member::publish_motion(motion_, agent_.self(), s);
  if (s.report) {
    msgs::MemberStatus own;
    own.robot(agent_.self());
    own.round(s.round);
    own.state(static_cast<std::uint8_t>(*s.report));
    tasks_[phase_]->on_member_status(own, ctx);
  }
  if (const planner::RouteProgress p = robot_.following(); p.id != 0 && !(p == own_progress_)) {
    own_progress_ = p;
    tasks_[phase_]->on_progress(0, p, ctx);
  }
  tasks_[phase_]->finish_step(ctx);

  if (!to_gcs_.empty()) {
    msgs::MapPatch patch;
    patch.group(static_cast<std::uint16_t>(group_));
    patch.data(comm::encode_patch(to_gcs_, encoding_));
    patch_gcs_.send(patch);
    to_gcs_.clear();
  }
  if (!to_members_.empty()) {
    if (patch_down_ != nullptr) {
      msgs::MapPatch patch;
      patch.group(static_cast<std::uint16_t>(group_));
      patch.data(comm::encode_patch(to_members_, encoding_));
      patch_down_->send(patch);
    }
    to_members_.clear();
  }
}

std::string LeaderNode::report_json() const {
  nlohmann::json lost = nlohmann::json::array();
  for (const auto& l : members_lost_) {
    lost.push_back({{"agent", l.name},
                    {"noticed_at_tick", l.noticed_tick},
                    {"rejoined_at_tick", l.rejoined_tick ? nlohmann::json(*l.rejoined_tick) : nlohmann::json(nullptr)}});
  }
  nlohmann::json out{{"members_lost", lost}, {"replans", robot_.replans()}};
  // Each phase's numbers under its task's name; explore's also at the top level (the exploration
  // tables read rounds_planned and planning_seconds there).
  const auto phases = config::mission_phases(setup_.world.scenario);
  nlohmann::json per_phase = nlohmann::json::array();
  for (std::size_t i = 0; i < tasks_.size(); ++i) {
    const nlohmann::json n = tasks_[i]->numbers();
    per_phase.push_back({{"task", config::task_name(config::task_of(phases[i]))}, {"numbers", n}});
    if (config::task_of(phases[i]) == config::TaskKind::Explore) {
      for (auto it = n.begin(); it != n.end(); ++it) out[it.key()] = it.value();
    }
  }
  out["phases"] = per_phase;
  return out.dump();
}

}  // namespace swarm::leader
