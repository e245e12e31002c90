#include "swarm/tasks/explore/explore_row.hpp"

#include <cmath>

#include "swarm/tasks/explore/explore_gcs.hpp"
#include "swarm/tasks/explore/explore_leader.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"

namespace swarm::tasks {

namespace {
// The simulator's judge: how much of the map the robots' scans covered, and when 99 % was.
class ExploreJudge : public sim::PhaseJudge {
 public:
  sim::Progress progress(const sim::World& world) const override {
    const auto reachable = static_cast<std::uint64_t>(world.reachable_free_cells());
    return {static_cast<std::uint64_t>(std::llround(world.explored_fraction() * static_cast<double>(reachable))), reachable};
  }
  nlohmann::json judge(const sim::World& world, const sim::PhaseFacts& facts) const override {
    // The paper's measure of an explored map: 99 % of the free cells the robots can reach, seen.
    return {{record::kGroundTruthDone, world.explored_fraction() >= 0.99},
            {"explored_fraction", world.explored_fraction()},
            {"steps_to_99", facts.steps_to_99 ? nlohmann::json(*facts.steps_to_99) : nlohmann::json(nullptr)}};
  }
};
}  // namespace

TaskRow explore_row() {
  TaskRow row;
  row.name = "explore";
  row.phase_case = Phase::kExplore;
  row.motion = planner::MotionModel::eight();  // the paper's 8-connected robots
  row.gcs = [](const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
    const swarm::scenario::Explore& e = phase.explore();
    PlanningRoundsConfig c;
    c.groups = setup.topology.groups();
    c.start_cells = setup.world.robot_cells;
    c.replan_threshold = e.replan_threshold_steps();
    // Ideal mode is the paper's "no delay" comparison: the map fused now is used now.
    c.map_delay_rounds = e.mode() == swarm::scenario::IDEAL ? 0 : e.global_map_delay_rounds();
    return std::make_unique<gcs::ExploreGcsTask>(
        index, std::move(c), gcs::ExploreGcsTask::Drive{traffic_driving(), static_cast<int>(e.traffic_window_steps())});
  };
  row.leader = [](const Phase& phase, const app::RoleSetup& setup, int group, std::uint32_t) {
    const swarm::scenario::Explore& e = phase.explore();
    return std::make_unique<leader::ExploreGroupTask>(e, setup.world.scenario.seed(), group, traffic_driving());
  };
  row.check = [](const Phase& phase, const config::World&, const std::string& field, config::Problems& p) {
    p.at_least(field + ".traffic_window_steps", 1, phase.explore().traffic_window_steps());
    if (!phase.explore().traffic()) p.add(field + ".traffic", kOnlyTheLayer, "false");
  };
  row.judge = [](const Phase&, const app::RoleSetup&, std::uint32_t) { return std::make_unique<ExploreJudge>(); };
  return row;
}

}  // namespace swarm::tasks
