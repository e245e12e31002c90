// swarm-gcs: the ground control station of a swarm run. See gcs_node.hpp.
#include "swarm/comm/lockstep.hpp"
#include "swarm/comm/role.hpp"
#include "swarm/gcs/gcs_node.hpp"

int main(int argc, char** argv) {
  using namespace swarm;
  comm::RoleOptions options;
  CLI::App app{"swarm-gcs: ground control station (map fusion, planning rounds, metrics)"};
  comm::add_role_flags(app, options, comm::RoleKind::Gcs);
  return comm::run_role(app, argc, argv, "gcs", [&]() -> int {
    const comm::RoleSetup setup = comm::load_role(options, comm::RoleKind::Gcs, "gcs");
    comm::Participant participant(setup.dds);
    comm::LockstepAgent agent(participant, setup.topology, setup.links, setup.topology.gcs());
    gcs::GcsNode node(agent, setup, options.run_dir, gcs::Progress::parse(options.progress));
    comm::run_lockstep(agent, [&](const msgs::Clock& clock) { return node.step(clock); });
    node.finish();
    comm::exit_after_work("gcs");
  });
}
