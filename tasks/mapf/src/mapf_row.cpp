#include "swarm/tasks/mapf/mapf_row.hpp"

#include "swarm/config/task_config.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"
#include "swarm/tasks/mapf/mapf_leader.hpp"

namespace swarm::tasks {

namespace {
// The simulator's judge. Executed makespan: ticks from the phase's start to the last move any
// robot made (orders and routes take a few ticks to arrive), and from the first move to the last
// (the plan's own measure, comparable with the planned makespan); conflicts as the world saw them.
class MapfJudge : public sim::PhaseJudge {
 public:
  nlohmann::json judge(const sim::World&, const sim::PhaseFacts& f) const override {
    const bool moved = f.last_move_tick.has_value();
    return {{"makespan_ticks", moved ? *f.last_move_tick - f.start_tick : 0},
            {"driven_makespan_ticks", moved ? *f.last_move_tick - *f.first_move_tick + 1 : 0},
            {"conflicts", f.motion.vertex_conflict_events + f.motion.edge_conflict_events},
            {"blocked_moves", f.motion.total.blocked_moves}};
  }
};
}  // namespace

TaskRow mapf_row() {
  TaskRow row;
  row.name = "mapf";
  row.phase_case = Phase::kMapf;
  row.motion = planner::MotionModel::four();  // the MAPF paper's 4-connected grid
  row.gcs = [](const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
    return std::make_unique<gcs::MapfGcsTask>(config::resolved_mapf(phase.mapf(), setup.world.scenario), index,
                                              config::map_given(setup.world.scenario, index));
  };
  row.leader = [](const Phase& phase, const app::RoleSetup& setup, int group, std::uint32_t) {
    return std::make_unique<leader::MapfGroupTask>(config::resolved_mapf(phase.mapf(), setup.world.scenario), group);
  };
  row.judge = [](const Phase&, const app::RoleSetup&, std::uint32_t) { return std::make_unique<MapfJudge>(); };
  return row;
}

}  // namespace swarm::tasks
