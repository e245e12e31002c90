// The GCS's exploration task (docs/papers.md section 1): planning rounds on the fused map with the
// paper's one-round delay (planning_rounds.hpp), each round's map to the leaders, completion when
// no reachable frontier is left.
#pragma once

#include <optional>

#include "swarm/gcs/gcs_task.hpp"
#include "swarm/tasks/explore/planning_rounds.hpp"

namespace swarm::gcs {

class ExploreGcsTask : public GcsTask {
 public:
  ExploreGcsTask(std::uint32_t phase, tasks::PlanningRoundsConfig config)
      : phase_(phase), config_(std::move(config)), rounds_(config_) {}
  void start(GcsContext& ctx) override;
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return complete_; }
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  void on_round_done(int group, std::uint32_t round, GcsContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  std::uint32_t phase_;
  tasks::PlanningRoundsConfig config_;
  tasks::PlanningRounds rounds_;
  // The run-wide number of this phase's round 1 on the wire; this phase's round r went out as
  // first_round_ + r - 1.
  std::optional<std::uint32_t> first_round_;
  bool complete_ = false;
};

}  // namespace swarm::gcs
