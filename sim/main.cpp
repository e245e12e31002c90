// swarm-sim: the simulator and clock master of a swarm run. See sim_node.hpp.
#include <chrono>
#include <cstdio>

#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/app/stop_signal.hpp"
#include "swarm/sim/sim_node.hpp"
#include "swarm/tasks/registry.hpp"

int main(int argc, char** argv) {
  using namespace swarm;
  app::RoleOptions options;
  CLI::App app{"swarm-sim: the simulator (ground truth, motion, LiDAR) and clock of a swarm run"};
  app::add_role_flags(app, options, app::RoleKind::Sim);
  return app::run_role(app, argc, argv, "sim", [&]() -> int {
    app::StopOnSignal stop;  // before DDS starts its threads
    const app::RoleSetup setup = tasks::load_role(options, app::RoleKind::Sim);
    comm::Participant participant(setup.dds);
    comm::LockstepClock clock(participant, setup.topology, setup.links);
    const auto calling = stop.start([&clock] { clock.request_stop(); });  // goes before `clock`
    sim::SimNode node(clock, setup, tasks::sim_part);
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint32_t last = node.run();
    const auto t1 = std::chrono::steady_clock::now();
    clock.send_report("sim", node.report_json());
    for (const auto& l : clock.losses()) {
      std::printf("sim: %s stopped answering at tick %u; DDS declared it lost after %.2f s",
                  setup.topology.name_of(l.agent).c_str(), l.tick, l.detection_seconds);
      if (l.rejoined_tick) std::printf("; it came back at tick %u", *l.rejoined_tick);
      std::printf("\n");
    }
    std::printf("sim: %u ticks; discovery + run %.2f s, report %.2f s\n", last + 1,
                std::chrono::duration<double>(t1 - t0).count(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count());
    app::exit_after_work("sim");
  });
}
