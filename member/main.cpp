// swarm-member: one group member robot. See member_node.hpp.
#include <iostream>

#include "swarm/comm/fault_injection.hpp"
#include "swarm/comm/lockstep.hpp"
#include "swarm/comm/role.hpp"
#include "swarm/member/member_node.hpp"

int main(int argc, char** argv) {
  using namespace swarm;
  comm::RoleOptions options;
  CLI::App app{"swarm-member: one group member robot of a swarm run"};
  comm::add_role_flags(app, options, comm::RoleKind::Member);
  return comm::run_role(app, argc, argv, "member", [&]() -> int {
    const comm::RoleSetup setup = comm::load_role(options, comm::RoleKind::Member, "member");
    comm::Participant participant(setup.dds);
    const comm::AgentId self = setup.topology.robot(options.group, options.index);
    comm::LockstepAgent agent(participant, setup.topology, setup.links, self);
    member::MemberNode node(agent, setup, options.group, options.index);
    comm::FaultInjector faults(setup.world.scenario, setup.topology.name_of(self));
    comm::run_lockstep(agent, [&](const msgs::Clock& clock) {
      faults.at_tick(clock.tick());
      node.step(clock);
      return false;
    });
    agent.send_report("member", node.report_json());
    comm::exit_after_work(setup.topology.name_of(self));
  });
}
