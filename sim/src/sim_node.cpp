#include "swarm/sim/sim_node.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/record/metrics.hpp"

namespace swarm::sim {

using comm::LinkClass;
namespace topic = comm::topic;

namespace {
LidarConfig lidar_of(const app::RoleSetup& setup) {
  const auto& s = setup.world.scenario;
  return {static_cast<int>(s.lidar_beams()),
          static_cast<float>(s.sensing_range_m() / setup.world.truth.resolution())};
}
}  // namespace

SimNode::SimNode(comm::LockstepClock& clock, const app::RoleSetup& setup, PhaseSimFactory phase_sim)
    : clock_(clock),
      world_(setup.world.truth, setup.world.robot_cells, lidar_of(setup),
             static_cast<int>(setup.world.scenario.footprint_radius())),
      max_ticks_(setup.world.scenario.max_ticks()),
      alive_(setup.world.robot_cells.size(), true),
      setup_(setup),
      phase_sim_(std::move(phase_sim)) {
  const comm::Topology& t = setup.topology;
  // Lockstep has no wall time, but a GCS that is down comes back after wall seconds: while it is
  // lost, mission time passes at the real-time rate (tick_ms), so its outage lasts as many ticks
  // as it would in real time, rather than as many as the machine can run.
  for (const auto& f : setup.world.scenario.faults()) {
    if (f.agent() == "gcs" && f.has_restart_after_seconds() && !setup.world.scenario.realtime()) {
      pace_while_gcs_lost_ = std::chrono::milliseconds(setup.world.scenario.tick_ms());
    }
  }
  for (comm::AgentId r : t.robot_ids()) {
    sense_.push_back(&clock.advertise<msgs::Sense>(topic::sense(r), LinkClass::SimRobot, {r}));
  }
  clock.subscribe<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, [this, &t](const msgs::MotionCommand& m) {
    if (!t.is_robot(m.robot()) || !alive_[m.robot()]) return;
    if (m.start_tick() > tick_) {
      world_.command_at(m.start_tick(), m.robot(), m.route_id(), app::from_xy(m.path_xy()), m.pick_steps(), m.drop_steps());
    } else {
      world_.command(m.robot(), m.route_id(), app::from_xy(m.path_xy()), m.pick_steps(), m.drop_steps());
    }
  }, comm::Delivery::Reliable, t.robots());
  clock.subscribe<msgs::PhaseStart>(topic::kPhaseSim, LinkClass::Control,
                                    [this](const msgs::PhaseStart& p) {
                                      // Judged from when the robots stand still (PhaseStart.settle).
                                      if (!p.settle()) next_phase_ = p.phase();
                                    },
                                    comm::Delivery::Reliable, 1);
  mission_ = config::mission_phases(setup.world.scenario);
  start_phase(0, 0);
}

void SimNode::start_phase(std::uint32_t index, std::uint32_t tick) {
  if (!phases_.empty()) judge_phase();
  PhaseSim part = phase_sim_(mission_[index], setup_, index);
  world_.set_motion(part.motion);
  PhaseLog log;
  log.index = index;
  log.task = config::task_name(mission_[index]);
  log.start_tick = tick;
  log.counts_at_start = world_.counts();
  world_.mark();
  log.events_at_start = world_.events();
  log.diagonals_at_start = world_.diagonal_moves();
  log.judge_part = std::move(part.judge);
  log.judge_part->start(world_, tick);
  phases_.push_back(std::move(log));
}

void SimNode::judge_phase() {
  PhaseLog& p = phases_.back();
  if (p.judged) return;
  p.judge = judge_of(p, p.motion);
  p.judged = true;
}

nlohmann::json SimNode::judge_of(const PhaseLog& p, record::MotionNumbers& motion) const {
  PhaseFacts facts;
  facts.start_tick = p.start_tick;
  facts.first_move_tick = p.first_move_tick;
  facts.last_move_tick = p.last_move_tick;
  facts.motion = motion = motion_since(p.counts_at_start, p.events_at_start);
  facts.diagonal_moves = world_.diagonal_moves() - p.diagonals_at_start;
  facts.steps_to_99 = steps_to_99_;
  facts.alive = alive_;
  return p.judge_part->judge(world_, facts);
}

std::vector<msgs::RobotState> SimNode::states() const {
  std::vector<msgs::RobotState> out;
  for (const auto& c : world_.robots()) {
    msgs::RobotState s;
    s.x(static_cast<std::int16_t>(c.x));
    s.y(static_cast<std::int16_t>(c.y));
    s.alive(alive_[out.size()]);
    out.push_back(s);
  }
  return out;
}

msgs::RunTally SimNode::tally() const {
  msgs::RunTally t;
  t.vertex_conflicts(static_cast<std::uint32_t>(world_.events().vertex));
  t.edge_conflicts(static_cast<std::uint32_t>(world_.events().edge));
  t.blocked_moves(static_cast<std::uint32_t>(world_.total_counts().blocked_moves));
  const Progress p = phases_.back().judge_part->progress(world_);
  t.progress_done(static_cast<std::uint32_t>(p.done));
  t.progress_total(static_cast<std::uint32_t>(p.total));
  for (const int v : p.objects) t.objects().push_back(static_cast<std::int16_t>(v));
  return t;
}

void SimNode::begin_tick(std::uint32_t k) {
  tick_ = k;
  clock_.begin_tick(k);
  if (next_phase_ && *next_phase_ < mission_.size() && *next_phase_ != phases_.back().index) start_phase(*next_phase_, k);
  next_phase_.reset();
  for (std::size_t r = 0; r < alive_.size(); ++r) {
    const bool lost = clock_.is_lost(static_cast<comm::AgentId>(r));
    // A lost robot stands where it was; one whose link healed senses and moves again.
    if (alive_[r] && lost) {
      world_.stop(static_cast<int>(r));
      world_.put_down(static_cast<int>(r));  // what it carried lies where it stopped
    }
    alive_[r] = !lost;
  }
  world_.start_due(k);
  if (k > 0) {
    const std::uint64_t moves_before = world_.total_counts().moves;
    world_.move();
    if (world_.total_counts().moves != moves_before) {
      PhaseLog& p = phases_.back();
      if (!p.first_move_tick) p.first_move_tick = k;
      p.last_move_tick = k;
    }
  }
  for (std::size_t r = 0; r < sense_.size(); ++r) {
    if (!alive_[r]) continue;
    world_.scan(static_cast<int>(r), ranges_);
    const planner::RouteProgress& route = world_.route(static_cast<int>(r));
    msgs::Sense s;
    s.x(static_cast<std::int16_t>(world_.robots()[r].x));
    s.y(static_cast<std::int16_t>(world_.robots()[r].y));
    s.route_id(route.id);
    s.route_step(route.step);
    s.route_state(static_cast<std::uint8_t>(route.state));
    s.max_range(world_.lidar().range_cells);
    s.ranges(ranges_);
    s.carrying(world_.carried_by(static_cast<int>(r)));
    sense_[r]->send(s);
  }
  const double explored = world_.explored_fraction();
  if (!steps_to_99_ && explored >= 0.99) steps_to_99_ = k;
  if (k % 10 == 0) curve_.emplace_back(k, explored);
  phases_.back().judge_part->after_tick(world_, k);
  clock_.publish_clock(k, states(), false, tally());
}

bool SimNode::end_tick(std::uint32_t k) {
  complete_ = clock_.wait_done(k);
  if (pace_while_gcs_lost_.count() > 0 && clock_.is_lost(clock_.topology().gcs())) {
    std::this_thread::sleep_for(pace_while_gcs_lost_);
  }
  last_tick_ = k;
  // The launcher asked the run to stop (an interrupt, a timeout, a failed process): it ends
  // here as at max_ticks, judged and reported up to this tick.
  if (!complete_ && k + 1 < max_ticks_ && !clock_.stop_requested()) return false;
  curve_.emplace_back(k, world_.explored_fraction());
  phases_.back().judge_part->last_tick(world_, k);
  judge_phase();
  clock_.publish_clock(k + 1, states(), true, tally());
  return true;
}

std::uint32_t SimNode::run() {
  clock_.wait_ready();
  for (std::uint32_t k = 0;; ++k) {
    begin_tick(k);
    if (end_tick(k)) return k;
  }
}


record::MotionNumbers SimNode::motion_since(const std::vector<MotionCounts>& start, const ConflictEvents& events) const {
  record::MotionNumbers m;
  for (std::size_t r = 0; r < world_.counts().size(); ++r) {
    MotionCounts c = world_.counts()[r];
    if (!start.empty()) {  // a phase: since its start
      c = c - start[r];
      c.longest_blocked_ticks = world_.longest_blocked_since_mark()[r];
    }
    m.per_robot[clock_.topology().name_of(static_cast<comm::AgentId>(r))] = c;
    m.total += c;
  }
  m.vertex_conflict_events = world_.events().vertex - events.vertex;
  m.edge_conflict_events = world_.events().edge - events.edge;
  return m;
}

std::string SimNode::report_json() const {
  record::SimReport r;
  r.last_tick = last_tick_;
  r.steps_to_99 = steps_to_99_;
  r.explored_fraction = world_.explored_fraction();
  r.reachable_free_cells = static_cast<std::uint32_t>(world_.reachable_free_cells());
  r.explored_curve = curve_;
  r.motion = motion_since({}, {});
  for (const PhaseLog& p : phases_) {
    if (p.judged) {
      r.phases.push_back({p.index, p.task, p.start_tick, p.motion, p.judge});
    } else {  // the phase in force, when the run is reported before it stopped
      record::MotionNumbers motion;
      nlohmann::json judge = judge_of(p, motion);
      r.phases.push_back({p.index, p.task, p.start_tick, motion, judge});
    }
  }
  for (const auto& l : clock_.losses()) {
    r.agents_lost.push_back({clock_.topology().name_of(l.agent), l.tick, l.detection_seconds, l.rejoined_tick, l.restarted});
  }
  return record::to_json(r).dump();
}

}  // namespace swarm::sim
