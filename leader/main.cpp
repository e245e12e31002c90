// swarm-leader: a group's first leader robot and its group's planner. See candidate_node.hpp.
#include "swarm/app/fault_injection.hpp"
#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/app/candidate_node.hpp"
#include "swarm/tasks/registry.hpp"

int main(int argc, char** argv) {
  using namespace swarm;
  app::RoleOptions options;
  CLI::App app{"swarm-leader: a group leader (a robot plus its group's exploration planner)"};
  app::add_role_flags(app, options, app::RoleKind::Leader);
  return app::run_role(app, argc, argv, "leader", [&]() -> int {
    const app::RoleSetup setup = tasks::load_role(options, app::RoleKind::Leader);
    comm::Participant participant(setup.dds);
    comm::LockstepAgent agent(participant, setup.topology, setup.links, setup.topology.leader(options.group));
    app::CandidateNode node(agent, setup, options.group, 0, tasks::group_task);
    app::FaultInjector faults(setup.world.scenario, setup.topology.name_of(agent.self()));
    comm::run_lockstep(agent, [&](const msgs::Clock& clock) {
      faults.at_tick(clock.tick());
      node.step(clock);
      return false;
    });
    agent.send_report("leader", node.report_json());
    app::exit_after_work(setup.topology.name_of(agent.self()));
  });
}
