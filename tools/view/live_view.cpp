#include "live_view.hpp"

#include "swarm/app/convert.hpp"
#include "swarm/comm/endpoint.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/record/record.hpp"
#include "view_data.hpp"

namespace swarm::tools {

namespace {
enum Channel : std::uint32_t { kTf = 1, kRobots = 2, kMap = 3, kTruth = 4, kLog = 5, kRoutes = 6, kFrontiers = 7, kStatus = 8 };
// The cursor's slots: what a connection has had of each channel.
enum Slot : std::size_t { kCellsSeen, kRobotsSeen, kMapSeen, kTruthSeen, kLogSeen, kRoutesSeen, kPlansSeen, kSlots };

std::vector<planner::Cell> cells_of(const std::vector<std::int16_t>& xy) {
  std::vector<planner::Cell> out;
  for (std::size_t k = 0; k + 1 < xy.size(); k += 2) out.push_back({xy[k], xy[k + 1]});
  return out;
}

std::vector<planner::Cell> at_steps(const std::vector<planner::Cell>& route, const std::vector<std::uint32_t>& steps) {
  std::vector<planner::Cell> out;
  for (const std::uint32_t s : steps) {
    if (s < route.size()) out.push_back(route[s]);
  }
  return out;
}

// Pick and drop cells: an object's colour, and black for where things go.
const nlohmann::json kPickColour = {{"r", 0.85}, {"g", 0.65}, {"b", 0.0}, {"a", 1.0}};
const nlohmann::json kDropColour = {{"r", 0.0}, {"g", 0.0}, {"b", 0.0}, {"a", 1.0}};
}  // namespace

struct LiveView::Readers {
  std::unique_ptr<comm::Reader<msgs::Clock>> clock;
  std::unique_ptr<comm::Reader<msgs::RoundStart>> round;
  std::unique_ptr<comm::Reader<msgs::PhaseStart>> phase;
  std::unique_ptr<comm::Reader<msgs::MotionCommand>> motion;
  std::unique_ptr<comm::Reader<msgs::PlanReport>> plan;
  std::unique_ptr<comm::Reader<msgs::PlannedRoute>> planned;
};

LiveView::Setup LiveView::setup_for(const config::World& world, comm::DdsOptions dds) {
  const auto& s = world.scenario;
  Setup setup;
  setup.dds = std::move(dds);
  record::Header team;
  team.set_groups(s.groups());
  team.set_robots_per_group(s.robots_per_group());
  setup.names = record::robot_names(team);
  setup.robots_per_group = static_cast<int>(s.robots_per_group());
  setup.frame = planner::OccupancyGrid(world.truth.width(), world.truth.height(), world.truth.resolution(),
                                       world.truth.origin_x(), world.truth.origin_y());
  setup.truth = &world.truth;
  setup.tick_ns = std::uint64_t{s.tick_ms()} * 1'000'000U;
  setup.title = s.map() + ", seed " + std::to_string(s.seed());
  setup.layout = mission_layout(world);
  for (const auto& phase : config::mission_phases(s)) setup.tasks.push_back(config::task_name(phase));
  return setup;
}

LiveView::LiveView(Setup setup)
    : setup_(std::move(setup)),
      frame_{setup_.frame.resolution(), setup_.frame.origin_x(), setup_.frame.origin_y()},
      layout_(setup_.layout),
      map_(setup_.frame) {
  const std::size_t robots = setup_.names.size();
  const int groups = static_cast<int>(robots) / std::max(1, setup_.robots_per_group);
  lost_.assign(robots, false);
  took_over_.assign(robots, -1);
  routes_.resize(robots);
  plans_of_.resize(robots);
  plans_.resize(static_cast<std::size_t>(groups));
  participant_ = std::make_unique<comm::Participant>(setup_.dds);
  readers_ = std::make_unique<Readers>();
  readers_->clock = std::make_unique<comm::Reader<msgs::Clock>>(*participant_, comm::topic::kClock, [this](msgs::Clock&& c) {
    const std::lock_guard<std::mutex> lock(mutex_);
    on_clock(c);
  }, comm::EndpointKind::Watch);
  readers_->round = std::make_unique<comm::Reader<msgs::RoundStart>>(*participant_, comm::topic::kRound, [this](msgs::RoundStart&& r) {
    planner::OccupancyGrid g = setup_.frame;
    try {
      app::decode_map(r.map_rle(), static_cast<planner::PatchEncoding>(r.encoding()), g);
    } catch (const std::exception&) {
      return;  // a map of another size: not this run's
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    if (r.fused_tick() < map_tick_) return;
    map_ = std::move(g);
    map_tick_ = r.fused_tick();
    ++map_version_;
  }, comm::EndpointKind::Watch);
  readers_->phase = std::make_unique<comm::Reader<msgs::PhaseStart>>(*participant_, comm::topic::kPhase, [this](msgs::PhaseStart&& p) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::string text = "phase " + std::to_string(p.phase() + 1) + " (" + p.task() + ") " + (p.settle() ? "settling" : "started");
    if (log_.empty() || log_.back().second != text) log_.emplace_back(std::uint64_t{tick_} * setup_.tick_ns, text);
    if (static_cast<std::int64_t>(p.phase()) != phase_) {
      // A new phase: the last one's frontiers are history (its routes stop as its robots do).
      for (Plan& plan : plans_) {
        if (plan.frontiers.empty() && plan.segments.empty()) continue;
        plan = Plan{{}, {}, ++version_};
        plans_version_ = version_;
      }
      for (Route& planned : plans_of_) {
        if (planned.cells.empty()) continue;
        planned = Route{0, {}, {}, {}, ++version_};
        routes_version_ = version_;
      }
    }
    phase_ = p.phase();
    task_ = p.task();
    settling_ = p.settle();
  }, comm::EndpointKind::Watch);
  readers_->motion =
      std::make_unique<comm::Reader<msgs::MotionCommand>>(*participant_, comm::topic::kMotion, [this](msgs::MotionCommand&& m) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (m.robot() >= routes_.size()) return;
        Route& r = routes_[m.robot()];
        if (r.version > 0 && m.route_id() < r.id) return;  // overtaken on its way (sim::World::command)
        r.id = m.route_id();
        r.cells = cells_of(m.path_xy());
        r.picks = at_steps(r.cells, m.pick_steps());
        r.drops = at_steps(r.cells, m.drop_steps());
        r.version = ++version_;
        routes_version_ = version_;
      }, comm::EndpointKind::Watch);
  readers_->plan =
      std::make_unique<comm::Reader<msgs::PlanReport>>(*participant_, comm::topic::kPlanReport, [this](msgs::PlanReport&& p) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (p.group() >= plans_.size()) return;
        Plan& plan = plans_[p.group()];
        plan.frontiers = cells_of(p.group_frontiers_xy());
        plan.segments.clear();
        for (const auto& segment : p.global_segments_xy()) {
          for (const planner::Cell c : cells_of(segment)) plan.segments.push_back(c);
        }
        plan.version = ++version_;
        plans_version_ = version_;
      }, comm::EndpointKind::Watch);
  readers_->planned =
      std::make_unique<comm::Reader<msgs::PlannedRoute>>(*participant_, comm::topic::kPlanned, [this](msgs::PlannedRoute&& p) {
        // A cover division's route (its region) or a mapf plan's path; not the traffic layer's
        // windows, which the robots' motion commands show.
        const bool mapf = p.phase() < setup_.tasks.size() && setup_.tasks[p.phase()] == "mapf";
        if (p.region_cells() == 0 && !mapf) return;
        const std::lock_guard<std::mutex> lock(mutex_);
        if (p.robot() >= plans_of_.size()) return;
        Route& planned = plans_of_[p.robot()];
        planned.id = p.phase();
        planned.cells = cells_of(p.path_xy());
        planned.version = ++version_;
        routes_version_ = version_;
      }, comm::EndpointKind::Watch);
}

LiveView::~LiveView() {
  readers_.reset();
  participant_.reset();
}

void LiveView::on_clock(const msgs::Clock& c) {
  if (c.tick() < tick_ && cells_version_ > 0) return;  // an old clock repeated
  tick_ = c.tick();
  cells_.clear();
  for (const auto& r : c.robots()) cells_.push_back({r.x(), r.y()});
  cells_version_ = ++version_;
  tally_ = c.tally();
  sent_bytes_ = c.sent_bytes();
  const auto name = [&](std::size_t r) { return r < setup_.names.size() ? setup_.names[r] : "robot " + std::to_string(r); };
  const std::uint64_t ns = std::uint64_t{tick_} * setup_.tick_ns;
  for (std::size_t r = 0; r < c.robots().size() && r < lost_.size(); ++r) {
    if (c.robots()[r].alive() == !lost_[r]) continue;
    lost_[r] = !c.robots()[r].alive();
    ++lost_version_;
    log_.emplace_back(ns, event_text(lost_[r] ? TeamEvent::Lost : TeamEvent::Back, name(r), 0, tick_));
  }
  // Take-overs: a group led by another robot than the last clock said, or, in the first clock this
  // view sees (it may attach late), by another than its first leader.
  for (std::size_t g = 0; g < c.leaders().size() && g < plans_.size(); ++g) {
    const std::uint16_t now = c.leaders()[g];
    const std::uint16_t before = g < leaders_.size() ? leaders_[g] : static_cast<std::uint16_t>(g * setup_.robots_per_group);
    if (now == before || now >= took_over_.size()) continue;
    if (before < took_over_.size()) took_over_[before] = -1;
    took_over_[now] = now % setup_.robots_per_group == 0 ? -1 : static_cast<int>(g);
    ++lost_version_;
    log_.emplace_back(ns, event_text(TeamEvent::TakeOver, name(now), static_cast<int>(g), tick_));
  }
  leaders_ = c.leaders();
}

nlohmann::json LiveView::status_json() const {
  StatusFacts s;
  s.tick = tick_;
  s.phase = phase_;
  s.task = task_;
  s.settling = settling_;
  s.vertex_conflicts = tally_.vertex_conflicts();
  s.edge_conflicts = tally_.edge_conflicts();
  s.blocked_moves = tally_.blocked_moves();
  s.progress_done = tally_.progress_done();
  s.progress_total = tally_.progress_total();
  s.sent_bytes = sent_bytes_;
  s.objects.assign(tally_.objects().begin(), tally_.objects().end());
  for (const bool b : lost_) s.lost_robots += b ? 1 : 0;
  return status_message(s);
}

void LiveView::add_route_entities(nlohmann::json& entities, const std::string& kind, std::size_t robot, const Route& r,
                                  std::uint64_t ns) const {
  const int group = static_cast<int>(robot) / std::max(1, setup_.robots_per_group);
  const std::string& name = setup_.names[robot];
  const std::string prefix = kind == "route" ? "" : kind + "_";
  nlohmann::json line = foxglove_entity(kind + "/" + name, ns);
  add_line(line, r.cells, group_colour(group, kind == "route" ? 0.6 : 0.3), frame_);
  nlohmann::json picks = foxglove_entity(prefix + "picks/" + name, ns);
  add_cells(picks, r.picks, kPickColour, frame_);
  nlohmann::json drops = foxglove_entity(prefix + "drops/" + name, ns);
  add_cells(drops, r.drops, kDropColour, frame_);
  entities.push_back(std::move(line));
  entities.push_back(std::move(picks));
  entities.push_back(std::move(drops));
}

nlohmann::json LiveView::routes_since(std::uint64_t seen, std::uint64_t ns) const {
  nlohmann::json entities = nlohmann::json::array();
  for (std::size_t r = 0; r < routes_.size(); ++r) {
    if (routes_[r].version > seen) add_route_entities(entities, "route", r, routes_[r], ns);
    if (plans_of_[r].version > seen) add_route_entities(entities, "plan", r, plans_of_[r], ns);
  }
  return {{"deletions", nlohmann::json::array()}, {"entities", std::move(entities)}};
}

nlohmann::json LiveView::frontiers_since(std::uint64_t seen, std::uint64_t ns) const {
  nlohmann::json entities = nlohmann::json::array();
  for (std::size_t g = 0; g < plans_.size(); ++g) {
    const Plan& plan = plans_[g];
    if (plan.version <= seen) continue;
    nlohmann::json group = foxglove_entity("frontiers/" + std::to_string(g), ns);
    add_cells(group, plan.frontiers, group_colour(static_cast<int>(g), 0.6), frame_);
    nlohmann::json segments = foxglove_entity("segments/" + std::to_string(g), ns);
    add_cells(segments, plan.segments, group_colour(static_cast<int>(g), 0.25), frame_);
    entities.push_back(std::move(group));
    entities.push_back(std::move(segments));
  }
  return {{"deletions", nlohmann::json::array()}, {"entities", std::move(entities)}};
}

std::vector<LiveChannel> LiveView::channels() const {
  std::vector<LiveChannel> out = {{kTf, "/tf", "foxglove.FrameTransforms", ""},
                                  {kRobots, "/robots", "foxglove.SceneUpdate", ""},
                                  {kMap, "/map", "foxglove.Grid", ""},
                                  {kLog, "/log", "foxglove.Log", ""},
                                  {kRoutes, "/routes", "foxglove.SceneUpdate", ""},
                                  {kFrontiers, "/frontiers", "foxglove.SceneUpdate", ""},
                                  {kStatus, "/status", kStatusSchemaName, ""}};
  if (setup_.truth != nullptr) out.push_back({kTruth, "/map/truth", "foxglove.Grid", ""});
  for (LiveChannel& c : out) c.schema = (c.schema_name == kStatusSchemaName ? status_schema() : foxglove_schema(c.schema_name)).dump();
  return out;
}

std::vector<LiveMessage> LiveView::since(std::vector<std::uint64_t>& cursor) const {
  cursor.resize(kSlots, 0);
  std::vector<LiveMessage> out;
  if (setup_.truth != nullptr && cursor[kTruthSeen] == 0) {
    out.push_back({kTruth, 0, foxglove_grid(*setup_.truth, 0).dump()});
    cursor[kTruthSeen] = 1;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  const std::uint64_t ns = std::uint64_t{tick_} * setup_.tick_ns;
  if (lost_version_ > cursor[kRobotsSeen]) {
    out.push_back({kRobots, ns, foxglove_robots(setup_.names, setup_.robots_per_group, frame_.resolution, lost_, took_over_).dump()});
    cursor[kRobotsSeen] = lost_version_;
  }
  if (map_version_ > cursor[kMapSeen]) {
    const std::uint64_t map_ns = map_tick_ * setup_.tick_ns;
    out.push_back({kMap, map_ns, foxglove_grid(map_, map_ns).dump()});
    cursor[kMapSeen] = map_version_;
  }
  if (plans_version_ > cursor[kPlansSeen]) {
    out.push_back({kFrontiers, ns, frontiers_since(cursor[kPlansSeen], ns).dump()});
    cursor[kPlansSeen] = plans_version_;
  }
  if (routes_version_ > cursor[kRoutesSeen]) {
    out.push_back({kRoutes, ns, routes_since(cursor[kRoutesSeen], ns).dump()});
    cursor[kRoutesSeen] = routes_version_;
  }
  if (cells_version_ > cursor[kCellsSeen]) {
    out.push_back({kTf, ns, foxglove_transforms(setup_.names, cells_, frame_, ns).dump()});
    out.push_back({kStatus, ns, status_json().dump()});
    cursor[kCellsSeen] = cells_version_;
  }
  for (std::size_t k = cursor[kLogSeen]; k < log_.size(); ++k) {
    out.push_back({kLog, log_[k].first, foxglove_log(log_[k].second, log_[k].first).dump()});
  }
  cursor[kLogSeen] = log_.size();
  return out;
}

std::string LiveView::setup_json() const {
  const nlohmann::json j = {{"live", true},
                            {"width", setup_.frame.width()},
                            {"height", setup_.frame.height()},
                            {"resolution", frame_.resolution},
                            {"origin", {frame_.origin_x, frame_.origin_y}},
                            {"names", setup_.names},
                            {"robots_per_group", setup_.robots_per_group},
                            {"groups", setup_.names.size() / static_cast<std::size_t>(std::max(1, setup_.robots_per_group))},
                            {"tick_ns", setup_.tick_ns},
                            {"title", setup_.title},
                            {"links", link_names()},
                            {"layout", layout_}};
  return j.dump();
}

}  // namespace swarm::tools
