#include "swarm/gcs/gcs_node.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "swarm/comm/convert.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/planner/map_patch.hpp"

namespace swarm::gcs {

using comm::LinkClass;
using nlohmann::json;
namespace topic = comm::topic;

namespace {

MissionConfig mission_config(const comm::RoleSetup& setup) {
  const auto& s = setup.world.scenario;
  MissionConfig c;
  c.groups = setup.topology.groups();
  c.start_cells = setup.world.robot_cells;
  c.replan_threshold = s.explore().replan_threshold_steps();
  // Ideal mode is the paper's "no delay" comparison: the map fused now is used now.
  c.map_delay_rounds = s.explore().mode() == swarm::scenario::IDEAL ? 0 : s.explore().global_map_delay_rounds();
  return c;
}

// Adds n to obj[key], creating it (and obj) as needed.
void add(json& obj, const char* key, std::uint64_t n) {
  if (!obj.is_object()) obj = json::object();
  obj[key] = obj.value(key, std::uint64_t{0}) + n;
}

// How many ticks of silence make a leader unreachable. In lockstep a heartbeat sent at t is seen
// at t + 1 + delay (+ jitter): two ticks of slack. In real time a busy machine delays a process by
// a few ticks of 40 ms now and then, which is not a cut link: half a second of slack.
std::uint32_t unreachable_after_ticks(const comm::LinkTable& links) {
  const comm::LinkParams& p = links[LinkClass::LeaderGcs];
  if (!links.realtime) return 3 + p.delay_ticks + p.jitter_ticks;
  return 1 + static_cast<std::uint32_t>(std::ceil((p.delay_ms + 500.0) / links.tick_ms));
}

record::Frame map_frame(std::uint32_t tick, std::uint32_t round, const planner::OccupancyGrid& map) {
  record::Frame f;
  auto* m = f.mutable_map();
  m->set_tick(tick);
  m->set_round(round);
  const auto rle = planner::encode_grid_rle(map);
  m->set_rle(std::string(rle.begin(), rle.end()));
  return f;
}

}  // namespace

GcsNode::GcsNode(comm::LockstepAgent& agent, const comm::RoleSetup& setup, const std::string& run_dir,
                 Progress::Style progress)
    : agent_(agent),
      setup_(setup),
      run_dir_(run_dir),
      mission_(setup.world.truth.width(), setup.world.truth.height(), setup.world.truth.resolution(),
               mission_config(setup)),
      encoding_(comm::patch_encoding(setup.world.scenario.map_encoding())),
      progress_(progress, setup.world.scenario.max_ticks()),
      record_(record::run_record_path(run_dir)),
      round_(agent.advertise<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs, setup.topology.leaders())),
      last_heard_(setup.topology.groups(), 0),
      unreachable_after_ticks_(unreachable_after_ticks(setup.links)),
      unreachable_(setup.topology.groups()),
      robots_lost_(setup.topology.robots()) {
  agent.subscribe<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, [this](const msgs::Heartbeat& h) {
    if (h.group() < last_heard_.size()) last_heard_[h.group()] = agent_.tick();
  }, comm::Delivery::Reliable, setup.topology.groups());
  agent.subscribe<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, [this](const msgs::MapPatch& p) {
    mission_.fuse(p.group(), comm::decode_patch(p.data()));
  }, comm::Delivery::Reliable, setup.topology.groups());
  agent.subscribe<msgs::GroupStatus>(topic::kGroupStatus, LinkClass::LeaderGcs,
                                     [this](const msgs::GroupStatus& s) { mission_.group_arrived(s.group(), s.round()); },
                                     comm::Delivery::Reliable, setup.topology.groups());
  agent.subscribe<msgs::PlanReport>(topic::kPlanReport, LinkClass::Telemetry,
                                    [this](const msgs::PlanReport& p) { on_plan(p); }, comm::Delivery::Reliable,
                                    setup.topology.groups());
  reports_reader_ = std::make_unique<comm::Reader<msgs::AgentReport>>(
      agent.participant(), topic::kReport, [this](msgs::AgentReport&& r) {
        std::lock_guard<std::mutex> lock(reports_mutex_);
        reports_[r.agent()] = std::move(r);
      });

  record::Frame header;
  auto* h = header.mutable_header();
  *h->mutable_scenario() = setup.world.scenario;
  const auto& truth = setup.world.truth;
  h->set_width(truth.width());
  h->set_height(truth.height());
  h->set_resolution(truth.resolution());
  h->set_origin_x(truth.origin_x());
  h->set_origin_y(truth.origin_y());
  h->set_start_x(setup.world.start.x);
  h->set_start_y(setup.world.start.y);
  h->set_groups(setup.topology.groups());
  h->set_robots_per_group(setup.topology.robots_per_group());
  record_.append(header);
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
  record_.append(f);
}

bool GcsNode::step(const msgs::Clock& clock) {
  const auto now = std::chrono::steady_clock::now();
  if (clock.tick() == 0) first_tick_time_ = now;
  last_tick_time_ = now;
  last_tick_ = clock.tick();

  std::vector<planner::Cell> robots;
  record::Frame poses;
  poses.mutable_poses()->set_tick(clock.tick());
  for (const auto& r : clock.robots()) {
    robots.push_back({r.x(), r.y()});
    poses.mutable_poses()->add_xy(r.x());
    poses.mutable_poses()->add_xy(r.y());
  }
  record_.append(poses);

  const Mission::Decision d = mission_.tick(clock.tick(), robots);
  if (d.start_round) {
    msgs::RoundStart rs;
    rs.round(*d.start_round);
    rs.fused_tick(d.map_tick);
    rs.width(static_cast<std::uint16_t>(d.map->width()));
    rs.height(static_cast<std::uint16_t>(d.map->height()));
    rs.encoding(static_cast<std::uint8_t>(encoding_ == planner::PatchEncoding::ZstdRunLength
                                              ? planner::PatchEncoding::ZstdRunLength
                                              : planner::PatchEncoding::RunLength));
    rs.map_rle(comm::encode_map(*d.map, encoding_));
    round_.send(rs);
    record::Frame version = map_frame(clock.tick(), *d.start_round, mission_.fused());
    version.mutable_map()->set_planning_map_tick(d.map_tick);  // names the map rs carries
    record_.append(version);
  }
  if (d.complete && !complete_tick_) complete_tick_ = clock.tick();

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
  progress_.update(clock.tick(), mission_.mapped_fraction(), mission_.round(), mission_.frontier_cells(), note);
  return d.complete;
}

void GcsNode::finish() {
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
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
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
  const bool complete = complete_tick_.has_value();
  const std::uint32_t steps = complete ? *complete_tick_ : last_tick_ + 1;
  json sim_extra = json::object();
  if (auto it = reports.find(setup_.topology.sim()); it != reports.end()) sim_extra = json::parse(it->second.extra_json());

  json by_topic = json::object(), by_link = json::object(), agents = json::object();
  std::uint64_t total_messages = 0, total_bytes = 0;
  json missing = json::array();
  for (int a = 0; a < setup_.topology.agents(); ++a) {
    if (!reports.count(static_cast<comm::AgentId>(a))) missing.push_back(setup_.topology.name_of(static_cast<comm::AgentId>(a)));
  }
  for (const auto& [id, r] : reports) {
    agents[setup_.topology.name_of(id)] = r.extra_json().empty() ? json::object() : json::parse(r.extra_json());
    for (const auto& t : r.traffic()) {
      json& bt = by_topic[t.topic()];
      add(bt, "messages", t.sent_messages());
      add(bt, "bytes", t.sent_bytes());
      add(bt, "received_messages", t.received_messages());
      add(bt, "lost_transmissions", t.lost_transmissions());
      add(bt, "dropped_messages", t.dropped_messages());
      bt["link"] = t.link();
      json& bl = by_link[t.link()];
      add(bl, "messages", t.sent_messages());
      add(bl, "bytes", t.sent_bytes());
      add(bl, "lost_transmissions", t.lost_transmissions());
      add(bl, "dropped_messages", t.dropped_messages());
      total_messages += t.sent_messages();
      total_bytes += t.sent_bytes();
    }
  }
  const auto tick_or_null = [](const std::optional<std::uint32_t>& t) { return t ? json(*t) : json(nullptr); };
  json unreachable = json::array();
  for (const auto& o : unreachable_.intervals()) {
    unreachable.push_back(
        {{"agent", "leader-" + std::to_string(o.who)}, {"from_tick", o.from}, {"to_tick", o.to.value_or(last_tick_ + 1)}});
  }
  // The GCS saw each loss in the clock's robot states; the simulator knows when the agent went
  // silent and how long DDS took to say so. The n-th loss of an agent is the n-th on both sides.
  json agents_lost = json::array();
  std::map<std::string, std::size_t> seen;
  const json sim_losses = sim_extra.value("agents_lost", json::array());
  for (const auto& o : robots_lost_.intervals()) {
    const std::string name = setup_.topology.name_of(static_cast<comm::AgentId>(o.who));
    json entry = {{"agent", name}, {"marked_lost_at_tick", o.from}, {"rejoined_at_tick", tick_or_null(o.to)}};
    const std::size_t nth = seen[name]++;
    std::size_t i = 0;
    for (const auto& l : sim_losses) {
      if (l.value("agent", "") != name) continue;
      if (i++ < nth) continue;
      entry["stopped_answering_at_tick"] = l["missed_tick"];
      entry["detection_seconds"] = l["detection_seconds"];
      break;
    }
    agents_lost.push_back(entry);
  }
  json rounds = json::array();
  for (std::size_t i = 0; i < mission_.round_ticks().size(); ++i) {
    rounds.push_back({{"round", i + 1}, {"tick", mission_.round_ticks()[i]}});
  }
  double planning_seconds = 0;
  for (int g = 0; g < setup_.topology.groups(); ++g) {
    const auto it = agents.find(setup_.topology.name_of(setup_.topology.leader(g)));
    if (it != agents.end() && it->is_object()) planning_seconds += it->value("planning_seconds", 0.0);
  }
  const std::uint32_t ticks_run = last_tick_ + 1;
  json metrics = {
      {"scenario", s.name()},
      {"map", s.map()},
      {"mode", config::mode_name(s.explore().mode())},
      {"seed", s.seed()},
      {"groups", s.groups()},
      {"robots_per_group", s.robots_per_group()},
      {"robots", s.groups() * s.robots_per_group()},
      {"steps", steps},
      {"steps_to_99", sim_extra.contains("steps_to_99") ? sim_extra["steps_to_99"] : json(nullptr)},
      {"planning_rounds", mission_.round()},
      {"explored_fraction", sim_extra.value("explored_fraction", 0.0)},
      {"complete", complete},
      {"ticks_run", ticks_run},
      {"wall_seconds", wall},
      {"ticks_per_second", wall > 0 ? ticks_run / wall : 0.0},
      {"traffic", {{"by_topic", by_topic}, {"by_link", by_link}, {"total", {{"messages", total_messages}, {"bytes", total_bytes}}}}},
      {"rounds", rounds},
      {"explored_curve", sim_extra.value("explored_curve", json::array())},
      {"timings", {{"planning_seconds_total", planning_seconds},
                   {"planning_ms_per_group_round",
                    mission_.round() > 0 ? 1000.0 * planning_seconds / (mission_.round() * setup_.topology.groups()) : 0.0}}},
      {"faults", {{"agents_lost", agents_lost}, {"unreachable", unreachable}}},
      {"agents", agents},
      {"reports_missing", missing}};
  std::ofstream(run_dir_ + "/metrics.json") << metrics.dump(2) << "\n";

  record_.append(map_frame(last_tick_, mission_.round(), mission_.fused()));
  record::Frame summary;
  auto* sm = summary.mutable_summary();
  sm->set_steps(steps);
  sm->set_planning_rounds(mission_.round());
  sm->set_complete(complete);
  if (sim_extra.contains("steps_to_99") && !sim_extra["steps_to_99"].is_null()) sm->set_steps_to_99(sim_extra["steps_to_99"]);
  sm->set_explored_fraction(sim_extra.value("explored_fraction", 0.0));
  record_.append(summary);
  record_.close();

  char line[256];
  std::snprintf(line, sizeof line, "%s after %u steps, %u planning rounds, %.1f%% explored (ground truth)",
                complete ? "complete" : "INCOMPLETE", steps, mission_.round(),
                100.0 * sim_extra.value("explored_fraction", 0.0));
  progress_.finish(line);
}

}  // namespace swarm::gcs
