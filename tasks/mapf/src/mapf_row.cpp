#include "swarm/tasks/mapf/mapf_row.hpp"

#include "swarm/config/numbers.hpp"
#include "swarm/config/task_config.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"
#include "swarm/tasks/mapf/mapf_gcs.hpp"
#include "swarm/tasks/mapf/mapf_goals.hpp"
#include "swarm/tasks/mapf/mapf_leader.hpp"

namespace swarm::tasks {

namespace {
// The simulator's judge. Executed makespan: ticks from the phase's start to the last move any
// robot made (orders and routes take a few ticks to arrive), and from the first move to the last
// (the plan's own measure, comparable with the planned makespan); conflicts as the world saw them;
// and, from the robots' true cells, how many living robots stand on their goals (the GCS judges
// arrival from the leaders' reports; the two must agree). Only goals fixed at load (the scenario's
// points or scen) are known here: random goals are drawn by the GCS from its known map when the
// phase starts, and their counts are then null.
class MapfJudge : public sim::PhaseJudge {
 public:
  explicit MapfJudge(std::vector<planner::Cell> goals) : goals_(std::move(goals)) {}
  // Robots on their goals, out of every robot with one (unknown for goals drawn by the GCS).
  sim::Progress progress(const sim::World& world) const override {
    sim::Progress p;
    for (std::size_t r = 0; r < world.robots().size() && r < goals_.size(); ++r) {
      ++p.total;
      p.done += world.robots()[r] == goals_[r] ? 1 : 0;
    }
    return p;
  }

  nlohmann::json judge(const sim::World& world, const sim::PhaseFacts& f) const override {
    const bool moved = f.last_move_tick.has_value();
    int living = 0, at_goal = 0;
    for (std::size_t r = 0; r < world.robots().size() && r < goals_.size(); ++r) {
      if (r < f.alive.size() && !f.alive[r]) continue;
      ++living;
      at_goal += world.robots()[r] == goals_[r] ? 1 : 0;
    }
    const bool known = !goals_.empty();
    return {{record::kGroundTruthDone, known ? nlohmann::json(at_goal == living) : nlohmann::json(nullptr)},
            {"makespan_ticks", moved ? *f.last_move_tick - f.start_tick : 0},
            {"driven_makespan_ticks", moved ? *f.last_move_tick - *f.first_move_tick + 1 : 0},
            {"conflicts", f.motion.vertex_conflict_events + f.motion.edge_conflict_events},
            {"blocked_moves", f.motion.total.blocked_moves},
            {"ground_truth_at_goal", known ? nlohmann::json(at_goal) : nlohmann::json(nullptr)},
            {"ground_truth_living", known ? nlohmann::json(living) : nlohmann::json(nullptr)}};
  }

 private:
  std::vector<planner::Cell> goals_;  // per robot id (the row's `resolve`)
};
}  // namespace

void check_mapf_paths(const swarm::scenario::Mapf& m, const swarm::scenario::Scenario& scenario, const std::string& field,
                      config::Problems& p) {
  p.number(field + ".w", m.w(), config::NumberRule{1.0});
  p.time_limit(field + ".time_limit_s", m.time_limit_s());
  if (m.execution() == swarm::scenario::MAPF_EXECUTE_TIMED && !config::delivery_ticks_bounded(scenario)) {
    // A lost and re-sent (or queued) route would set off after its start tick, behind the
    // others: robots meet and stay stuck (measured: 586 conflict events, 4 of 6 robots stuck).
    p.add(field + ".execution",
          "be MAPF_EXECUTE_ADG or MAPF_EXECUTE_AUTO when a link loses messages, has a bandwidth cap or the run "
          "is in real time (a plan driven by its timing needs every route on time)",
          "MAPF_EXECUTE_TIMED");
  }
}

TaskRow mapf_row() {
  TaskRow row;
  row.name = "mapf";
  row.phase_case = Phase::kMapf;
  row.motion = planner::MotionModel::four();  // the MAPF paper's 4-connected grid
  row.gcs = [](const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
    return std::make_unique<gcs::MapfGcsTask>(tasks::resolved_mapf(phase.mapf(), setup.world.scenario), index,
                                              config::map_given(setup.world.scenario, index));
  };
  row.leader = [](const Phase& phase, const app::RoleSetup& setup, int group, std::uint32_t) {
    return std::make_unique<leader::MapfGroupTask>(tasks::resolved_mapf(phase.mapf(), setup.world.scenario), group);
  };
  row.judge = [](const Phase&, const app::RoleSetup& setup, std::uint32_t index) {
    return std::make_unique<MapfJudge>(std::any_cast<const std::vector<planner::Cell>&>(setup.world.phase_data.at(index)));
  };
  row.resolve = [](const Phase& phase, const config::World& world, const std::string& field) -> std::any {
    return mapf_goals(phase.mapf(), world.truth, static_cast<int>(world.robot_cells.size()), field);
  };
  row.check = [](const Phase& phase, const config::World& world, const std::string& field, config::Problems& p) {
    const auto& m = phase.mapf();
    check_mapf_paths(m, world.scenario, field, p);
    if (m.goals_size() > 0 && m.has_scen()) p.add(field, "give goals or scen, not both", "both");
    const std::uint64_t robots = std::uint64_t{world.scenario.groups()} * world.scenario.robots_per_group();
    if (m.goals_size() > 0 && static_cast<std::uint64_t>(m.goals_size()) != robots) {
      p.add(field + ".goals", "give one goal per robot (" + std::to_string(robots) + ")", std::to_string(m.goals_size()));
    }
  };
  return row;
}

}  // namespace swarm::tasks
