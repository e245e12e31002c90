// The GCS's collection task (issue 10; PAPERS.md section 4): every object carried to its type's
// destination. The objects and destinations come from the scenario (config::collect_world, the
// same for the simulator, the GCS and the leaders, so an object is known by its number).
//
// The GCS splits the objects among the groups whose leader lives (each object to the nearest
// group leader with room left: at most ceil(objects / groups) per group) and sends each group its
// objects' numbers (TaskOrder kOrderWork, values = [object, ...]); the leader splits them among
// its members (leader/collect_task.hpp). The phase is complete when every group has reported its
// objects delivered (TaskReport kDone, values = [seq]). The simulator judges what was delivered.
#pragma once

#include <cstdint>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/gcs/gcs_task.hpp"

namespace swarm::gcs {

class CollectGcsTask : public GcsTask {
 public:
  CollectGcsTask(const swarm::scenario::Collect& config, std::uint32_t phase);
  void start(GcsContext& ctx) override;
  void step(GcsContext& ctx) override;
  [[nodiscard]] bool complete() const override { return complete_; }
  [[nodiscard]] ProgressLine progress(const GcsContext& ctx) const override;
  void on_report(const msgs::TaskReport& r, GcsContext& ctx) override;
  [[nodiscard]] nlohmann::json numbers() const override;

 private:
  swarm::scenario::Collect config_;
  std::uint32_t phase_;
  config::CollectWorld world_;
  std::uint32_t seq_ = 0;
  std::vector<int> objects_of_group_;  // how many each group was given
  std::vector<bool> done_;
  bool complete_ = false;
};

}  // namespace swarm::gcs
