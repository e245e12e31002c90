#include "swarm/leader/group_task.hpp"

#include "swarm/config/scenario.hpp"
#include "swarm/config/task_config.hpp"
#include "swarm/leader/cover_task.hpp"
#include "swarm/leader/collect_task.hpp"
#include "swarm/leader/explore_task.hpp"
#include "swarm/leader/mapf_task.hpp"

namespace swarm::leader {

std::unique_ptr<GroupTask> make_group_task(const swarm::scenario::Phase& phase, const app::RoleSetup& setup,
                                           int group, std::uint32_t index) {
  const auto& s = setup.world.scenario;
  switch (config::task_of(phase)) {
    case config::TaskKind::Explore:
      return std::make_unique<ExploreGroupTask>(phase.explore(), s.seed(), setup.topology.robots_per_group());
    case config::TaskKind::Cover:
      return std::make_unique<CoverGroupTask>(phase.cover(), setup, group);
    case config::TaskKind::Mapf:
      return std::make_unique<MapfGroupTask>(config::resolved_mapf(phase.mapf(), s), group);
    case config::TaskKind::Collect:
      return std::make_unique<CollectGroupTask>(phase.collect(), setup, group, index);
    default:
      break;
  }
  throw config::ConfigError("task '" + config::task_name(config::task_of(phase)) +
                            "' has no leader side in this build");
}

}  // namespace swarm::leader
