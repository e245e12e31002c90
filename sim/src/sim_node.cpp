#include "swarm/sim/sim_node.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/config/task_config.hpp"
#include "swarm/record/metrics.hpp"

namespace swarm::sim {

using comm::LinkClass;
namespace topic = comm::topic;

namespace {
// Exploration and collection drive the paper's 8-connected robots; coverage and MAPF plan on the
// 4-connected grid their papers assume.
planner::MotionModel motion_for(config::TaskKind task) {
  return task == config::TaskKind::Cover || task == config::TaskKind::Mapf ? planner::MotionModel::four()
                                                                           : planner::MotionModel::eight();
}

LidarConfig lidar_of(const app::RoleSetup& setup) {
  const auto& s = setup.world.scenario;
  return {static_cast<int>(s.lidar_beams()),
          static_cast<float>(s.sensing_range_m() / setup.world.truth.resolution())};
}
}  // namespace

SimNode::SimNode(comm::LockstepClock& clock, const app::RoleSetup& setup)
    : clock_(clock),
      world_(setup.world.truth, setup.world.robot_cells, lidar_of(setup),
             static_cast<int>(setup.world.scenario.footprint_radius())),
      max_ticks_(setup.world.scenario.max_ticks()),
      alive_(setup.world.robot_cells.size(), true),
      collect_(setup.world.collect) {
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
    if (t.is_robot(m.robot()) && alive_[m.robot()]) world_.command(m.robot(), m.route_id(), app::from_xy(m.path_xy()), m.pick_steps(), m.drop_steps());
  }, comm::Delivery::Reliable, t.robots());
  clock.subscribe<msgs::PhaseStart>(topic::kPhase, LinkClass::LeaderGcs,
                                    [this](const msgs::PhaseStart& p) { next_phase_ = p.phase(); },
                                    comm::Delivery::Reliable, 1);
  mission_ = config::mission_phases(setup.world.scenario);
  start_phase(0, 0);
}

void SimNode::start_phase(std::uint32_t index, std::uint32_t tick) {
  if (!phases_.empty()) judge_phase();
  const config::TaskKind task = config::task_of(mission_[index]);
  world_.set_motion(motion_for(task));
  PhaseLog log;
  log.index = index;
  log.task = config::task_name(task);
  log.start_tick = tick;
  log.counts_at_start = world_.counts();
  log.events_at_start = world_.events();
  log.diagonals_at_start = world_.diagonal_moves();
  if (task == config::TaskKind::Cover) {
    world_.reset_coverage();
    log.curve.emplace_back(tick, world_.covered_fraction());
  }
  if (task == config::TaskKind::Collect) {
    const config::CollectWorld& cw = collect_.at(index);
    world_.set_objects(cw.objects, cw.destinations);
    log.curve.emplace_back(tick, 0.0);
  }
  phases_.push_back(std::move(log));
}

void SimNode::judge_phase() {
  if (!phases_.back().judged) fill_judge(phases_.back());
}

void SimNode::fill_judge(PhaseLog& p) const {
  p.motion = motion_since(p.counts_at_start, p.events_at_start);
  if (p.task == "explore") {
    p.judge = {{"explored_fraction", world_.explored_fraction()},
               {"steps_to_99", steps_to_99_ ? nlohmann::json(*steps_to_99_) : nlohmann::json(nullptr)}};
  } else if (p.task == "cover") {
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& [tick, f] : p.curve) curve.push_back({tick, f});
    p.judge = {{"covered_fraction", world_.covered_fraction()},
               {"covered_cells", world_.covered_cells()},
               {"target_cells", world_.coverage_target_cells()},
               {"makespan_ticks", p.full_tick ? nlohmann::json(*p.full_tick - p.start_tick) : nlohmann::json(nullptr)},
               {"coverage_curve", curve}};
  } else if (p.task == "collect") {
    // Delivered objects over time (tick, count): a point at every delivery.
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& [tick, n] : p.curve) curve.push_back({tick, n});
    const auto& c = world_.collect();
    // What the robots drove in the phase, in the tour planner's terms: length in cells (straight
    // 1, diagonal sqrt 2) and rotation in radians (eighths of a turn x pi / 4).
    const std::uint64_t diagonals = world_.diagonal_moves() - p.diagonals_at_start;
    const double length = static_cast<double>(p.motion.total.moves - diagonals) +
                          static_cast<double>(diagonals) * planner::MotionModel::kDiagonalCost;
    const double rotation = static_cast<double>(p.motion.total.turn_eighths) * std::acos(-1.0) / 4.0;
    p.judge = {{"objects", c.objects},
               {"delivered", c.delivered},
               {"picked", c.picked},
               {"wrong_drops", c.wrong_drops},
               {"driven_length_cells", length},
               {"driven_rotation_rad", rotation},
               {"makespan_ticks", p.full_tick ? nlohmann::json(*p.full_tick - p.start_tick) : nlohmann::json(nullptr)},
               {"delivered_curve", curve}};
  } else if (p.task == "mapf") {
    // Executed makespan: ticks from the phase's start to the last move any robot made (orders and
    // routes take a few ticks to arrive), and from the first move to the last (the plan's own
    // measure, comparable with the planned makespan).
    const bool moved = p.last_move_tick.has_value();
    p.judge = {{"makespan_ticks", moved ? *p.last_move_tick - p.start_tick : 0},
               {"driven_makespan_ticks", moved ? *p.last_move_tick - *p.first_move_tick + 1 : 0},
               {"conflicts", p.motion.vertex_conflict_events + p.motion.edge_conflict_events},
               {"blocked_moves", p.motion.total.blocked_moves}};
  }
  p.judged = true;
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

void SimNode::begin_tick(std::uint32_t k) {
  clock_.begin_tick(k);
  if (next_phase_ && *next_phase_ < mission_.size() && *next_phase_ != phases_.back().index) start_phase(*next_phase_, k);
  next_phase_.reset();
  for (std::size_t r = 0; r < alive_.size(); ++r) {
    const bool lost = clock_.is_lost(static_cast<comm::AgentId>(r));
    // A lost robot stands where it was; one whose link healed senses and moves again.
    if (alive_[r] && lost) {
      world_.command(static_cast<int>(r), world_.route(static_cast<int>(r)).id, {});
      world_.put_down(static_cast<int>(r));  // what it carried lies where it stopped
    }
    alive_[r] = !lost;
  }
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
  if (PhaseLog& p = phases_.back(); p.task == "cover") {
    if (!p.full_tick && world_.covered_cells() >= world_.coverage_target_cells()) p.full_tick = k;
    if (k % 5 == 0) p.curve.emplace_back(k, world_.covered_fraction());
  } else if (p.task == "collect") {
    const int delivered = world_.collect().delivered;
    if (delivered != static_cast<int>(p.curve.back().second)) p.curve.emplace_back(k, delivered);
    if (!p.full_tick && delivered >= world_.collect().objects) p.full_tick = k;
  }
  clock_.publish_clock(k, states(), false);
}

bool SimNode::end_tick(std::uint32_t k) {
  complete_ = clock_.wait_done(k);
  if (pace_while_gcs_lost_.count() > 0 && clock_.is_lost(clock_.topology().gcs())) {
    std::this_thread::sleep_for(pace_while_gcs_lost_);
  }
  last_tick_ = k;
  if (!complete_ && k + 1 < max_ticks_) return false;
  curve_.emplace_back(k, world_.explored_fraction());
  if (PhaseLog& p = phases_.back(); p.task == "cover") p.curve.emplace_back(k, world_.covered_fraction());
  judge_phase();
  clock_.publish_clock(k + 1, states(), true);
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
    const MotionCounts c = world_.counts()[r] - (start.empty() ? MotionCounts{} : start[r]);
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
  for (PhaseLog p : phases_) {
    if (!p.judged) fill_judge(p);  // the phase in force, when the run is reported before it stopped
    r.phases.push_back({p.index, p.task, p.start_tick, p.motion, p.judge});
  }
  for (const auto& l : clock_.losses()) {
    r.agents_lost.push_back({clock_.topology().name_of(l.agent), l.tick, l.detection_seconds, l.rejoined_tick, l.restarted});
  }
  return record::to_json(r).dump();
}

}  // namespace swarm::sim
