#include "swarm/tasks/rendezvous/rendezvous_row.hpp"

#include <algorithm>

#include "swarm/config/task_config.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"
#include "swarm/tasks/mapf/mapf_leader.hpp"
#include "swarm/tasks/mapf/mapf_row.hpp"
#include "swarm/tasks/rendezvous/gather.hpp"
#include "swarm/tasks/rendezvous/rendezvous_gcs.hpp"

namespace swarm::tasks {

using planner::Cell;

namespace {

// The simulator's judge, from ground truth: the gathering the living robots should stand in on the
// true map (gather.hpp, the lost robots standing where they stopped) against where they stand,
// in 8-connected steps from its centre; robots on its cells; makespan and conflicts as for mapf.
class RendezvousJudge : public sim::PhaseJudge {
 public:
  explicit RendezvousJudge(Cell target) : target_(target) {}
  nlohmann::json judge(const sim::World& world, const sim::PhaseFacts& f) const override {
    planner::OccupancyGrid truth = world.truth();
    std::vector<Cell> living;
    std::vector<int> lost;
    for (std::size_t r = 0; r < world.robots().size(); ++r) {
      if (r < f.alive.size() && !f.alive[r]) {
        truth.set(world.robots()[r], planner::CellState::Occupied);
        lost.push_back(static_cast<int>(r));
      } else {
        living.push_back(world.robots()[r]);
      }
    }
    const rendezvous::Gathering ideal = rendezvous::gather(truth, target_, living);
    const rendezvous::Packing got = rendezvous::packing(truth, ideal.centre, living);
    const rendezvous::Packing best = rendezvous::packing(truth, ideal.centre, ideal.cells);
    int on_cells = 0;
    for (const Cell c : living) on_cells += std::count(ideal.cells.begin(), ideal.cells.end(), c) > 0 ? 1 : 0;
    const int cannot_reach = static_cast<int>(living.size() - ideal.cells.size());
    const bool moved = f.last_move_tick.has_value();
    const bool packed = got.unreachable == cannot_reach && got.step_sum == best.step_sum;
    return {{record::kGroundTruthDone, packed},
            {"centre", {ideal.centre.x, ideal.centre.y}},
            {"robots_alive", living.size()},
            {"robots_lost", lost},
            {"robots_cannot_reach", cannot_reach},
            {"on_gathering_cells", on_cells},
            // Every robot that can reach the centre stands on one of the nearest cells there are.
            {"packed", packed},
            {"step_sum", got.step_sum},
            {"ideal_step_sum", best.step_sum},
            {"max_steps", got.max_steps},
            {"ideal_max_steps", best.max_steps},
            {"makespan_ticks", moved ? *f.last_move_tick - f.start_tick : 0},
            {"conflicts", f.motion.vertex_conflict_events + f.motion.edge_conflict_events},
            {"blocked_moves", f.motion.total.blocked_moves}};
  }

 private:
  Cell target_;
};

}  // namespace

namespace {
// The mapf settings a rendezvous drives its robots by, as the scenario gives them.
swarm::scenario::Mapf paths_as_given(const swarm::scenario::Rendezvous& r) {
  swarm::scenario::Mapf m;
  m.set_solver(r.solver());
  m.set_w(r.w());
  m.set_time_limit_s(r.time_limit_s());
  m.set_execution(r.execution());
  return m;
}
}  // namespace

swarm::scenario::Mapf rendezvous_paths(const swarm::scenario::Rendezvous& r, const swarm::scenario::Scenario& s) {
  return tasks::resolved_mapf(paths_as_given(r), s);
}

TaskRow rendezvous_row() {
  TaskRow row;
  row.name = "rendezvous";
  row.phase_case = Phase::kRendezvous;
  row.motion = planner::MotionModel::four();  // driven by the MAPF planner's 4-connected plans
  row.gcs = [](const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
    return std::make_unique<gcs::RendezvousGcsTask>(phase.rendezvous(),
                                                    rendezvous_paths(phase.rendezvous(), setup.world.scenario), index,
                                                    config::map_given(setup.world.scenario, index));
  };
  row.leader = [](const Phase& phase, const app::RoleSetup& setup, int group, std::uint32_t) {
    return std::make_unique<leader::MapfGroupTask>(rendezvous_paths(phase.rendezvous(), setup.world.scenario), group);
  };
  row.judge = [](const Phase& phase, const app::RoleSetup& setup, std::uint32_t) {
    return std::make_unique<RendezvousJudge>(gcs::rendezvous_target(phase.rendezvous(), setup.world.start, setup.world.truth));
  };
  row.check = [](const Phase& phase, const config::World& world, const std::string& field, config::Problems& p) {
    const auto& r = phase.rendezvous();
    check_mapf_paths(paths_as_given(r), world.scenario, field, p);
    if (r.has_point() && r.home()) p.add(field, "give point or home: true, not both", "both");
    if (!r.has_point()) return;
    const auto& at = r.point();
    if (!at.has_x() || !at.has_y()) {
      p.add(field + ".point", "give both x and y in metres", at.has_x() ? "only x" : at.has_y() ? "only y" : "neither");
    } else if (!world.frame.contains(at.x(), at.y())) {
      p.add(field + ".point", "lie inside the map, which spans " + world.frame.extent_text(),
            "(" + config::num(at.x()) + ", " + config::num(at.y()) + ")");
    }
  };
  return row;
}

}  // namespace swarm::tasks
