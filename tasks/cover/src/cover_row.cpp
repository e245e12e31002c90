#include "swarm/tasks/cover/cover_row.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/planner/coverage/cover_bounds.hpp"
#include "swarm/tasks/cover/cover_gcs.hpp"
#include "swarm/tasks/mapf/mapf_leader.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"

namespace swarm::tasks {

namespace {
// The simulator's judge: the share of the coverage target the robots' footprints swept, when it
// was all swept, and the curve of it (every 5 ticks). Also two lower bounds on the makespan
// besides ⌈cells / robots⌉ (planner/coverage/cover_bounds.hpp), from the ground truth at the
// phase's start: the moves to the target cell farthest from every robot, and the moves each that
// give the team a landing on every target cell of both chessboard colours (where robots cover
// only the cell they stand on; a wider footprint reaches a cell from elsewhere, and the bounds are
// then not given).
class CoverJudge : public sim::PhaseJudge {
 public:
  sim::Progress progress(const sim::World& world) const override {
    return {static_cast<std::uint64_t>(world.covered_cells()), static_cast<std::uint64_t>(world.coverage_target_cells())};
  }
  void start(sim::World& world, std::uint32_t tick) override {
    world.reset_coverage();
    curve_.emplace_back(tick, world.covered_fraction());
    bounds_.reset();
    if (world.footprint_radius() == 0) bounds_ = planner::cover_bounds(world.truth(), world.uncovered(), world.robots());
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
            // The orders' way to the robots: ticks from the phase's start to the first move.
            {"first_move_ticks", facts.first_move_tick ? nlohmann::json(*facts.first_move_tick - facts.start_tick)
                                                       : nlohmann::json(nullptr)},
            {"reach_bound_moves", bounds_ ? nlohmann::json(bounds_->reach_moves) : nlohmann::json(nullptr)},
            {"colour_bound_moves", bounds_ ? nlohmann::json(bounds_->colour_moves) : nlohmann::json(nullptr)},
            {"coverage_curve", curve}};
  }

 private:
  std::vector<std::pair<std::uint32_t, double>> curve_;  // (tick, covered fraction)
  std::optional<std::uint32_t> full_tick_;                // every target cell covered
  std::optional<planner::CoverBounds> bounds_;
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
  row.leader = [](const Phase&, const app::RoleSetup&, int group, std::uint32_t) -> std::unique_ptr<leader::GroupTask> {
    // The leaders drive the traffic layer's windows as they drive mapf plans.
    return std::make_unique<leader::MapfGroupTask>(traffic_driving(), group);
  };
  row.judge = [](const Phase&, const app::RoleSetup&, std::uint32_t) { return std::make_unique<CoverJudge>(); };
  row.check = [](const Phase& phase, const config::World&, const std::string& field, config::Problems& p) {
    p.at_least(field + ".darp_max_iterations", 1, phase.cover().darp_max_iterations());
    p.time_limit(field + ".darp_time_limit_s", phase.cover().darp_time_limit_s());
    p.at_least(field + ".traffic_window_steps", 1, phase.cover().traffic_window_steps());
    p.in_range(field + ".route_candidates", 1, 16, phase.cover().route_candidates());
    p.in_range(field + ".route_balance_rounds", 0, 256, phase.cover().route_balance_rounds());
    p.in_range(field + ".tour_seeds", 1, 16, phase.cover().tour_seeds());
    if (!phase.cover().traffic()) p.add(field + ".traffic", kOnlyTheLayer, "false");
  };
  return row;
}

}  // namespace swarm::tasks
