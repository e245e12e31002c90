#include "swarm/tasks/collect/collect_row.hpp"

#include <any>
#include <cmath>
#include <utility>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/tasks/collect/collect_gcs.hpp"
#include "swarm/tasks/collect/collect_world.hpp"
#include "swarm/tasks/mapf/mapf_leader.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"

namespace swarm::tasks {

namespace {
// The simulator's judge: it lays the phase's objects out (its `resolve` drew them at load), counts what was picked, delivered and dropped at a wrong destination, with a point of
// the delivered curve at every delivery, and what the robots drove in the tour planner's terms.
class CollectJudge : public sim::PhaseJudge {
 public:
  explicit CollectJudge(CollectWorld world) : world_(std::move(world)) {}
  sim::Progress progress(const sim::World& world) const override {
    return {static_cast<std::uint64_t>(world.collect().delivered), static_cast<std::uint64_t>(world.collect().objects),
            world.object_states()};
  }
  void start(sim::World& world, std::uint32_t tick) override {
    world.set_objects(world_.objects, world_.destinations);
    curve_.emplace_back(tick, 0.0);
  }
  void after_tick(const sim::World& world, std::uint32_t k) override {
    const int delivered = world.collect().delivered;
    if (delivered != static_cast<int>(curve_.back().second)) curve_.emplace_back(k, delivered);
    if (!full_tick_ && delivered >= world.collect().objects) full_tick_ = k;
  }
  nlohmann::json judge(const sim::World& world, const sim::PhaseFacts& f) const override {
    nlohmann::json curve = nlohmann::json::array();
    for (const auto& [tick, n] : curve_) curve.push_back({tick, n});
    const auto& c = world.collect();
    // Length in cells (straight 1, diagonal sqrt 2), rotation in radians (eighths of a turn x pi / 4).
    const double length = static_cast<double>(f.motion.total.moves - f.diagonal_moves) +
                          static_cast<double>(f.diagonal_moves) * planner::MotionModel::kDiagonalCost;
    const double rotation = static_cast<double>(f.motion.total.turn_eighths) * std::acos(-1.0) / 4.0;
    return {{record::kGroundTruthDone, c.delivered == c.objects},
            {"objects", c.objects},
            {"delivered", c.delivered},
            {"picked", c.picked},
            {"wrong_drops", c.wrong_drops},
            {"driven_length_cells", length},
            {"driven_rotation_rad", rotation},
            {"makespan_ticks", full_tick_ ? nlohmann::json(*full_tick_ - f.start_tick) : nlohmann::json(nullptr)},
            {"delivered_curve", curve}};
  }

 private:
  CollectWorld world_;
  std::vector<std::pair<std::uint32_t, double>> curve_;  // (tick, objects delivered)
  std::optional<std::uint32_t> full_tick_;                // every object delivered
};
}  // namespace

TaskRow collect_row() {
  TaskRow row;
  row.name = "collect";
  row.phase_case = Phase::kCollect;
  row.motion = planner::MotionModel::eight();  // the tour paper's robots turn in eighths
  row.gcs = [](const Phase& phase, const app::RoleSetup& setup, std::uint32_t index) {
    return std::make_unique<gcs::CollectGcsTask>(phase.collect(), traffic_driving(), index,
                                                 config::map_given(setup.world.scenario, index));
  };
  row.leader = [](const Phase&, const app::RoleSetup&, int group, std::uint32_t) -> std::unique_ptr<leader::GroupTask> {
    // The leaders drive the traffic layer's windows as they drive mapf plans.
    return std::make_unique<leader::MapfGroupTask>(traffic_driving(), group);
  };
  row.judge = [](const Phase&, const app::RoleSetup& setup, std::uint32_t index) {
    return std::make_unique<CollectJudge>(std::any_cast<const CollectWorld&>(setup.world.phase_data.at(index)));
  };
  row.resolve = [](const Phase& phase, const config::World& world, const std::string& field) -> std::any {
    return collect_world(phase.collect(), world.truth, world.robot_cells, world.scenario.seed(), field);
  };
  row.check = [](const Phase& phase, const config::World&, const std::string& field, config::Problems& p) {
    const auto& c = phase.collect();
    p.at_least(field + ".types", 1, c.types());
    p.at_least(field + ".traffic_window_steps", 1, c.traffic_window_steps());
    if (!c.traffic()) p.add(field + ".traffic", kOnlyTheLayer, "false");
    for (int o = 0; o < c.objects_size(); ++o) {
      if (c.objects(o).type() >= c.types()) {
        p.add(field + ".objects[" + std::to_string(o) + "].type", "be below collect.types (" + std::to_string(c.types()) + ")",
              std::to_string(c.objects(o).type()));
      }
    }
    if (c.destinations_size() > 0 && static_cast<std::uint32_t>(c.destinations_size()) != c.types()) {
      p.add(field + ".destinations", "give one destination per type (" + std::to_string(c.types()) + ")",
            std::to_string(c.destinations_size()));
    }
  };
  return row;
}

}  // namespace swarm::tasks
