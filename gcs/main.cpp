// swarm-gcs: the ground control station of a swarm run. See gcs_node.hpp.
#include "swarm/app/fault_injection.hpp"
#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/gcs/gcs_node.hpp"
#include "swarm/tasks/registry.hpp"

int main(int argc, char** argv) {
  using namespace swarm;
  app::RoleOptions options;
  CLI::App app{"swarm-gcs: ground control station (map fusion, planning rounds, metrics)"};
  app::add_role_flags(app, options, app::RoleKind::Gcs);
  return app::run_role(app, argc, argv, "gcs", [&]() -> int {
    const app::RoleSetup setup = tasks::load_role(options, app::RoleKind::Gcs);
    comm::Participant participant(setup.dds);
    comm::LockstepAgent agent(participant, setup.topology, setup.links, setup.topology.gcs());
    gcs::GcsNode node(agent, setup, options.run_dir, gcs::Progress::parse(options.progress), tasks::gcs_task);
    const std::string journal = gcs::journal_path(options.run_dir);
    if (options.resume) {
      // A restart (gcs_node.hpp "Restart"): the old process's inputs again, then back into the run.
      node.resumed(agent.replay_journal(journal, [&](const msgs::Clock& clock) { node.step(clock); }));
      agent.rejoin();
    } else {
      agent.journal_to(journal);
    }
    // The scheduled kill is the first process's; a restarted one runs to the end.
    std::optional<app::FaultInjector> faults;
    if (!options.resume) faults.emplace(setup.world.scenario, "gcs");
    comm::run_lockstep(agent, [&](const msgs::Clock& clock) {
      if (faults) faults->at_tick(clock.tick());
      return node.step(clock);
    });
    node.finish();
    app::exit_after_work("gcs");
  });
}
