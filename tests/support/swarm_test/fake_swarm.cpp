// FakeSwarm (fake_swarm.hpp), compiled once for every test that runs a swarm on the fake bus.
#include "swarm_test/fake_swarm.hpp"

namespace swarm::test {

namespace {

template <class T>
struct Tag {
  using type = T;
};

}  // namespace

app::RoleSetup setup_for(const planner::OccupancyGrid& truth, planner::Cell start, swarm::scenario::Scenario scenario) {
  app::RoleSetup setup;
  setup.world.scenario = std::move(scenario);
  setup.world.truth = truth;
  setup.world.start = start;
  const auto& s = setup.world.scenario;
  setup.world.robot_cells = planner::start_cells(truth, start, static_cast<int>(s.groups() * s.robots_per_group()));
  if (setup.world.robot_cells.size() != s.groups() * s.robots_per_group()) {
    throw std::invalid_argument("setup_for: not enough free cells around the start for every robot");
  }
  setup.world.frame = config::MapFrame::of(truth);
  tasks::resolve_mission(setup.world, "test scenario");
  setup.topology = comm::Topology(static_cast<int>(s.groups()), static_cast<int>(s.robots_per_group()),
                                  config::leader_standbys(s));
  setup.links = app::link_table(s, setup.topology);
  // One setup serves the fake simulator and the roles: it keeps the truth, and gives the roles the
  // map as load_role would.
  if (config::any_map_given(s)) setup.given_map = setup.world.truth;
  return setup;
}

app::RoleSetup setup_from_text(const std::string& scenario_text) {
  auto s = config::parse_scenario_text(scenario_text, "test scenario");
  config::validate(s, "test scenario");
  app::RoleSetup setup;
  setup.world = config::resolve_world(s, "");
  tasks::resolve_mission(setup.world, "test scenario");
  setup.topology = comm::Topology(static_cast<int>(setup.world.scenario.groups()),
                                  static_cast<int>(setup.world.scenario.robots_per_group()),
                                  config::leader_standbys(setup.world.scenario));
  setup.links = app::link_table(setup.world.scenario, setup.topology);
  if (config::any_map_given(setup.world.scenario)) setup.given_map = setup.world.truth;
  return setup;
}

FakeSwarm::FakeSwarm(app::RoleSetup setup, std::set<comm::AgentId> scripted, gcs::GcsTaskFactory gcs_tasks)
    : setup_(std::move(setup)), scripted_(std::move(scripted)), gcs_tasks_(std::move(gcs_tasks)) {
  const comm::Topology& t = setup_.topology;
  for (int a = 0; a < t.agents(); ++a) buses_.push_back(std::make_unique<comm::FakeBus>(net_));
  clock_ = std::make_unique<comm::LockstepClock>(*buses_[t.sim()], t, setup_.links);
  sim_ = std::make_unique<sim::SimNode>(*clock_, setup_, tasks::sim_part);
  agents_.resize(static_cast<std::size_t>(t.agents()));
  const auto agent = [&](comm::AgentId id) -> comm::LockstepAgent& {
    agents_[id] = std::make_unique<comm::LockstepAgent>(*buses_[id], t, setup_.links, id);
    return *agents_[id];
  };
  const auto node = [&](comm::AgentId id) { return scripted_.count(id) == 0; };
  if (node(t.gcs())) {
    gcs_ = std::make_unique<gcs::GcsNode>(agent(t.gcs()), setup_, dir_.str(), gcs::Progress::Style::None, gcs_tasks_);
  } else {
    agent(t.gcs());
  }
  // As the processes do: a candidate leader (comm/leadership.hpp) is a CandidateNode, any other
  // robot a MemberNode with its own RobotAgent.
  for (int g = 0; g < t.groups(); ++g) {
    for (int i = 0; i < t.robots_per_group(); ++i) {
      const comm::AgentId id = t.robot(g, i);
      if (!node(id)) {
        agent(id);
      } else if (t.is_candidate(id)) {
        candidates_[id] = std::make_unique<app::CandidateNode>(agent(id), setup_, g, i, tasks::group_task);
      } else {
        bodies_[id] = std::make_unique<member::RobotAgent>(setup_.world.truth.width(), setup_.world.truth.height(),
                                                           setup_.world.truth.resolution());
        members_[id] = std::make_unique<member::MemberNode>(agent(id), setup_, g, *bodies_[id]);
      }
    }
  }
  alive_.assign(static_cast<std::size_t>(t.agents()), true);
}

void FakeSwarm::complete_endpoints(comm::AgentId a) {
  using comm::LinkClass;
  namespace topic = comm::topic;
  const comm::Topology& t = topology();
  comm::LockstepAgent& x = *agents_.at(a);
  const auto sub = [&](auto tag, const std::string& name, LinkClass link, int writers,
                       comm::Delivery d = comm::Delivery::Reliable) {
    using T = typename decltype(tag)::type;
    if (!x.subscribes(name) && writers > 0) x.template subscribe<T>(name, link, [](const T&) {}, d, writers);
  };
  const auto pub = [&](auto tag, const std::string& name, LinkClass link, std::vector<comm::AgentId> to) {
    using T = typename decltype(tag)::type;
    if (!x.advertises(name) && !to.empty()) x.template advertise<T>(name, link, std::move(to));
  };
  const std::vector<comm::AgentId> leaders = t.all_candidates();
  if (a == t.gcs()) {
    const int writers = static_cast<int>(leaders.size());
    sub(Tag<msgs::Heartbeat>{}, topic::kHeartbeat, LinkClass::LeaderGcs, writers);
    sub(Tag<msgs::MapPatch>{}, topic::kPatchGcs, LinkClass::LeaderGcs, writers);
    sub(Tag<msgs::TaskReport>{}, topic::kTaskReport, LinkClass::LeaderGcs, writers);
    sub(Tag<msgs::PlanReport>{}, topic::kPlanReport, LinkClass::Telemetry, writers);
    pub(Tag<msgs::PhaseStart>{}, topic::kPhase, LinkClass::LeaderGcs, leaders);
    pub(Tag<msgs::PhaseStart>{}, topic::kPhaseSim, LinkClass::Control, {t.sim()});
    pub(Tag<msgs::TaskOrder>{}, topic::kTaskOrder, LinkClass::LeaderGcs, leaders);
    pub(Tag<msgs::RoundStart>{}, topic::kRound, LinkClass::LeaderGcs, leaders);
    return;
  }
  const int g = t.group_of(a);
  const auto others = t.group_except(g, a);
  const auto up = member::leaders_except_self(t, g, a);
  const int candidates = static_cast<int>(up.size());
  sub(Tag<msgs::Sense>{}, topic::sense(a), LinkClass::SimRobot, 1, comm::Delivery::BestEffort);
  pub(Tag<msgs::MotionCommand>{}, topic::kMotion, LinkClass::SimRobot, {t.sim()});
  // Every robot's member side (a candidate's too).
  sub(Tag<msgs::MapPatch>{}, topic::patch_down(g), LinkClass::MemberLeader, candidates);
  sub(Tag<msgs::Route>{}, topic::route(g), LinkClass::MemberLeader, candidates);
  sub(Tag<msgs::RouteRelease>{}, topic::release(g), LinkClass::MemberLeader, candidates);
  pub(Tag<msgs::MapPatch>{}, topic::patch_up(g), LinkClass::MemberLeader, up);
  pub(Tag<msgs::RouteProgress>{}, topic::progress(g), LinkClass::MemberLeader, up);
  if (t.is_candidate(a)) {
    const int robots = static_cast<int>(others.size());
    sub(Tag<msgs::MapPatch>{}, topic::patch_up(g), LinkClass::MemberLeader, robots);
    sub(Tag<msgs::RouteProgress>{}, topic::progress(g), LinkClass::MemberLeader, robots);
    sub(Tag<msgs::RoundStart>{}, topic::kRound, LinkClass::LeaderGcs, 1);
    sub(Tag<msgs::PhaseStart>{}, topic::kPhase, LinkClass::LeaderGcs, 1);
    sub(Tag<msgs::TaskOrder>{}, topic::kTaskOrder, LinkClass::LeaderGcs, 1);
    pub(Tag<msgs::MapPatch>{}, topic::kPatchGcs, LinkClass::LeaderGcs, {t.gcs()});
    pub(Tag<msgs::Heartbeat>{}, topic::kHeartbeat, LinkClass::LeaderGcs, {t.gcs()});
    pub(Tag<msgs::PlanReport>{}, topic::kPlanReport, LinkClass::Telemetry, {t.gcs()});
    pub(Tag<msgs::TaskReport>{}, topic::kTaskReport, LinkClass::LeaderGcs, {t.gcs()});
    pub(Tag<msgs::MapPatch>{}, topic::patch_down(g), LinkClass::MemberLeader, others);
    pub(Tag<msgs::Route>{}, topic::route(g), LinkClass::MemberLeader, others);
    pub(Tag<msgs::RouteRelease>{}, topic::release(g), LinkClass::MemberLeader, others);
  }
}

void FakeSwarm::start() {
  for (comm::AgentId a : scripted_) complete_endpoints(a);
  // On the fake, whatever is not matched at once never will be, and nothing waits for a slow
  // peer: a test with a missing endpoint fails in seconds, naming it, instead of after 60 s.
  ::setenv("SWARM_STALL_TIMEOUT", "2", 0);
  for (auto& a : agents_) {
    if (a) a->announce_ready();
  }
  clock_->wait_ready();
}

bool FakeSwarm::step() {
  if (stopped_) return false;
  sim_->begin_tick(tick_);
  for (std::size_t a = 0; a < agents_.size(); ++a) {
    if (!agents_[a] || !alive_[a]) continue;
    const msgs::Clock* clock = agents_[a]->begin_tick();
    if (clock == nullptr) continue;
    bool complete = false;
    const comm::AgentId id = static_cast<comm::AgentId>(a);
    if (scripted_.count(id)) {
      if (auto it = scripts_.find(id); it != scripts_.end()) it->second(*clock);
    } else if (id == topology().gcs()) {
      complete = gcs_->step(*clock);
      complete_ = complete_ || complete;
    } else if (const auto c = candidates_.find(id); c != candidates_.end()) {
      c->second->step(*clock);
    } else {
      members_.at(id)->step(*clock);
    }
    agents_[a]->end_tick(complete);
  }
  stopped_ = sim_->end_tick(tick_);
  ++tick_;
  return !stopped_;
}

bool FakeSwarm::run_until(const std::function<bool()>& done, int max_ticks) {
  for (int i = 0; i < max_ticks; ++i) {
    if (!step()) return done();
    if (done()) return true;
  }
  return false;
}

void FakeSwarm::disconnect(comm::AgentId a) {
  alive_.at(a) = false;
  net_.disconnect(*buses_.at(a));
}

nlohmann::json FakeSwarm::run_to_end(const std::function<void(std::uint32_t)>& at) {
  start();
  while (step()) {
    if (at) at(tick());
  }
  finish();
  std::ifstream in(run_dir() + "/metrics.json");
  return nlohmann::json::parse(in);
}

void FakeSwarm::finish(bool sim_reports, const std::optional<std::string>& sim_json) {
  for (std::size_t a = 0; a < agents_.size(); ++a) {
    const comm::AgentId id = static_cast<comm::AgentId>(a);
    if (!agents_[a] || !alive_[a] || id == topology().gcs()) continue;
    if (scripted_.count(id)) {
      agents_[a]->send_report("scripted", "{}");
    } else if (const auto c = candidates_.find(id); c != candidates_.end()) {
      agents_[a]->send_report(topology().index_of(id) == 0 ? "leader" : "member", c->second->report_json());
    } else {
      agents_[a]->send_report("member", members_.at(id)->report_json());
    }
  }
  if (sim_reports) clock_->send_report("sim", sim_json ? *sim_json : sim_->report_json());
  if (gcs_) gcs_->finish(std::chrono::milliseconds(sim_reports ? 15000 : 100));
}

nlohmann::json run_text(const std::string& scenario_text) {
  FakeSwarm s(setup_from_text(scenario_text));
  return s.run_to_end();
}

}  // namespace swarm::test
