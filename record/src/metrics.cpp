#include "swarm/record/metrics.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

namespace swarm::record {

using nlohmann::json;

namespace {

// Reads required keys of one JSON object; every failure names where and which key.
class Fields {
 public:
  Fields(const json& j, std::string where) : j_(j), where_(std::move(where)) {
    if (!j_.is_object()) throw MetricsError(where_ + ": expected an object");
  }
  const json& at(const char* key) const {
    if (!j_.contains(key)) throw MetricsError(where_ + ": missing key '" + key + "'");
    return j_.at(key);
  }
  template <class T>
  T get(const char* key) const {
    const json& v = at(key);
    try {
      return v.get<T>();
    } catch (const json::exception&) {
      throw MetricsError(where_ + ": key '" + key + "' has the wrong type (" + v.type_name() + ")");
    }
  }
  double number(const char* key) const {
    const json& v = at(key);
    if (!v.is_number()) throw MetricsError(where_ + ": key '" + key + "' is not a number");
    return v.get<double>();
  }
  template <class T>
  std::optional<T> optional(const char* key) const {
    const json& v = at(key);  // present, possibly null
    if (v.is_null()) return std::nullopt;
    return get<T>(key);
  }
  Fields object(const char* key) const { return Fields(at(key), where_ + "." + key); }
  const json& raw() const { return j_; }
  const std::string& where() const { return where_; }

 private:
  const json& j_;
  std::string where_;
};

template <class T>
json opt(const std::optional<T>& v) {
  return v ? json(*v) : json(nullptr);
}

}  // namespace

MotionCounts& MotionCounts::operator+=(const MotionCounts& o) {
  moves += o.moves;
  waits += o.waits;
  vertex_conflicts += o.vertex_conflicts;
  edge_conflicts += o.edge_conflicts;
  blocked_moves += o.blocked_moves;
  wall_stops += o.wall_stops;
  routes_rejected += o.routes_rejected;
  turn_eighths += o.turn_eighths;
  longest_blocked_ticks = std::max(longest_blocked_ticks, o.longest_blocked_ticks);
  return *this;
}

MotionCounts MotionCounts::operator-(const MotionCounts& o) const {
  return {moves - o.moves,
          waits - o.waits,
          vertex_conflicts - o.vertex_conflicts,
          edge_conflicts - o.edge_conflicts,
          blocked_moves - o.blocked_moves,
          wall_stops - o.wall_stops,
          routes_rejected - o.routes_rejected,
          turn_eighths - o.turn_eighths,
          longest_blocked_ticks};
}

namespace {

json counts_json(const MotionCounts& c) {
  return {{"moves", c.moves},
          {"waits", c.waits},
          {"vertex_conflicts", c.vertex_conflicts},
          {"edge_conflicts", c.edge_conflicts},
          {"blocked_moves", c.blocked_moves},
          {"wall_stops", c.wall_stops},
          {"routes_rejected", c.routes_rejected},
          {"turn_eighths", c.turn_eighths},
          {"longest_blocked_ticks", c.longest_blocked_ticks}};
}

MotionCounts counts_from(const Fields& f) {
  MotionCounts c;
  c.moves = f.get<std::uint64_t>("moves");
  c.waits = f.get<std::uint64_t>("waits");
  c.vertex_conflicts = f.get<std::uint64_t>("vertex_conflicts");
  c.edge_conflicts = f.get<std::uint64_t>("edge_conflicts");
  c.blocked_moves = f.get<std::uint64_t>("blocked_moves");
  c.wall_stops = f.get<std::uint64_t>("wall_stops");
  c.routes_rejected = f.get<std::uint64_t>("routes_rejected");
  c.turn_eighths = f.get<std::uint64_t>("turn_eighths");
  c.longest_blocked_ticks = f.get<std::uint64_t>("longest_blocked_ticks");
  return c;
}

json curve_json(const std::vector<std::pair<std::uint32_t, double>>& curve) {
  json out = json::array();
  for (const auto& [t, f] : curve) out.push_back({t, f});
  return out;
}

std::vector<std::pair<std::uint32_t, double>> curve_from(const json& j, const std::string& where) {
  if (!j.is_array()) throw MetricsError(where + ": expected an array of [tick, value]");
  std::vector<std::pair<std::uint32_t, double>> out;
  for (const json& p : j) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
      throw MetricsError(where + ": expected [tick, value] pairs");
    }
    out.emplace_back(p[0].get<std::uint32_t>(), p[1].get<double>());
  }
  return out;
}

}  // namespace

std::optional<std::uint32_t> queue_quantile(const std::vector<std::uint64_t>& queued_ticks, double q) {
  std::uint64_t total = 0;
  for (const std::uint64_t n : queued_ticks) total += n;
  if (total == 0) return std::nullopt;
  std::uint64_t below = 0;
  for (std::size_t d = 0; d < queued_ticks.size(); ++d) {
    below += queued_ticks[d];
    if (static_cast<double>(below) >= q * static_cast<double>(total)) return static_cast<std::uint32_t>(d);
  }
  return static_cast<std::uint32_t>(queued_ticks.size() - 1);
}

json to_json(const MotionNumbers& m) {
  json out = counts_json(m.total);
  out["vertex_conflict_events"] = m.vertex_conflict_events;
  out["edge_conflict_events"] = m.edge_conflict_events;
  json per = json::object();
  for (const auto& [name, c] : m.per_robot) per[name] = counts_json(c);
  out["per_robot"] = per;
  return out;
}

MotionNumbers motion_from_json(const json& j, const std::string& where) {
  const Fields f(j, where);
  MotionNumbers m;
  m.total = counts_from(f);
  m.vertex_conflict_events = f.get<std::uint64_t>("vertex_conflict_events");
  m.edge_conflict_events = f.get<std::uint64_t>("edge_conflict_events");
  const Fields per = f.object("per_robot");
  for (const auto& [name, c] : per.raw().items()) m.per_robot[name] = counts_from(Fields(c, per.where() + "." + name));
  return m;
}

json to_json(const RunMetrics& m) {
  json by_topic = json::object(), by_link = json::object();
  for (const auto& [topic, t] : m.traffic.by_topic) {
    by_topic[topic] = {{"link", t.link},
                       {"messages", t.messages},
                       {"bytes", t.bytes},
                       {"addressed_messages", t.addressed_messages},
                       {"received_messages", t.received_messages},
                       {"lost_transmissions", t.lost_transmissions},
                       {"dropped_messages", t.dropped_messages}};
  }
  for (const auto& [link, l] : m.traffic.by_link) {
    by_link[link] = {{"messages", l.messages},
                     {"bytes", l.bytes},
                     {"lost_transmissions", l.lost_transmissions},
                     {"dropped_messages", l.dropped_messages},
                     {"queued_ticks", l.queued_ticks},
                     {"queue_median_ticks", opt(queue_quantile(l.queued_ticks, 0.5))},
                     {"queue_p95_ticks", opt(queue_quantile(l.queued_ticks, 0.95))},
                     {"busiest_sender", l.busiest_sender.empty() ? json(nullptr) : json(l.busiest_sender)},
                     {"busiest_sender_bytes", l.busiest_sender_bytes}};
  }
  json rounds = json::array();
  for (const auto& [r, t] : m.rounds) rounds.push_back({{"round", r}, {"tick", t}});
  json lost = json::array();
  for (const auto& l : m.agents_lost) {
    lost.push_back({{"agent", l.agent},
                    {"marked_lost_at_tick", l.marked_lost_at_tick},
                    {"rejoined_at_tick", opt(l.rejoined_at_tick)},
                    {"stopped_answering_at_tick", opt(l.stopped_answering_at_tick)},
                    {"detection_seconds", opt(l.detection_seconds)}});
  }
  json unreachable = json::array();
  for (const auto& u : m.unreachable) {
    unreachable.push_back({{"agent", u.agent}, {"from_tick", u.from_tick}, {"to_tick", u.to_tick}});
  }
  json handovers = json::array();
  for (const auto& h : m.leader_handovers) {
    handovers.push_back({{"group", h.group},
                         {"from", h.from},
                         {"to", h.to},
                         {"at_tick", h.at_tick},
                         {"from_stopped_at_tick", opt(h.from_stopped_at_tick)},
                         {"leaderless_ticks", opt(h.leaderless_ticks)},
                         {"detection_seconds", opt(h.detection_seconds)}});
  }
  json restarts = json::array();
  for (const auto& r : m.gcs_restarts) {
    restarts.push_back({{"stopped_at_tick", opt(r.stopped_at_tick)},
                        {"detection_seconds", opt(r.detection_seconds)},
                        {"rejoined_at_tick", opt(r.rejoined_at_tick)},
                        {"replayed_ticks", r.replayed_ticks},
                        {"replay_seconds", r.replay_seconds}});
  }
  json phases = json::array();
  for (const auto& p : m.phases) {
    phases.push_back({{"name", p.name},
                      {"start_tick", p.start_tick},
                      {"end_tick", opt(p.end_tick)},
                      {"complete", p.complete},
                      {"gave_up", opt(p.gave_up)},
                      {"ground_truth_done", opt(p.ground_truth_done)},
                      {"disagreement", opt(p.disagreement)},
                      {"motion", to_json(p.motion)},
                      {"task", p.task}});
  }
  json agents = json::object();
  for (const auto& [name, a] : m.agents) agents[name] = a;
  return {{"schema_version", m.schema_version},
          {"scenario", m.scenario},
          {"map", m.map},
          {"mode", m.mode},
          {"seed", m.seed},
          {"groups", m.groups},
          {"robots_per_group", m.robots_per_group},
          {"robots", m.robots},
          {"steps", m.steps},
          {"steps_to_99", opt(m.steps_to_99)},
          {"planning_rounds", m.planning_rounds},
          {"explored_fraction", m.explored_fraction},
          {"complete", m.complete},
          {"ended", m.ended},
          {"ticks_run", m.ticks_run},
          {"wall_seconds", m.wall_seconds},
          {"ticks_per_second", m.ticks_per_second},
          {"traffic",
           {{"by_topic", by_topic},
            {"by_link", by_link},
            {"total", {{"messages", m.traffic.total_messages}, {"bytes", m.traffic.total_bytes}}}}},
          {"rounds", rounds},
          {"explored_curve", curve_json(m.explored_curve)},
          {"timings",
           {{"planning_seconds_total", m.planning_seconds_total},
            {"planning_ms_per_group_round", m.planning_ms_per_group_round}}},
          {"faults",
           {{"agents_lost", lost},
            {"unreachable", unreachable},
            {"leader_handovers", handovers},
            {"gcs_restarts", restarts},
            {"messages_from_deposed_leaders", m.messages_from_deposed_leaders}}},
          {"motion", to_json(m.motion)},
          {"phases", phases},
          {"agents", agents},
          {"reports_missing", m.reports_missing}};
}

RunMetrics metrics_from_json(const json& j, const std::string& source) {
  const Fields f(j, source);
  RunMetrics m;
  if (!j.is_object() || !j.contains("schema_version")) {
    throw MetricsError(source + ": no schema_version: written by a swarm older than metrics schema " +
                       std::to_string(kMetricsSchemaVersion) + "; re-run it with this swarm");
  }
  m.schema_version = f.get<int>("schema_version");
  if (m.schema_version != kMetricsSchemaVersion) {
    throw MetricsError(source + ": metrics schema_version " + std::to_string(m.schema_version) +
                       ", but this swarm reads version " + std::to_string(kMetricsSchemaVersion) +
                       " only; re-run it, or use the swarm that wrote it");
  }
  if (j.value("partial", false)) {
    throw PartialMetricsError(source + ": the run ended early (" + j.value("ended", std::string("no reason given")) +
                       ") before the GCS wrote its metrics; only ticks_run and the phases begun are known (partial)");
  }
  m.scenario = f.get<std::string>("scenario");
  m.map = f.get<std::string>("map");
  m.mode = f.get<std::string>("mode");
  m.seed = f.get<std::uint64_t>("seed");
  m.groups = f.get<std::uint32_t>("groups");
  m.robots_per_group = f.get<std::uint32_t>("robots_per_group");
  m.robots = f.get<std::uint32_t>("robots");
  m.steps = f.get<std::uint32_t>("steps");
  m.steps_to_99 = f.optional<std::uint32_t>("steps_to_99");
  m.planning_rounds = f.get<std::uint32_t>("planning_rounds");
  m.explored_fraction = f.number("explored_fraction");
  m.complete = f.get<bool>("complete");
  m.ended = f.get<std::string>("ended");
  m.ticks_run = f.get<std::uint32_t>("ticks_run");
  m.wall_seconds = f.number("wall_seconds");
  m.ticks_per_second = f.number("ticks_per_second");
  const Fields traffic = f.object("traffic");
  const Fields by_topic = traffic.object("by_topic");
  for (const auto& [topic, t] : by_topic.raw().items()) {
    const Fields tf(t, by_topic.where() + "." + topic);
    m.traffic.by_topic[topic] = {tf.get<std::string>("link"),
                                 tf.get<std::uint64_t>("messages"),
                                 tf.get<std::uint64_t>("bytes"),
                                 tf.get<std::uint64_t>("addressed_messages"),
                                 tf.get<std::uint64_t>("received_messages"),
                                 tf.get<std::uint64_t>("lost_transmissions"),
                                 tf.get<std::uint64_t>("dropped_messages")};
  }
  const Fields by_link = traffic.object("by_link");
  for (const auto& [link, l] : by_link.raw().items()) {
    const Fields lf(l, by_link.where() + "." + link);
    m.traffic.by_link[link] = {lf.get<std::uint64_t>("messages"), lf.get<std::uint64_t>("bytes"),
                               lf.get<std::uint64_t>("lost_transmissions"), lf.get<std::uint64_t>("dropped_messages"),
                               lf.raw().contains("queued_ticks") ? lf.get<std::vector<std::uint64_t>>("queued_ticks")
                                                                 : std::vector<std::uint64_t>{},
                               // absent from records of schema 6 written before it existed
                               lf.raw().contains("busiest_sender") ? lf.optional<std::string>("busiest_sender").value_or("") : "",
                               lf.raw().contains("busiest_sender_bytes") ? lf.get<std::uint64_t>("busiest_sender_bytes") : 0};
  }
  const Fields total = traffic.object("total");
  m.traffic.total_messages = total.get<std::uint64_t>("messages");
  m.traffic.total_bytes = total.get<std::uint64_t>("bytes");
  for (const json& r : f.at("rounds")) {
    const Fields rf(r, source + ".rounds[]");
    m.rounds.emplace_back(rf.get<std::uint32_t>("round"), rf.get<std::uint32_t>("tick"));
  }
  m.explored_curve = curve_from(f.at("explored_curve"), source + ".explored_curve");
  const Fields timings = f.object("timings");
  m.planning_seconds_total = timings.number("planning_seconds_total");
  m.planning_ms_per_group_round = timings.number("planning_ms_per_group_round");
  const Fields faults = f.object("faults");
  for (const json& l : faults.at("agents_lost")) {
    const Fields lf(l, faults.where() + ".agents_lost[]");
    m.agents_lost.push_back({lf.get<std::string>("agent"), lf.get<std::uint32_t>("marked_lost_at_tick"),
                             lf.optional<std::uint32_t>("rejoined_at_tick"),
                             lf.optional<std::uint32_t>("stopped_answering_at_tick"),
                             lf.optional<double>("detection_seconds")});
  }
  for (const json& u : faults.at("unreachable")) {
    const Fields uf(u, faults.where() + ".unreachable[]");
    m.unreachable.push_back({uf.get<std::string>("agent"), uf.get<std::uint32_t>("from_tick"),
                             uf.get<std::uint32_t>("to_tick")});
  }
  m.messages_from_deposed_leaders = faults.get<std::uint64_t>("messages_from_deposed_leaders");
  for (const json& h : faults.at("leader_handovers")) {
    const Fields hf(h, faults.where() + ".leader_handovers[]");
    m.leader_handovers.push_back({hf.get<int>("group"), hf.get<std::string>("from"), hf.get<std::string>("to"),
                                  hf.get<std::uint32_t>("at_tick"), hf.optional<std::uint32_t>("from_stopped_at_tick"),
                                  hf.optional<std::uint32_t>("leaderless_ticks"),
                                  hf.optional<double>("detection_seconds")});
  }
  if (faults.raw().contains("gcs_restarts")) {  // since the GCS restart
    for (const json& r : faults.at("gcs_restarts")) {
      const Fields rf(r, faults.where() + ".gcs_restarts[]");
      m.gcs_restarts.push_back({rf.optional<std::uint32_t>("stopped_at_tick"), rf.optional<double>("detection_seconds"),
                                rf.optional<std::uint32_t>("rejoined_at_tick"), rf.get<std::uint32_t>("replayed_ticks"),
                                rf.number("replay_seconds")});
    }
  }
  m.motion = motion_from_json(f.at("motion"), source + ".motion");
  for (const json& p : f.at("phases")) {
    const Fields pf(p, source + ".phases[]");
    PhaseMetrics ph;
    ph.name = pf.get<std::string>("name");
    ph.start_tick = pf.get<std::uint32_t>("start_tick");
    ph.end_tick = pf.optional<std::uint32_t>("end_tick");
    ph.complete = pf.get<bool>("complete");
    if (pf.raw().contains("gave_up")) ph.gave_up = pf.optional<std::string>("gave_up");  // since schema 3
    if (pf.raw().contains("ground_truth_done")) {  // since schema 5
      ph.ground_truth_done = pf.optional<bool>("ground_truth_done");
      ph.disagreement = pf.optional<std::string>("disagreement");
    }
    ph.motion = motion_from_json(pf.at("motion"), pf.where() + ".motion");
    ph.task = pf.at("task");
    m.phases.push_back(std::move(ph));
  }
  for (const auto& [name, a] : f.object("agents").raw().items()) m.agents[name] = a;
  m.reports_missing = f.get<std::vector<std::string>>("reports_missing");
  return m;
}

void write_metrics(const std::string& path, const RunMetrics& m) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << to_json(m).dump(2) << "\n";
  out.close();
  if (!out) throw MetricsError("cannot write " + path + " (" + std::strerror(errno) + ")");
}

RunMetrics read_metrics(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MetricsError("cannot open " + path + " (did the run finish?)");
  json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw MetricsError(path + " is not valid JSON: " + e.what());
  }
  return metrics_from_json(j, path);
}

json to_json(const SimReport& r) {
  json phases = json::array();
  for (const auto& p : r.phases) {
    phases.push_back({{"phase", p.phase},
                      {"name", p.name},
                      {"start_tick", p.start_tick},
                      {"motion", to_json(p.motion)},
                      {"judge", p.judge}});
  }
  json losses = json::array();
  for (const auto& l : r.agents_lost) {
    losses.push_back({{"agent", l.agent},
                      {"missed_tick", l.missed_tick},
                      {"detection_seconds", l.detection_seconds},
                      {"rejoined_tick", opt(l.rejoined_tick)},
                      {"restarted", l.restarted}});
  }
  return {{"last_tick", r.last_tick},
          {"steps_to_99", opt(r.steps_to_99)},
          {"explored_fraction", r.explored_fraction},
          {"reachable_free_cells", r.reachable_free_cells},
          {"explored_curve", curve_json(r.explored_curve)},
          {"motion", to_json(r.motion)},
          {"phases", phases},
          {"agents_lost", losses}};
}

SimReport sim_report_from_json(const json& j, const std::string& process) {
  const Fields f(j, process + "'s report");
  SimReport r;
  r.last_tick = f.get<std::uint32_t>("last_tick");
  r.steps_to_99 = f.optional<std::uint32_t>("steps_to_99");
  r.explored_fraction = f.number("explored_fraction");
  r.reachable_free_cells = f.get<std::uint32_t>("reachable_free_cells");
  r.explored_curve = curve_from(f.at("explored_curve"), f.where() + ".explored_curve");
  r.motion = motion_from_json(f.at("motion"), f.where() + ".motion");
  for (const json& p : f.at("phases")) {
    const Fields pf(p, f.where() + ".phases[]");
    r.phases.push_back({pf.get<std::uint32_t>("phase"), pf.get<std::string>("name"),
                        pf.get<std::uint32_t>("start_tick"), motion_from_json(pf.at("motion"), pf.where() + ".motion"),
                        pf.at("judge")});
  }
  for (const json& l : f.at("agents_lost")) {
    const Fields lf(l, f.where() + ".agents_lost[]");
    r.agents_lost.push_back({lf.get<std::string>("agent"), lf.get<std::uint32_t>("missed_tick"),
                             lf.number("detection_seconds"), lf.optional<std::uint32_t>("rejoined_tick"),
                             l.contains("restarted") && lf.get<bool>("restarted")});
  }
  return r;
}

}  // namespace swarm::record
