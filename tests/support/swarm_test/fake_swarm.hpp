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
app::RoleSetup setup_for(const planner::OccupancyGrid& truth, planner::Cell start, swarm::scenario::Scenario scenario);

// A RoleSetup from scenario text (built-in maps are found through config::data_dir()).
app::RoleSetup setup_from_text(const std::string& scenario_text);

class FakeSwarm {
 public:
  // `gcs_tasks`: the GCS's task for each phase (the registry's, unless a test drives its own).
  explicit FakeSwarm(app::RoleSetup setup, std::set<comm::AgentId> scripted = {},
                     gcs::GcsTaskFactory gcs_tasks = tasks::gcs_task);

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
  void complete_endpoints(comm::AgentId a);

  void start();

  // One tick; false once the run has stopped (complete or max_ticks).
  bool step();

  // Steps until `done` holds (checked after each tick) or the run stops; true if `done` held.
  bool run_until(const std::function<bool()>& done, int max_ticks);

  // The agent's process is gone: its bus leaves the network (its peers' readers see its writers
  // lost, as DDS reports a crashed participant) and it is no longer stepped.
  void disconnect(comm::AgentId a);

  // The whole run: start, step to the end (calling at(tick) after each tick, if given), finish;
  // returns metrics.json.
  nlohmann::json run_to_end(const std::function<void(std::uint32_t)>& at = {});

  // The end of a run: every living agent reports (the simulator unless told not to, and with
  // `sim_json` instead of its own numbers when given), the GCS writes metrics.json and run.pb.
  void finish(bool sim_reports = true, const std::optional<std::string>& sim_json = std::nullopt);

 private:
  app::RoleSetup setup_;
  std::set<comm::AgentId> scripted_;
  gcs::GcsTaskFactory gcs_tasks_;
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

// A scenario given as protobuf text run on the FakeBus to its end: what metrics.json would hold.
nlohmann::json run_text(const std::string& scenario_text);

}  // namespace swarm::test
