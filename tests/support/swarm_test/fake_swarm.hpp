// A whole swarm in one thread on the in-process FakeBus (comm/fake_bus.hpp): the real node classes
// (SimNode, GcsNode, LeaderNode, MemberNode) over the real lockstep protocol, link emulation and
// traffic accounting, without DDS traffic or processes. A tick is: the simulator begins it (motion,
// scans, Clock), every living agent steps in id order, the simulator ends it. Runs are
// deterministic and take milliseconds, so role behaviour is unit-tested here; what only real DDS
// can show (discovery, liveliness leases, processes) stays in the multi-process tests.
//
//   swarm::test::FakeSwarm s(swarm::test::setup_from_text("map: 'small' groups: 1"));
//   s.start();
//   s.run_until([&] { return s.sim().world().robots()[1] == goal; }, 200);
//   s.disconnect(s.topology().robot(0, 2));   // as a crash: the others must notice
//   s.finish();                               // reports + metrics.json in s.run_dir()
//
// Scripted agents: an agent listed in `scripted` gets a bare LockstepAgent and no node; the test
// advertises and subscribes on it (agent(id)) before start() and acts for it each tick
// (script(id, f)). A spy reads any topic from a bus of its own: comm::FakeBus spy(s.network()).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarm/comm/fake_bus.hpp"
#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/gcs/gcs_node.hpp"
#include "swarm/app/candidate_node.hpp"
#include "swarm/member/member_node.hpp"
#include "swarm/planner/grid/start_cells.hpp"
#include "swarm/sim/sim_node.hpp"
#include "swarm/tasks/registry.hpp"
#include "swarm_test/files.hpp"
#include "swarm_test/metrics_fixture.hpp"

namespace swarm::test {

// A RoleSetup on a map drawn in a test (no files): robots start around `start`.
inline app::RoleSetup setup_for(const planner::OccupancyGrid& truth, planner::Cell start,
                                 swarm::scenario::Scenario scenario) {
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

// A RoleSetup from scenario text (built-in maps are found through config::data_dir()).
inline app::RoleSetup setup_from_text(const std::string& scenario_text) {
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

template <class T>
struct Tag {
  using type = T;
};

class FakeSwarm {
 public:
  explicit FakeSwarm(app::RoleSetup setup, std::set<comm::AgentId> scripted = {})
      : setup_(std::move(setup)), scripted_(std::move(scripted)) {
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
      gcs_ = std::make_unique<gcs::GcsNode>(agent(t.gcs()), setup_, dir_.str(), gcs::Progress::Style::None,
                                            tasks::gcs_task);
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
          members_[id] = std::make_unique<member::MemberNode>(agent(id), setup_, g, i, *bodies_[id]);
        }
      }
    }
    alive_.assign(static_cast<std::size_t>(t.agents()), true);
  }

  const comm::Topology& topology() const { return setup_.topology; }
  const app::RoleSetup& setup() const { return setup_; }
  comm::FakeNetwork& network() { return net_; }
  comm::FakeBus& bus(comm::AgentId a) { return *buses_.at(a); }
  comm::LockstepAgent& agent(comm::AgentId a) { return *agents_.at(a); }
  // What a scripted agent does each tick (after its due messages' handlers ran).
  void script(comm::AgentId a, std::function<void(const msgs::Clock&)> f) { scripts_[a] = std::move(f); }
  sim::SimNode& sim() { return *sim_; }
  gcs::GcsNode& gcs() { return *gcs_; }
  // The leader side of group `group`'s first leader (index 0), and any robot's member side.
  leader::LeaderNode& leader(int group) { return candidates_.at(topology().leader(group))->leader(); }
  member::MemberNode& member(comm::AgentId robot) {
    const auto c = candidates_.find(robot);
    return c != candidates_.end() ? c->second->member() : *members_.at(robot);
  }
  app::CandidateNode& candidate(comm::AgentId robot) { return *candidates_.at(robot); }
  std::uint32_t tick() const { return tick_; }
  bool complete() const { return complete_; }
  bool stopped() const { return stopped_; }
  std::string run_dir() const { return dir_.str(); }

  // Gives a scripted agent every endpoint its role has that the test did not make itself, with
  // handlers that ignore what comes (readiness waits for both sides of every endpoint).
  void complete_endpoints(comm::AgentId a) {
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
      sub(Tag<msgs::GroupStatus>{}, topic::kGroupStatus, LinkClass::LeaderGcs, writers);
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
    sub(Tag<msgs::Assignment>{}, topic::assign(g), LinkClass::MemberLeader, candidates);
    sub(Tag<msgs::Route>{}, topic::route(g), LinkClass::MemberLeader, candidates);
    sub(Tag<msgs::RouteRelease>{}, topic::release(g), LinkClass::MemberLeader, candidates);
    pub(Tag<msgs::MapPatch>{}, topic::patch_up(g), LinkClass::MemberLeader, up);
    pub(Tag<msgs::MemberStatus>{}, topic::status(g), LinkClass::MemberLeader, up);
    pub(Tag<msgs::RouteProgress>{}, topic::progress(g), LinkClass::MemberLeader, up);
    if (t.is_candidate(a)) {
      const int robots = static_cast<int>(others.size());
      sub(Tag<msgs::MapPatch>{}, topic::patch_up(g), LinkClass::MemberLeader, robots);
      sub(Tag<msgs::MemberStatus>{}, topic::status(g), LinkClass::MemberLeader, robots);
      sub(Tag<msgs::RouteProgress>{}, topic::progress(g), LinkClass::MemberLeader, robots);
      sub(Tag<msgs::RoundStart>{}, topic::kRound, LinkClass::LeaderGcs, 1);
      sub(Tag<msgs::PhaseStart>{}, topic::kPhase, LinkClass::LeaderGcs, 1);
      sub(Tag<msgs::TaskOrder>{}, topic::kTaskOrder, LinkClass::LeaderGcs, 1);
      pub(Tag<msgs::MapPatch>{}, topic::kPatchGcs, LinkClass::LeaderGcs, {t.gcs()});
      pub(Tag<msgs::Heartbeat>{}, topic::kHeartbeat, LinkClass::LeaderGcs, {t.gcs()});
      pub(Tag<msgs::GroupStatus>{}, topic::kGroupStatus, LinkClass::LeaderGcs, {t.gcs()});
      pub(Tag<msgs::PlanReport>{}, topic::kPlanReport, LinkClass::Telemetry, {t.gcs()});
      pub(Tag<msgs::TaskReport>{}, topic::kTaskReport, LinkClass::LeaderGcs, {t.gcs()});
      pub(Tag<msgs::MapPatch>{}, topic::patch_down(g), LinkClass::MemberLeader, others);
      pub(Tag<msgs::Assignment>{}, topic::assign(g), LinkClass::MemberLeader, others);
      pub(Tag<msgs::Route>{}, topic::route(g), LinkClass::MemberLeader, others);
      pub(Tag<msgs::RouteRelease>{}, topic::release(g), LinkClass::MemberLeader, others);
    }
  }

  void start() {
    for (comm::AgentId a : scripted_) complete_endpoints(a);
    // On the fake, whatever is not matched at once never will be, and nothing waits for a slow
    // peer: a test with a missing endpoint fails in seconds, naming it, instead of after 60 s.
    ::setenv("SWARM_STALL_TIMEOUT", "2", 0);
    for (auto& a : agents_) {
      if (a) a->announce_ready();
    }
    clock_->wait_ready();
  }

  // One tick; false once the run has stopped (complete or max_ticks).
  bool step() {
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

  // Steps until `done` holds (checked after each tick) or the run stops; true if `done` held.
  bool run_until(const std::function<bool()>& done, int max_ticks) {
    for (int i = 0; i < max_ticks; ++i) {
      if (!step()) return done();
      if (done()) return true;
    }
    return false;
  }

  // The agent's process is gone: its bus leaves the network (its peers' readers see its writers
  // lost, as DDS reports a crashed participant) and it is no longer stepped.
  void disconnect(comm::AgentId a) {
    alive_.at(a) = false;
    net_.disconnect(*buses_.at(a));
  }

  // The whole run: start, step to the end (calling at(tick) after each tick, if given), finish;
  // returns metrics.json.
  nlohmann::json run_to_end(const std::function<void(std::uint32_t)>& at = {}) {
    start();
    while (step()) {
      if (at) at(tick());
    }
    finish();
    std::ifstream in(run_dir() + "/metrics.json");
    return nlohmann::json::parse(in);
  }

  // The end of a run: every living agent reports (the simulator unless told not to, and with
  // `sim_json` instead of its own numbers when given), the GCS writes metrics.json and run.pb.
  void finish(bool sim_reports = true, const std::optional<std::string>& sim_json = std::nullopt) {
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

 private:
  app::RoleSetup setup_;
  std::set<comm::AgentId> scripted_;
  std::map<comm::AgentId, std::function<void(const msgs::Clock&)>> scripts_;
  TempDir dir_;
  comm::FakeNetwork net_;
  std::vector<std::unique_ptr<comm::FakeBus>> buses_;
  std::unique_ptr<comm::LockstepClock> clock_;
  std::unique_ptr<sim::SimNode> sim_;
  std::vector<std::unique_ptr<comm::LockstepAgent>> agents_;
  std::unique_ptr<gcs::GcsNode> gcs_;
  std::map<comm::AgentId, std::unique_ptr<app::CandidateNode>> candidates_;
  std::map<comm::AgentId, std::unique_ptr<member::RobotAgent>> bodies_;
  std::map<comm::AgentId, std::unique_ptr<member::MemberNode>> members_;
  std::vector<bool> alive_;
  std::uint32_t tick_ = 0;
  bool complete_ = false;
  bool stopped_ = false;
};

}  // namespace swarm::test
