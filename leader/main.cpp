// swarm-leader: a group's first leader robot and its group's planner. See candidate_node.hpp.
#include "swarm/comm/fault_injection.hpp"
#include "swarm/comm/lockstep.hpp"
#include "swarm/comm/role.hpp"
#include "swarm/leader/candidate_node.hpp"

int main(int argc, char** argv) {
  using namespace swarm;
  comm::RoleOptions options;
  CLI::App app{"swarm-leader: a group leader (a robot plus its group's exploration planner)"};
  comm::add_role_flags(app, options, comm::RoleKind::Leader);
  return comm::run_role(app, argc, argv, "leader", [&]() -> int {
    const comm::RoleSetup setup = comm::load_role(options, comm::RoleKind::Leader);
    comm::Participant participant(setup.dds);
    comm::LockstepAgent agent(participant, setup.topology, setup.links, setup.topology.leader(options.group));
    leader::CandidateNode node(agent, setup, options.group, 0);
    comm::FaultInjector faults(setup.world.scenario, setup.topology.name_of(agent.self()));
    comm::run_lockstep(agent, [&](const msgs::Clock& clock) {
      faults.at_tick(clock.tick());
      node.step(clock);
      return false;
    });
    agent.send_report("leader", node.report_json());
    comm::exit_after_work(setup.topology.name_of(agent.self()));
  });
}
