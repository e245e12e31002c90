#include "swarm/tasks/cover/cover_row.hpp"

#include <utility>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/tasks/cover/cover_gcs.hpp"
#include "swarm/tasks/cover/cover_leader.hpp"
#include "swarm/tasks/mapf/mapf_leader.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"

namespace swarm::tasks {

namespace {
// The simulator's judge: the share of the coverage target the robots' footprints swept, when it
// was all swept, and the curve of it (every 5 ticks).
class CoverJudge : public sim::PhaseJudge {
 public:
  void start(sim::World& world, std::uint32_t tick) override {
    world.reset_coverage();
    curve_.emplace_back(tick, world.covered_fraction());
  }
  void after_tick(const sim::World& world, std::uint32_t k) override {
    if (!full_tick_ && world.covered_cells() >= world.coverage_target_cells()) full_tick_ = k;
    if (k % 5 == 0) curve_.emplace_back(k, world.covered_fraction());
  }
  void last_tick(const sim::World& world, std::uint32_t k) override { curve_.emplace_back(k, world.covered_fraction()); }
  nlohmann::json judge(const sim::World& world, const sim::PhaseFacts& facts) const override {
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& [tick, f] : curve_) curve.push_back({tick, f});
    return {{record::kGroundTruthDone, world.covered_cells() >= world.coverage_target_cells()},
            {"covered_fraction", world.covered_fraction()},
            {"covered_cells", world.covered_cells()},
            {"target_cells", world.coverage_target_cells()},
            {"makespan_ticks", full_tick_ ? nlohmann::json(*full_tick_ - facts.start_tick) : nlohmann::json(nullptr)},
            {"coverage_curve", curve}};
  }

 private:
  std::vector<std::pair<std::uint32_t, double>> curve_;  // (tick, covered fraction)
  std::optional<std::uint32_t> full_tick_;                // every target cell covered
};
}  // namespace

TaskRow cover_row() {
  TaskRow row;
  row.name = "cover";
  row.phase_case = Phase::kCover;
  row.motion = planner::MotionModel::four();  // DARP and STC plan on the 4-connected grid
  row.gcs = [](const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
    return std::make_unique<gcs::CoverGcsTask>(phase.cover(), traffic_driving(), index,
                                               config::map_given(setup.world.scenario, index));
  };
  row.leader = [](const Phase& phase, const app::RoleSetup& setup, int group,
                  std::uint32_t) -> std::unique_ptr<leader::GroupTask> {
    // Through the traffic layer the leaders drive windows as they drive mapf plans.
    if (phase.cover().traffic()) return std::make_unique<leader::MapfGroupTask>(traffic_driving(), group);
    return std::make_unique<leader::CoverGroupTask>(phase.cover(), setup, group);
  };
  row.judge = [](const Phase&, const app::RoleSetup&, std::uint32_t) { return std::make_unique<CoverJudge>(); };
  row.check = [](const Phase& phase, const config::World&, const std::string& field, config::Problems& p) {
    p.at_least(field + ".darp_max_iterations", 1, phase.cover().darp_max_iterations());
    p.time_limit(field + ".darp_time_limit_s", phase.cover().darp_time_limit_s());
    p.at_least(field + ".stall_ticks", 1, phase.cover().stall_ticks());
    p.at_least(field + ".traffic_window_steps", 1, phase.cover().traffic_window_steps());
  };
  return row;
}

}  // namespace swarm::tasks
