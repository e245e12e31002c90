#include "swarm/leader/leader_node.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm/app/task_wire.hpp"
#include "swarm/comm/leadership.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/member/member_node.hpp"
#include "swarm/planner/grid/map_patch.hpp"

namespace swarm::leader {

using comm::LinkClass;
using planner::Cell;
namespace topic = comm::topic;

planner::Cell GroupContext::leader_cell(int g) const {
  return clock.robots[static_cast<std::size_t>(clock.leaders[static_cast<std::size_t>(g)])].cell;
}

std::vector<int> GroupContext::living() const {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(alive.size()); ++i) {
    if (alive[static_cast<std::size_t>(i)]) out.push_back(i);
  }
  return out;
}

LeaderNode::LeaderNode(comm::LockstepAgent& agent, const app::RoleSetup& setup, int group, int index,
                       member::RobotAgent& robot, bool leading, const GroupTaskFactory& make_task)
    : agent_(agent),
      setup_(setup),
      topology_(setup.topology),
      group_(group),
      self_index_(index),
      leading_(leading),
      encoding_(app::patch_encoding(setup.world.scenario.map_encoding())),
      map_(setup.world.frame.width, setup.world.frame.height, setup.world.frame.resolution),
      robot_(robot),
      alive_(setup.topology.robots_per_group(), true),
      // Route ids never repeat in a run: each candidate numbers its routes in a range of its own.
      route_ids_(static_cast<std::uint32_t>(index) << 24),
      patch_gcs_(agent.advertise<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, {topology_.gcs()})),
      heartbeat_(agent.advertise<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, {topology_.gcs()})),
      motion_(agent.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {topology_.sim()})) {
  if (leading_) led_.push_back({0, std::nullopt});
  const auto phases = config::mission_phases(setup.world.scenario);
  for (std::uint32_t i = 0; i < phases.size(); ++i) tasks_.push_back(make_task(phases[i], setup, group, i));
  const auto others = topology_.group_except(group, agent.self());
  // Every other robot of the group writes its member topics (the candidates too, while members).
  const int writers = static_cast<int>(others.size());
  auto& plan_report = agent.advertise<msgs::PlanReport>(topic::kPlanReport, LinkClass::Telemetry, {topology_.gcs()});
  auto& task_report = agent.advertise<msgs::TaskReport>(topic::kTaskReport, LinkClass::LeaderGcs, {topology_.gcs()});
  comm::Mailbox::Outlet<msgs::Route>* route = nullptr;
  comm::Mailbox::Outlet<msgs::RouteRelease>* release = nullptr;
  if (!others.empty()) {
    patch_down_ = &agent.advertise<msgs::MapPatch>(topic::patch_down(group), LinkClass::MemberLeader, others);
    route = &agent.advertise<msgs::Route>(topic::route(group), LinkClass::MemberLeader, others);
    release = &agent.advertise<msgs::RouteRelease>(topic::release(group), LinkClass::MemberLeader, others);
  }
  // The task's outlets; the leader's own robot (self_index_) is told directly.
  outlets_.route = [this, route](int index, const task::Route& plan) {
    msgs::Route r = app::route_msg(plan, phase_, topology_.robot(group_, index), plan.grows != 0 ? plan.grows : ++route_ids_);
    if (index == self_index_) {
      member::follow_route(robot_, r);
    } else if (route != nullptr) {
      route->send(r);
    }
    return r.route_id();
  };
  outlets_.release = [this, release](int index, std::uint32_t route_id, std::uint32_t step,
                                     const planner::mapf::Watch& watch) {
    if (index == self_index_) {
      robot_.release(route_id, step);
    } else if (release != nullptr) {
      msgs::RouteRelease r = app::release_msg(topology_.robot(group_, index), route_id, step, watch);
      release->send(r);
    }
  };
  outlets_.report = [this, &task_report](const task::Report& r) {
    msgs::TaskReport m = app::report_msg(r, phase_);
    m.group(static_cast<std::uint16_t>(group_));
    task_report.send(m);
  };
  outlets_.plan_telemetry = [this, &plan_report](const task::PlanTelemetry& p) {
    msgs::PlanReport m = app::plan_report_msg(p, group_);
    plan_report.send(m);
  };

  // Subscription order fixes the order in which same-tick messages are handled. A standby (not
  // leading) keeps only the group map up to date from what it hears, and the GCS's latest phase,
  // round and orders for its group: what it needs to take the group over.
  if (!others.empty()) {
    agent.subscribe<msgs::MapPatch>(topic::patch_up(group), LinkClass::MemberLeader, [this](const msgs::MapPatch& p) {
      const auto changes = app::decode_patch(p.data(), robot_.map().size());
      if (leading_) {
        learn(map_.observe(changes), true);
      } else {
        map_.observe(changes);
      }
    }, comm::Delivery::Reliable, writers);
    agent.subscribe<msgs::RouteProgress>(topic::progress(group), LinkClass::MemberLeader, [this](const msgs::RouteProgress& p) {
      if (leading_) progress_.push_back(p);
    }, comm::Delivery::Reliable, writers);
  }
  agent.subscribe<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs, [this](const msgs::RoundStart& r) {
    planner::OccupancyGrid global(r.width(), r.height(), map_.group().resolution());
    app::decode_map(r.map_rle(), static_cast<planner::PatchEncoding>(r.encoding()), global);
    if (leading_) {
      learn(map_.adopt_global(global), false);
    } else {
      map_.adopt_global(global);
    }
    round_ = r.round();
  }, comm::Delivery::Reliable, 1);
  agent.subscribe<msgs::PhaseStart>(topic::kPhase, LinkClass::LeaderGcs,
                                    [this](const msgs::PhaseStart& p) { next_phase_ = PhaseCall{p.phase(), p.settle()}; },
                                    comm::Delivery::Reliable, 1);
  agent.subscribe<msgs::TaskOrder>(topic::kTaskOrder, LinkClass::LeaderGcs, [this](const msgs::TaskOrder& o) {
    if (o.group() == group_ || o.group() == task::kAllGroups) orders_.push_back(o);
  }, comm::Delivery::Reliable, 1);
}

void LeaderNode::learn_own(const std::vector<planner::CellChange>& changes) { learn(map_.observe(changes), true); }

void LeaderNode::enter_phase() {
  if (next_phase_ && next_phase_->phase < tasks_.size()) {
    phase_ = next_phase_->phase;
    started_ = false;
    taking_over_ = false;  // a new phase's task no leader has started yet: it starts afresh
    settling_ = next_phase_->settle;
    stops_sent_ = settle_reported_ = false;
    stopping_.clear();
  }
  next_phase_.reset();
}

void LeaderNode::settle(GroupContext& ctx) {
  if (!stops_sent_) {
    stops_sent_ = true;
    for (const int i : ctx.living()) stopping_.emplace_back(i, outlets_.route(i, task::Route{}));
  }
  // A robot lost before its stop was confirmed stands still anyway.
  std::erase_if(stopping_, [&](const std::pair<int, std::uint32_t>& s) { return !alive_[static_cast<std::size_t>(s.first)]; });
  if (!stopping_.empty() || settle_reported_) return;
  task::Report r;
  r.state = task::GroupState::Held;
  r.values = {0};
  outlets_.report(r);
  settle_reported_ = true;
}

void LeaderNode::stopped(int index, const planner::RouteProgress& p) {
  std::erase_if(stopping_, [&](const std::pair<int, std::uint32_t>& s) {
    return s.first == index && s.second == p.id && p.state == planner::RouteState::Stopped;
  });
}

void LeaderNode::shadow(const msgs::Clock& clock) {
  // The current phase's orders for this group stay (a take-over replays them); nothing else
  // queued is this robot's business while another leads. A restart of the GCS meanwhile is the
  // leader's to answer.
  enter_phase();
  if (const auto& from = clock.counted_from(); from.size() > topology_.gcs()) {
    gcs_back_at_ = std::max(gcs_back_at_, from[topology_.gcs()]);
  }
  std::erase_if(orders_, [this](const msgs::TaskOrder& o) { return o.phase() != phase_; });
  progress_.clear();
}

std::vector<planner::CellChange> known_cells(const planner::OccupancyGrid& map) {
  std::vector<planner::CellChange> out;
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (map.at(i) != planner::CellState::Unknown) out.push_back({i, map.at(i)});
  }
  return out;
}

void LeaderNode::take_over(const msgs::Clock& clock) {
  leading_ = true;
  led_.push_back({clock.tick(), std::nullopt});
  // The group map: what this robot knows itself (its scans went to the old leader, perhaps never
  // forwarded) joins what it heard as a standby; the GCS and the members get all of it.
  learn(map_.observe(known_cells(robot_.map())), true);
  const auto all = known_cells(map_.group());
  robot_.learn(all);
  to_members_ = all;
  for (int i = 0; i < topology_.robots_per_group(); ++i) {
    alive_[static_cast<std::size_t>(i)] = i == self_index_ || clock.robots()[topology_.robot(group_, i)].alive();
  }
  // The current phase's task starts afresh from the GCS's order (kept) and, exploring, from the
  // latest round: a new round's plan at once. It takes over what the old leader drove, unless the
  // phase has not started yet (settling: no leader has started its task, and the GCS's plan for
  // it will be made with this leader in it).
  started_ = false;
  taking_over_ = !settling_;
  stops_sent_ = settle_reported_ = false;  // settling: this leader stops the robots itself
  stopping_.clear();
  own_carrying_.reset();
  if (last_round_ > 0 && !round_) round_ = last_round_;
  std::fprintf(stderr, "%s: leads group %d from tick %u\n", topology_.name_of(agent_.self()).c_str(), group_,
               clock.tick());
}

void LeaderNode::stand_down(std::uint32_t tick) {
  leading_ = false;
  if (!led_.empty() && !led_.back().to) led_.back().to = tick;
  orders_.clear();
  progress_.clear();
  std::fprintf(stderr, "%s: another robot leads group %d from tick %u; a member again\n",
               topology_.name_of(agent_.self()).c_str(), group_, tick);
}

void LeaderNode::learn(const std::vector<planner::CellChange>& fresh, bool own_observation) {
  if (fresh.empty()) return;
  if (own_observation) to_gcs_.insert(to_gcs_.end(), fresh.begin(), fresh.end());
  to_members_.insert(to_members_.end(), fresh.begin(), fresh.end());
  robot_.learn(fresh);
}

void LeaderNode::track_members(const msgs::Clock& clock, GroupContext& ctx) {
  // A member the simulator lost gets no more work and nobody waits for it; one that comes back
  // (its link healed) is planned for again.
  for (int i = 0; i < topology_.robots_per_group(); ++i) {
    if (i == self_index_) continue;
    const bool alive = clock.robots()[topology_.robot(group_, i)].alive();
    if (alive == alive_[static_cast<std::size_t>(i)]) continue;
    alive_[static_cast<std::size_t>(i)] = alive;
    const std::string name = topology_.name_of(topology_.robot(group_, i));
    if (!alive) {
      members_lost_.push_back({name, clock.tick(), std::nullopt});
      if (!settling_) tasks_[phase_]->member_lost(i, ctx);
    } else {
      if (auto it = std::find_if(members_lost_.rbegin(), members_lost_.rend(),
                                 [&](const MemberLoss& l) { return l.name == name; });
          it != members_lost_.rend()) {
        it->rejoined_tick = clock.tick();
      }
      if (!settling_) tasks_[phase_]->member_back(i, ctx);
    }
    std::fprintf(stderr, "%s: %s %s at tick %u\n", topology_.name_of(agent_.self()).c_str(), name.c_str(),
                 alive ? "is back; planning for it again" : "lost; planning without it", clock.tick());
  }
}

void LeaderNode::dispatch(GroupContext& ctx) {
  if (settling_) {
    // Nothing is the next task's business yet but the robots' stops; an order of this phase that
    // overtook its PhaseStart waits for the task.
    for (const auto& p : progress_) {
      stopped(topology_.index_of(p.robot()), {p.route_id(), p.step(), static_cast<planner::RouteState>(p.state())});
    }
    std::erase_if(orders_, [this](const msgs::TaskOrder& o) { return o.phase() != phase_; });
    progress_.clear();
    round_.reset();
    return;
  }
  GroupTask& task = *tasks_[phase_];
  for (const auto& o : orders_) {
    if (o.phase() != phase_) continue;
    try {
      task.on_order(app::order_from(o), ctx);
    } catch (const std::exception& e) {
      agent_.drop_malformed(comm::topic::kTaskOrder, o.header().sender(), e.what());
    }
  }
  orders_.clear();
  for (const auto& p : progress_) {
    task.on_carrying(topology_.index_of(p.robot()), p.carrying(), ctx);
    task.on_progress(topology_.index_of(p.robot()), {p.route_id(), p.step(), static_cast<planner::RouteState>(p.state()), p.acted()},
                     ctx);
  }
  progress_.clear();
  if (round_) {
    task.on_round(*round_, ctx);
    last_round_ = *round_;
    round_.reset();
  }
}

void LeaderNode::step(const msgs::Clock& clock) {
  enter_phase();
  const task::Clock now = app::task_clock(clock, topology_);
  GroupContext ctx{setup_, group_, self_index_, phase_, now, alive_, map_, outlets_};
  if (!started_ && !settling_) {
    tasks_[phase_]->start(ctx);
    if (taking_over_) tasks_[phase_]->took_over(ctx);
    started_ = true;
    taking_over_ = false;
  }
  track_members(clock, ctx);
  // The GCS restarted (Clock.counted_from, comm/lockstep.hpp "Restart"): what it missed, again.
  if (const auto& from = clock.counted_from(); from.size() > topology_.gcs() && from[topology_.gcs()] > gcs_back_at_) {
    gcs_back_at_ = from[topology_.gcs()];
    const auto all = known_cells(map_.group());
    to_gcs_.insert(to_gcs_.end(), all.begin(), all.end());
    if (settling_) {
      settle_reported_ = false;  // that the group stands, again
    } else {
      tasks_[phase_]->gcs_back(ctx);
    }
    std::fprintf(stderr, "%s: the GCS is back at tick %u; sent it the group map again\n",
                 topology_.name_of(agent_.self()).c_str(), clock.tick());
  }
  msgs::Heartbeat beat;
  beat.group(static_cast<std::uint16_t>(group_));
  heartbeat_.send(beat);
  dispatch(ctx);
  if (settling_) settle(ctx);
  else tasks_[phase_]->step(ctx);

  const member::RobotAgent::Step s = robot_.step(clock.tick());
  member::publish_motion(motion_, agent_.self(), s);
  if (settling_) {
    // The own robot's stop; the next task hears of its gripper and progress once it starts.
    if (const planner::RouteProgress p = robot_.following(); p.id != 0 && !(p == own_progress_)) {
      own_progress_ = p;
      stopped(self_index_, p);
      settle(ctx);
    }
  } else {
    if (!own_carrying_ || *own_carrying_ != robot_.carrying()) {
      own_carrying_ = robot_.carrying();
      tasks_[phase_]->on_carrying(self_index_, *own_carrying_, ctx);
    }
    if (const planner::RouteProgress p = robot_.following(); p.id != 0 && !(p == own_progress_)) {
      own_progress_ = p;
      tasks_[phase_]->on_progress(self_index_, p, ctx);
    }
  }

  if (!to_gcs_.empty()) {
    msgs::MapPatch patch;
    patch.group(static_cast<std::uint16_t>(group_));
    patch.data(app::encode_patch(to_gcs_, encoding_));
    patch_gcs_.send(patch);
    to_gcs_.clear();
  }
  if (!to_members_.empty()) {
    if (patch_down_ != nullptr) {
      msgs::MapPatch patch;
      patch.group(static_cast<std::uint16_t>(group_));
      patch.data(app::encode_patch(to_members_, encoding_));
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
  nlohmann::json led = nlohmann::json::array();
  for (const auto& l : led_) led.push_back({{"from_tick", l.from}, {"to_tick", l.to ? nlohmann::json(*l.to) : nlohmann::json(nullptr)}});
  nlohmann::json out{{"members_lost", lost}, {"led", led}};
  // Each phase's numbers under its task's name; explore's also at the top level (the exploration
  // tables read rounds_planned and planning_seconds there).
  const auto phases = config::mission_phases(setup_.world.scenario);
  nlohmann::json per_phase = nlohmann::json::array();
  for (std::size_t i = 0; i < tasks_.size(); ++i) {
    const nlohmann::json n = tasks_[i]->numbers();
    per_phase.push_back({{"task", config::task_name(phases[i])}, {"numbers", n}});
    if (tasks_[i]->numbers_at_top_level()) {
      for (auto it = n.begin(); it != n.end(); ++it) out[it.key()] = it.value();
    }
  }
  out["phases"] = per_phase;
  return out.dump();
}

}  // namespace swarm::leader
