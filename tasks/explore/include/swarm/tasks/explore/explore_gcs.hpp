// The GCS's exploration task (docs/papers.md section 1): planning rounds on the fused map with the
// paper's one-round delay (mission.hpp), each round's map to the leaders, completion when no
// reachable frontier is left.
#pragma once

#include "swarm/gcs/gcs_task.hpp"

namespace swarm::gcs {

class ExploreGcsTask : public GcsTask {
 public:
  explicit ExploreGcsTask(std::uint32_t phase) : phase_(phase) {}
  void start(GcsContext& ctx) override;
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return complete_; }
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  void on_round_done(int group, std::uint32_t round, GcsContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  std::uint32_t phase_;
  bool complete_ = false;
  std::uint32_t rounds_at_start_ = 0;
  std::uint32_t rounds_ = 0;
};

}  // namespace swarm::gcs
