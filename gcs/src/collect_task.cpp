#include "swarm/gcs/collect_task.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "swarm/comm/task_codes.hpp"

namespace swarm::gcs {

namespace task = comm::task;

CollectGcsTask::CollectGcsTask(const swarm::scenario::Collect& config, std::uint32_t phase)
    : config_(config), phase_(phase) {}

void CollectGcsTask::start(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  world_ = config::collect_world(config_, ctx.setup.world.truth, ctx.setup.world.robot_cells,
                                 ctx.setup.world.scenario.seed(), "collect");
  std::vector<int> groups;
  for (int g = 0; g < t.groups(); ++g) {
    if (ctx.alive(ctx.leader_of(g))) groups.push_back(g);
  }
  objects_of_group_.assign(static_cast<std::size_t>(t.groups()), 0);
  done_.assign(static_cast<std::size_t>(t.groups()), true);
  ++seq_;
  if (groups.empty()) return;
  const std::size_t room = (world_.objects.size() + groups.size() - 1) / groups.size();
  std::vector<std::vector<std::int32_t>> ids(static_cast<std::size_t>(t.groups()));
  for (std::size_t i = 0; i < world_.objects.size(); ++i) {
    const planner::Cell o = world_.objects[i].cell;
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (int g : groups) {
      if (ids[static_cast<std::size_t>(g)].size() >= room) continue;
      const planner::Cell l = ctx.cell_of(ctx.leader_of(g));
      const double d = std::hypot(o.x - l.x, o.y - l.y);
      if (d < best_d) best_d = d, best = g;
    }
    ids[static_cast<std::size_t>(best)].push_back(static_cast<std::int32_t>(i));
  }
  for (int g : groups) {
    auto& mine = ids[static_cast<std::size_t>(g)];
    objects_of_group_[static_cast<std::size_t>(g)] = static_cast<int>(mine.size());
    done_[static_cast<std::size_t>(g)] = mine.empty();
    msgs::TaskOrder o;
    o.group(static_cast<std::uint16_t>(g));
    o.kind(task::kOrderWork);
    o.seq(seq_);
    o.values(std::move(mine));
    ctx.out.order(o);
  }
}

void CollectGcsTask::on_report(const msgs::TaskReport& r, GcsContext&) {
  if (r.state() != task::kDone || r.group() >= done_.size()) return;
  if (r.values().empty() || static_cast<std::uint32_t>(r.values()[0]) != seq_) return;
  done_[r.group()] = true;
}

void CollectGcsTask::step(GcsContext&) {
  bool all = true;
  for (bool d : done_) all = all && d;
  complete_ = all;
}

ProgressLine CollectGcsTask::progress(const GcsContext&) const {
  int done = 0;
  for (bool d : done_) done += d ? 1 : 0;
  char detail[64];
  std::snprintf(detail, sizeof detail, "objects %zu  groups done %d/%zu", world_.objects.size(), done, done_.size());
  return {"groups done", done_.empty() ? 0.0 : static_cast<double>(done) / static_cast<double>(done_.size()), detail};
}

nlohmann::json CollectGcsTask::numbers() const {
  return {{"objects", world_.objects.size()}, {"types", world_.destinations.size()}, {"objects_per_group", objects_of_group_}};
}

}  // namespace swarm::gcs
