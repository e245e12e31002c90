#include "swarm/gcs/gcs_node.hpp"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>
#include <tuple>

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm/app/task_wire.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/planner/grid/map_patch.hpp"
#include "swarm/record/metrics.hpp"
#include "swarm/gcs/gcs_task.hpp"

namespace swarm::gcs {

using comm::LinkClass;
using nlohmann::json;
namespace topic = comm::topic;

namespace {

// The encoding whole maps travel in (task orders, planning rounds) for the run's map_encoding:
// run-length, zstd-compressed when the run's encoding is ZstdRunLength.
planner::PatchEncoding map_encoding(const app::RoleSetup& setup) {
  return app::patch_encoding(setup.world.scenario.map_encoding()) == planner::PatchEncoding::ZstdRunLength
             ? planner::PatchEncoding::ZstdRunLength
             : planner::PatchEncoding::RunLength;
}

// How many ticks of silence make a leader unreachable. In lockstep a heartbeat sent at t is seen
// by its last arrival tick, plus two ticks of slack. In real time a busy machine delays a process by
// a few ticks of 40 ms now and then, which is not a cut link: half a second of slack.
std::uint32_t unreachable_after_ticks(const comm::LinkTable& links) {
  const comm::LinkParams& p = links[LinkClass::LeaderGcs];
  if (!links.realtime) return comm::last_arrival_tick(p, 0) + 2;
  return 1 + static_cast<std::uint32_t>(std::ceil((p.delay_ms + 500.0) / links.tick_ms));
}

}  // namespace

GcsNode::GcsNode(comm::LockstepAgent& agent, const app::RoleSetup& setup, const std::string& run_dir,
                 Progress::Style progress, const GcsTaskFactory& make_task)
    : agent_(agent),
      setup_(setup),
      run_dir_(run_dir),
      fused_(setup.world.frame.width, setup.world.frame.height, setup.world.frame.resolution,
             setup.topology.groups()),
      phases_(config::mission_phases(setup.world.scenario)),
      progress_(progress, setup.world.scenario.max_ticks()),
      record_(record::run_record_path(run_dir)),
      leaders_(setup.topology),
      last_heard_(setup.topology.groups(), 0),
      unreachable_after_ticks_(unreachable_after_ticks(setup.links)),
      unreachable_(setup.topology.groups()),
      robots_lost_(setup.topology.robots()) {
  planned_ = std::make_unique<comm::Writer<msgs::PlannedRoute>>(agent.bus(), topic::kPlanned);
  record_.on_append([this](const record::Frame& f) {
    if (!f.has_route() || agent_.replaying()) return;
    msgs::PlannedRoute p;
    p.tick(f.route().tick());
    p.phase(f.route().phase());
    p.robot(static_cast<std::uint16_t>(f.route().robot()));
    for (const std::int32_t v : f.route().xy()) p.path_xy().push_back(static_cast<std::int16_t>(v));
    p.region_cells(f.route().region_cells());
    planned_->write(p);
  });
  // Every candidate leader (comm/leadership.hpp) writes the leaders' topics; only the leader of
  // the moment is heard. What the map patches carry is true whoever sent it, so a deposed
  // leader's late patches are fused too.
  const int writers = static_cast<int>(setup.topology.all_candidates().size());
  agent.subscribe<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, [this](const msgs::Heartbeat& h) {
    if (h.group() < last_heard_.size() && from_leader(h.header())) last_heard_[h.group()] = agent_.tick();
  }, comm::Delivery::Reliable, writers);
  agent.subscribe<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, [this](const msgs::MapPatch& p) {
    fused_.fuse(p.group(), app::decode_patch(p.data(), setup_.world.frame.cells()));
  }, comm::Delivery::Reliable, writers);
  agent.subscribe<msgs::TaskReport>(topic::kTaskReport, LinkClass::LeaderGcs, [this](const msgs::TaskReport& r) {
    if (from_leader(r.header())) task_reports_.push_back(r);
  }, comm::Delivery::Reliable, writers);
  agent.subscribe<msgs::PlanReport>(topic::kPlanReport, LinkClass::Telemetry,
                                    [this](const msgs::PlanReport& p) { on_plan(p); }, comm::Delivery::Reliable,
                                    writers);
  reports_reader_ = std::make_unique<comm::Reader<msgs::AgentReport>>(
      agent.bus(), topic::kReport, [this](msgs::AgentReport&& r) {
        std::lock_guard<std::mutex> lock(reports_mutex_);
        reports_[r.agent()] = std::move(r);
      });

  // The mission: one task per phase, each with the topics made here once (DDS discovery must be
  // complete before tick 0).
  // To every candidate leader: a standby keeps the latest of each, to take its group over.
  const std::vector<comm::AgentId> leaders = setup.topology.all_candidates();
  auto& phase = agent.advertise<msgs::PhaseStart>(topic::kPhase, LinkClass::LeaderGcs, leaders);
  auto& phase_sim = agent.advertise<msgs::PhaseStart>(topic::kPhaseSim, LinkClass::Control, {setup.topology.sim()});
  auto& order = agent.advertise<msgs::TaskOrder>(topic::kTaskOrder, LinkClass::LeaderGcs, leaders);
  auto& round = agent.advertise<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs, leaders);
  outlets_.order = [this, &order](const task::Order& o) {
    msgs::TaskOrder m = app::order_msg(o, phase_);
    order.send(m);
  };
  outlets_.round = [this, &round](std::uint32_t fused_tick, const planner::OccupancyGrid& map) {
    round_ticks_.push_back(last_tick_);
    const auto index = static_cast<std::uint32_t>(round_ticks_.size());
    const planner::PatchEncoding encoding = map_encoding(setup_);
    msgs::RoundStart r;
    r.round(index);
    r.fused_tick(fused_tick);
    r.width(static_cast<std::uint16_t>(map.width()));
    r.height(static_cast<std::uint16_t>(map.height()));
    r.encoding(static_cast<std::uint8_t>(encoding));
    r.map_rle(app::encode_map(map, encoding));
    round.send(r);
    return index;
  };
  announce_phase_ = [&phase, &phase_sim](std::uint32_t index, const std::string& task, bool settle) {
    msgs::PhaseStart p;
    p.phase(index);
    p.task(task);
    p.settle(settle);
    phase.send(p);
    phase_sim.send(p);
  };
  for (std::uint32_t i = 0; i < phases_.size(); ++i) tasks_.push_back(make_task(phases_[i], setup, i));

  record::Frame header;
  auto* h = header.mutable_header();
  *h->mutable_scenario() = setup.world.scenario;
  const config::MapFrame& frame = setup.world.frame;
  h->set_width(frame.width);
  h->set_height(frame.height);
  h->set_resolution(frame.resolution);
  h->set_origin_x(frame.origin_x);
  h->set_origin_y(frame.origin_y);
  h->set_start_x(setup.world.start.x);
  h->set_start_y(setup.world.start.y);
  h->set_groups(setup.topology.groups());
  h->set_robots_per_group(setup.topology.robots_per_group());
  record_.append(header);
}

bool GcsNode::from_leader(const msgs::Stamp& stamp) {
  leaders_.observe(agent_.clock());  // the tick being processed: its handlers run before step()
  if (leaders_.led_at(stamp.sender(), stamp.tick())) return true;
  ++not_from_a_leader_;
  return false;
}

void GcsNode::on_plan(const msgs::PlanReport& p) {
  record::Frame f;
  auto* plan = f.mutable_plan();
  plan->set_tick(agent_.tick());
  plan->set_round(p.round());
  plan->set_group(p.group());
  plan->set_plan_case(static_cast<record::PlanCase>(p.plan_case()));
  for (auto v : p.waypoints_xy()) plan->add_waypoints_xy(v);
  for (auto v : p.group_frontiers_xy()) plan->add_group_frontiers_xy(v);
  for (const auto& seg : p.global_segments_xy()) {
    auto* s = plan->add_global_segments();
    for (auto v : seg) s->add_xy(v);
  }
  plan->set_chosen_segment(p.chosen_segment());
  plan->set_phase(phase_);
  record_.append(f);
}

void GcsNode::record_phase(std::uint32_t tick, bool ended, bool complete) {
  record::Frame f;
  auto* c = f.mutable_phase();
  c->set_tick(tick);
  c->set_phase(phase_);
  c->set_task(config::task_name(phases_[phase_]));
  c->set_ended(ended);
  c->set_complete(complete);
  record_.append(f);
}

std::string journal_path(const std::string& run_dir) { return run_dir + "/gcs.journal"; }

namespace {
std::string start_time_path(const std::string& run_dir) { return run_dir + "/gcs.start"; }
}  // namespace

void GcsNode::resumed(std::vector<comm::JournalRestart> restarts) {
  restarts_ = std::move(restarts);
  rejoining_ = true;
  long long ms = 0;
  if (std::ifstream in(start_time_path(run_dir_)); in >> ms) {
    first_tick_time_ = std::chrono::system_clock::time_point(std::chrono::milliseconds(ms));
  }
  std::fprintf(stderr, "gcs: resumed: %u ticks of the journal replayed in %.3f s\n",
               restarts_.empty() ? 0u : restarts_.back().replayed_ticks, restarts_.empty() ? 0.0 : restarts_.back().seconds);
}

void GcsNode::record_events(const msgs::Clock& clock) {
  const auto event = [&](record::Event::Kind kind, std::uint32_t robot) {
    record::Frame f;
    record::Event& e = *f.mutable_event();
    e.set_tick(clock.tick());
    e.set_kind(kind);
    e.set_robot(robot);
    e.set_group(static_cast<std::uint32_t>(setup_.topology.group_of(static_cast<comm::AgentId>(robot))));
    record_.append(f);
  };
  // robots_lost_ still holds the last clock's verdict (step observes this one later).
  for (int r = 0; r < setup_.topology.robots() && r < static_cast<int>(clock.robots().size()); ++r) {
    const bool down = !clock.robots()[static_cast<std::size_t>(r)].alive();
    if (down != robots_lost_.down(r)) event(down ? record::Event::ROBOT_LOST : record::Event::ROBOT_BACK, static_cast<std::uint32_t>(r));
  }
  // A handler may have observed this clock before the step: every change not recorded yet.
  for (; leader_changes_recorded_ < leaders_.changes().size(); ++leader_changes_recorded_) {
    event(record::Event::TAKE_OVER, leaders_.changes()[leader_changes_recorded_].to);
  }
}

bool GcsNode::step(const msgs::Clock& clock) {
  const bool live = !agent_.replaying();
  const auto now = std::chrono::system_clock::now();
  if (clock.tick() == 0 && live) {
    first_tick_time_ = now;
    std::ofstream(start_time_path(run_dir_))
        << std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() << "\n";
  }
  if (live) last_tick_time_ = now;
  if (live && rejoining_) {
    // Back in the run: the leaders were not silent, this process was; hear them from now on.
    rejoining_ = false;
    std::fill(last_heard_.begin(), last_heard_.end(), clock.tick());
  }
  last_tick_ = clock.tick();
  leaders_.observe(clock);

  std::vector<planner::Cell> robots;
  record::Frame poses;
  poses.mutable_poses()->set_tick(clock.tick());
  // While the robots stop, their moves are still the last phase's (the simulator judges them so).
  poses.mutable_poses()->set_phase(settling_ ? phase_ - 1 : phase_);
  for (const auto& r : clock.robots()) {
    robots.push_back({r.x(), r.y()});
    poses.mutable_poses()->add_xy(r.x());
    poses.mutable_poses()->add_xy(r.y());
  }
  record::Tally& tally = *poses.mutable_poses()->mutable_tally();
  tally.set_vertex_conflicts(clock.tally().vertex_conflicts());
  tally.set_edge_conflicts(clock.tally().edge_conflicts());
  tally.set_blocked_moves(clock.tally().blocked_moves());
  tally.set_progress_done(clock.tally().progress_done());
  tally.set_progress_total(clock.tally().progress_total());
  for (const std::uint64_t b : clock.sent_bytes()) tally.add_sent_bytes(b);
  for (const std::int16_t v : clock.tally().objects()) tally.add_objects(v);
  record_.append(poses);
  record_events(clock);

  const task::Clock tick_clock = app::task_clock(clock, setup_.topology);
  GcsContext ctx{setup_, phase_, tick_clock, fused_, record_, outlets_};
  if (phase_starts_.empty()) {
    phase_starts_.push_back(clock.tick());
    record_phase(clock.tick(), false, false);
    tasks_[phase_]->start(ctx);
  }
  for (const auto& r : task_reports_) {
    if (r.phase() != phase_) continue;
    if (settling_) {
      const bool stands = r.state() == static_cast<std::uint8_t>(task::GroupState::Held) && r.values().size() == 1 &&
                          r.values()[0] == 0;
      if (stands && r.group() < settled_.size()) settled_[r.group()] = true;
      continue;
    }
    try {
      tasks_[phase_]->on_report(app::report_from(r), ctx);
    } catch (const std::exception& e) {
      agent_.drop_malformed(comm::topic::kTaskReport, r.header().sender(), e.what());
    }
  }
  task_reports_.clear();
  if (settling_) {
    settle(ctx);
    give_up_settling(clock.tick());
  } else if (!complete_tick_ && !gave_up_) {
    tasks_[phase_]->step(ctx);
    if (tasks_[phase_]->complete()) {
      phase_ends_.push_back(clock.tick());
      record_phase(clock.tick(), true, true);
      if (phase_ + 1 < tasks_.size()) {
        ++phase_;
        settling_ = true;
        settle_since_ = clock.tick();
        settled_.assign(static_cast<std::size_t>(setup_.topology.groups()), false);
        announce_phase_(phase_, config::task_name(phases_[phase_]), true);
      } else {
        complete_tick_ = clock.tick();
      }
    } else if (std::string why = tasks_[phase_]->given_up(); !why.empty()) {
      // The phase can never be done: end it and the mission here, incomplete, with the reason.
      phase_ends_.push_back(clock.tick());
      record_phase(clock.tick(), true, false);
      std::fprintf(stderr, "gcs: phase %u (%s) given up at tick %u: %s\n", phase_,
                   config::task_name(phases_[phase_]).c_str(), clock.tick(), why.c_str());
      gave_up_ = std::move(why);
    }
  }

  std::string note;
  for (int r = 0; r < setup_.topology.robots(); ++r) {
    robots_lost_.observe(r, !clock.robots()[r].alive(), clock.tick(), clock.tick());
    if (robots_lost_.down(r)) note += setup_.topology.name_of(static_cast<comm::AgentId>(r)) + " lost ";
  }
  for (int g = 0; g < setup_.topology.groups(); ++g) {
    const bool silent = clock.tick() > last_heard_[g] + unreachable_after_ticks_;
    unreachable_.observe(g, silent, last_heard_[g] + 1, clock.tick());
    if (unreachable_.down(g)) note += "leader-" + std::to_string(g) + " unreachable ";
  }
  ProgressLine line;
  if (settling_) {
    const auto stand = static_cast<double>(std::count(settled_.begin(), settled_.end(), true));
    line = {"groups standing", stand / static_cast<double>(settled_.size()), "stopping the robots"};
  } else {
    line = tasks_[phase_]->progress(ctx);
  }
  if (!settling_ && !complete_tick_ && !gave_up_) watch_stall(line, clock.tick());
  const std::string task = config::task_name(phases_[phase_]);
  if (live) {
    progress_.update(clock.tick(), phases_.size() > 1 ? task + " " + line.label : line.label, line.fraction,
                     line.detail, note);
  }
  // Per tick: a run stopped by a signal or a failed process keeps a record readable to here.
  record_.flush();
  return complete_tick_.has_value() || gave_up_.has_value();
}

void GcsNode::watch_stall(const ProgressLine& line, std::uint32_t tick) {
  const std::uint32_t limit = setup_.world.scenario.stall_ticks();
  if (stall_phase_ != phase_starts_.size() || line.fraction > stall_best_) {
    stall_phase_ = phase_starts_.size();
    stall_best_ = line.fraction;
    stall_since_ = tick;
    return;
  }
  if (limit == 0 || tick - stall_since_ < limit) return;
  char why[160];
  std::snprintf(why, sizeof why, "stalled: %s at %.1f %% since tick %u, no progress in %u ticks (stall_ticks)",
                line.label.c_str(), 100.0 * stall_best_, stall_since_, limit);
  phase_ends_.push_back(tick);
  record_phase(tick, true, false);
  std::fprintf(stderr, "gcs: phase %u (%s) given up at tick %u: %s\n", phase_, config::task_name(phases_[phase_]).c_str(),
               tick, why);
  gave_up_ = why;
}

void GcsNode::give_up_settling(std::uint32_t tick) {
  const std::uint32_t limit = setup_.world.scenario.stall_ticks();
  if (!settling_ || limit == 0 || tick - settle_since_ < limit) return;
  // The phase cannot start from robots that are not known to stand still: it starts and ends
  // here, given up, and the mission with it.
  char why[160];
  std::snprintf(why, sizeof why, "stalled: not every group reported its robots standing within %u ticks (stall_ticks)",
                limit);
  settling_ = false;
  phase_starts_.push_back(tick);
  record_phase(tick, false, false);
  phase_ends_.push_back(tick);
  record_phase(tick, true, false);
  std::fprintf(stderr, "gcs: phase %u (%s) given up at tick %u: %s\n", phase_, config::task_name(phases_[phase_]).c_str(),
               tick, why);
  gave_up_ = why;
}

void GcsNode::settle(GcsContext& ctx) {
  for (int g = 0; g < setup_.topology.groups(); ++g) {
    if (ctx.alive(ctx.leader_of(g)) && !settled_[static_cast<std::size_t>(g)]) return;
  }
  settling_ = false;
  ctx.phase = phase_;
  phase_starts_.push_back(ctx.tick());
  announce_phase_(phase_, config::task_name(phases_[phase_]), false);
  record_phase(ctx.tick(), false, false);
  tasks_[phase_]->start(ctx);
}

void GcsNode::finish(std::chrono::milliseconds wait) {
  const double wall = std::chrono::duration<double>(last_tick_time_ - first_tick_time_).count();
  // Every agent but the GCS reports once the run has stopped; a robot lost at the end may be
  // dead, so it is not waited for (its report is kept if it comes meanwhile).
  const auto all_living_reported = [&] {
    std::lock_guard<std::mutex> lock(reports_mutex_);
    for (int a = 0; a < setup_.topology.agents(); ++a) {
      const auto id = static_cast<comm::AgentId>(a);
      if (id == setup_.topology.gcs() || reports_.count(id)) continue;
      if (setup_.topology.is_robot(id) && robots_lost_.down(a)) continue;
      return false;
    }
    return true;
  };
  const auto deadline = std::chrono::steady_clock::now() + wait;
  while (!all_living_reported() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::map<comm::AgentId, msgs::AgentReport> reports;
  {
    std::lock_guard<std::mutex> lock(reports_mutex_);
    reports = reports_;
  }
  reports[setup_.topology.gcs()] = agent_.make_report("gcs", "{}");

  const auto& s = setup_.world.scenario;
  const comm::Topology& t = setup_.topology;
  // The simulator's report is the ground truth a run is judged by: without it there is no result.
  const auto sim_it = reports.find(t.sim());
  if (sim_it == reports.end()) {
    throw std::runtime_error("no end-of-run report from the simulator (sim) reached the GCS: the run has no "
                             "ground-truth result; see logs/sim.log");
  }
  json sim_json;
  try {
    sim_json = json::parse(sim_it->second.extra_json());
  } catch (const json::exception& e) {
    throw std::runtime_error(std::string("the simulator's (sim) report is not valid JSON: ") + e.what());
  }
  const record::SimReport sim = record::sim_report_from_json(sim_json, "sim");

  record::RunMetrics m;
  m.scenario = s.name();
  m.map = s.map();
  m.mode = config::mode_name(s.explore().mode());
  m.seed = s.seed();
  m.groups = s.groups();
  m.robots_per_group = s.robots_per_group();
  m.robots = s.groups() * s.robots_per_group();
  m.complete = complete_tick_.has_value();
  m.ticks_run = last_tick_ + 1;
  if (m.complete) {
    m.ended = "complete";
  } else if (gave_up_) {
    m.ended = "given up: " + *gave_up_;
  } else if (m.ticks_run >= s.max_ticks()) {
    m.ended = "max_ticks (" + std::to_string(s.max_ticks()) + ") reached";
  } else {
    m.ended = "stopped at tick " + std::to_string(last_tick_) + " by the launcher (an interrupt, a timeout or a failed process)";
  }
  m.steps = m.complete ? *complete_tick_ : m.ticks_run;
  m.steps_to_99 = sim.steps_to_99;
  m.planning_rounds = static_cast<std::uint32_t>(round_ticks_.size());
  m.explored_fraction = sim.explored_fraction;
  m.wall_seconds = wall;
  m.ticks_per_second = wall > 0 ? m.ticks_run / wall : 0.0;
  for (int a = 0; a < t.agents(); ++a) {
    if (!reports.count(static_cast<comm::AgentId>(a))) m.reports_missing.push_back(t.name_of(static_cast<comm::AgentId>(a)));
  }
  std::map<std::string, std::map<std::string, std::uint64_t>> sent_by;  // link -> agent -> bytes
  for (const auto& [id, r] : reports) {
    try {
      m.agents[t.name_of(id)] = r.extra_json().empty() ? json::object() : json::parse(r.extra_json());
    } catch (const json::exception& e) {
      throw std::runtime_error("the report of " + t.name_of(id) + " is not valid JSON: " + e.what());
    }
    for (const auto& tt : r.traffic()) {
      record::TopicTraffic& bt = m.traffic.by_topic[tt.topic()];
      bt.link = tt.link();
      bt.messages += tt.sent_messages();
      bt.bytes += tt.sent_bytes();
      bt.addressed_messages += tt.addressed_messages();
      bt.received_messages += tt.received_messages();
      bt.lost_transmissions += tt.lost_transmissions();
      bt.dropped_messages += tt.dropped_messages();
      record::LinkTraffic& bl = m.traffic.by_link[tt.link()];
      bl.messages += tt.sent_messages();
      bl.bytes += tt.sent_bytes();
      bl.lost_transmissions += tt.lost_transmissions();
      bl.dropped_messages += tt.dropped_messages();
      if (bl.queued_ticks.size() < tt.queued_ticks().size()) bl.queued_ticks.resize(tt.queued_ticks().size(), 0);
      for (std::size_t d = 0; d < tt.queued_ticks().size(); ++d) bl.queued_ticks[d] += tt.queued_ticks()[d];
      m.traffic.total_messages += tt.sent_messages();
      m.traffic.total_bytes += tt.sent_bytes();
      sent_by[tt.link()][t.name_of(id)] += tt.sent_bytes();
    }
  }
  for (const auto& [link, agents] : sent_by) {
    record::LinkTraffic& bl = m.traffic.by_link[link];
    for (const auto& [agent, bytes] : agents) {
      if (bytes > bl.busiest_sender_bytes) std::tie(bl.busiest_sender, bl.busiest_sender_bytes) = std::tie(agent, bytes);
    }
  }
  for (const auto& o : unreachable_.intervals()) {
    m.unreachable.push_back({"leader-" + std::to_string(o.who), o.from, o.to.value_or(last_tick_ + 1)});
  }
  // The GCS saw each loss in the clock's robot states; the simulator knows when the agent went
  // silent and how long DDS took to say so. The n-th loss of an agent is the n-th on both sides.
  std::map<std::string, std::size_t> seen;
  for (const auto& o : robots_lost_.intervals()) {
    record::AgentLost lost{t.name_of(static_cast<comm::AgentId>(o.who)), o.from, o.to, std::nullopt, std::nullopt};
    const std::size_t nth = seen[lost.agent]++;
    std::size_t i = 0;
    for (const auto& l : sim.agents_lost) {
      if (l.agent != lost.agent || i++ < nth) continue;
      lost.stopped_answering_at_tick = l.missed_tick;
      lost.detection_seconds = l.detection_seconds;
      break;
    }
    m.agents_lost.push_back(lost);
  }
  for (std::size_t i = 0; i < round_ticks_.size(); ++i) {
    m.rounds.emplace_back(static_cast<std::uint32_t>(i + 1), round_ticks_[i]);
  }
  // Every robot that led a group planned for it (a standby that took over, too).
  for (comm::AgentId c : t.all_candidates()) {
    const auto it = m.agents.find(t.name_of(c));
    if (it != m.agents.end() && it->second.is_object()) m.planning_seconds_total += it->second.value("planning_seconds", 0.0);
  }
  for (const auto& c : leaders_.changes()) {
    record::Handover h{c.group, t.name_of(c.from), t.name_of(c.to), c.tick, std::nullopt, std::nullopt, std::nullopt};
    // The old leader's loss, as the simulator saw it: the last one before the hand-over.
    for (const auto& l : sim.agents_lost) {
      if (l.agent != h.from || l.missed_tick > c.tick) continue;
      h.from_stopped_at_tick = l.missed_tick;
      h.leaderless_ticks = c.tick - l.missed_tick;
      h.detection_seconds = l.detection_seconds;
    }
    m.leader_handovers.push_back(h);
  }
  m.messages_from_deposed_leaders = not_from_a_leader_;
  // The GCS's own restarts: the simulator saw it stop and come back; the journal says what each
  // new process replayed. The n-th of each is the n-th restart.
  std::size_t nth = 0;
  for (const auto& l : sim.agents_lost) {
    if (l.agent != t.name_of(t.gcs()) || !l.restarted) continue;
    record::GcsRestart r{l.missed_tick, l.detection_seconds, l.rejoined_tick, 0, 0.0};
    if (nth < restarts_.size()) {
      r.replayed_ticks = restarts_[nth].replayed_ticks;
      r.replay_seconds = restarts_[nth].seconds;
    }
    ++nth;
    m.gcs_restarts.push_back(r);
  }
  m.planning_ms_per_group_round =
      m.planning_rounds > 0 ? 1000.0 * m.planning_seconds_total / (m.planning_rounds * t.groups()) : 0.0;
  m.explored_curve = sim.explored_curve;
  m.motion = sim.motion;
  // One entry per phase that started: the GCS's times and the task's numbers, the simulator's
  // ground-truth judge of it (motion and the task's own ground truth).
  for (std::size_t i = 0; i < phase_starts_.size(); ++i) {
    record::PhaseMetrics ph;
    ph.name = config::task_name(phases_[i]);
    ph.start_tick = phase_starts_[i];
    if (i < phase_ends_.size()) ph.end_tick = phase_ends_[i];
    const bool given_up = gave_up_ && i + 1 == phase_ends_.size();
    const bool judged_complete = i < phase_ends_.size() && !given_up;
    if (given_up) ph.gave_up = *gave_up_;
    ph.task = tasks_[i]->numbers();
    for (const auto& p : sim.phases) {
      if (p.phase != i) continue;
      ph.motion = p.motion;
      for (auto it = p.judge.begin(); it != p.judge.end(); ++it) ph.task[it.key()] = it.value();
    }
    // A phase is complete only when the ground truth agrees with the GCS's judgement.
    const auto truth = ph.task.find(record::kGroundTruthDone);
    if (truth != ph.task.end()) {
      if (truth->is_boolean()) ph.ground_truth_done = truth->get<bool>();
      ph.task.erase(truth);
    }
    if (judged_complete && ph.ground_truth_done == false) {
      ph.disagreement = "the GCS judged the phase complete; by the simulator's ground truth its work is not done";
      m.complete = false;
    }
    ph.complete = judged_complete && ph.ground_truth_done != false;
    m.phases.push_back(std::move(ph));
  }
  record::write_metrics(run_dir_ + "/metrics.json", m);

  record_.append(map_frame(last_tick_, m.planning_rounds, phase_, fused_.grid()));
  record::Frame summary;
  auto* sm = summary.mutable_summary();
  sm->set_steps(m.steps);
  sm->set_planning_rounds(m.planning_rounds);
  sm->set_complete(m.complete);
  if (m.steps_to_99) sm->set_steps_to_99(*m.steps_to_99);
  sm->set_explored_fraction(m.explored_fraction);
  record_.append(summary);
  record_.close();

  char line[256];
  std::snprintf(line, sizeof line, "%s after %u steps, %u planning rounds, %.1f%% explored (ground truth)",
                m.complete ? "complete" : "INCOMPLETE", m.steps, m.planning_rounds, 100.0 * m.explored_fraction);
  progress_.finish(line);
}

}  // namespace swarm::gcs
