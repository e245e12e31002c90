// swarm-member: group member robots, one by default. See member_node.hpp.
//
// `--index 1,2,3` runs several robots of one group in this process (swarm run
// --agents-per-process): each is its own LockstepAgent with its own DDS writers and readers on the
// process's one participant, stepping on its own thread, so the robots still talk only through
// DDS and the run is the same, tick for tick; only the process count (and simple discovery's
// participant count) falls. A kill or freeze fault acts on a whole process, so a robot named by
// one must run alone.
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "swarm/app/fault_injection.hpp"
#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/app/candidate_node.hpp"
#include "swarm/tasks/registry.hpp"
#include "swarm/member/member_node.hpp"

namespace {

using namespace swarm;

// One robot's whole life on the shared participant: lockstep until the run stops, then its report.
// Its agent goes into `keep`, which outlives the run: the process ends with exit_after_work and
// never tears Fast DDS down (destroying a writer with a long unacknowledged history took minutes
// at the end of a 3000-tick run).
void run_member(comm::Participant& participant, const app::RoleSetup& setup, int group, int index,
                app::FaultInjector& faults, std::unique_ptr<comm::LockstepAgent>& keep) {
  const comm::AgentId self = setup.topology.robot(group, index);
  keep = std::make_unique<comm::LockstepAgent>(participant, setup.topology, setup.links, self);
  comm::LockstepAgent& agent = *keep;
  const auto run = [&](auto& node) {
    comm::run_lockstep(agent, [&](const msgs::Clock& clock) {
      faults.at_tick(clock.tick());
      node.step(clock);
      return false;
    });
    agent.send_report("member", node.report_json());
  };
  // A standby leader (comm/leadership.hpp) is a candidate: member until the clock names it leader.
  if (setup.topology.is_candidate(self)) {
    app::CandidateNode node(agent, setup, group, index, tasks::group_task);
    run(node);
  } else {
    member::RobotAgent robot(setup.world.frame.width, setup.world.frame.height, setup.world.frame.resolution);
    member::MemberNode node(agent, setup, group, robot);
    run(node);
  }
}

}  // namespace

int main(int argc, char** argv) {
  app::RoleOptions options;
  CLI::App app{"swarm-member: group member robots of a swarm run (one per --index)"};
  app::add_role_flags(app, options, app::RoleKind::Member);
  return app::run_role(app, argc, argv, "member", [&]() -> int {
    const app::RoleSetup setup = tasks::load_role(options, app::RoleKind::Member);
    std::vector<std::unique_ptr<app::FaultInjector>> faults;
    std::string names;
    for (const int index : options.indices) {
      const std::string name = setup.topology.name_of(setup.topology.robot(options.group, index));
      faults.push_back(std::make_unique<app::FaultInjector>(setup.world.scenario, name));
      if (faults.back()->any() && options.indices.size() > 1) {
        throw config::ConfigError("a kill or freeze fault of " + name +
                                  " stops its whole process: run it alone (--agents-per-process 1)");
      }
      names += (names.empty() ? "" : ",") + name;
    }
    comm::Participant participant(setup.dds);
    std::vector<std::unique_ptr<comm::LockstepAgent>> agents(options.indices.size());
    if (options.indices.size() == 1) {
      run_member(participant, setup, options.group, options.indices[0], *faults[0], agents[0]);
      app::exit_after_work(names);
    }
    // A robot that fails ends the process at once with the role's exit code for a runtime
    // failure (its peers cannot finish the run without it anyway).
    std::vector<std::thread> robots;
    for (std::size_t i = 0; i < options.indices.size(); ++i) {
      robots.emplace_back([&, i] {
        try {
          run_member(participant, setup, options.group, options.indices[i], *faults[i], agents[i]);
        } catch (const std::exception& e) {
          std::cerr << "swarm-member: " << setup.topology.name_of(setup.topology.robot(options.group, options.indices[i]))
                    << ": " << e.what() << std::endl;
          std::fflush(nullptr);
          std::_Exit(1);
        }
      });
    }
    for (std::thread& t : robots) t.join();
    app::exit_after_work(names);
  });
}
