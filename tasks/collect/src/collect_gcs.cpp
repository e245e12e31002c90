#include "swarm/tasks/collect/collect_gcs.hpp"

#include <any>
#include <cmath>
#include <cstdio>
#include <limits>

#include "swarm/comm/link.hpp"
#include "swarm/tasks/collect/object_facts.hpp"

namespace swarm::gcs {


CollectGcsTask::CollectGcsTask(const swarm::scenario::Collect& config, std::uint32_t phase)
    : config_(config), phase_(phase) {}

void CollectGcsTask::start(GcsContext& ctx) {
  const comm::Topology& t = ctx.setup.topology;
  world_ = std::any_cast<const tasks::CollectWorld&>(ctx.setup.world.phase_data.at(phase_));
  std::vector<int> groups;
  for (int g = 0; g < t.groups(); ++g) {
    if (ctx.alive(ctx.leader_of(g))) groups.push_back(g);
  }
  objects_of_group_.assign(static_cast<std::size_t>(t.groups()), 0);
  done_.assign(static_cast<std::size_t>(t.groups()), true);
  seq_.assign(static_cast<std::size_t>(t.groups()), 1);
  owner_.assign(world_.objects.size(), -1);
  known_.clear();
  for (const auto& o : world_.objects) known_.push_back({collect::kObjectLying, o.cell.x, o.cell.y});
  leader_.clear();
  for (int g = 0; g < t.groups(); ++g) leader_.push_back(ctx.leader_of(g));
  resume_at_.assign(static_cast<std::size_t>(t.groups()), std::nullopt);
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
    for (std::int32_t id : mine) owner_[static_cast<std::size_t>(id)] = g;
    task::Order o;
    o.group = static_cast<std::uint16_t>(g);
    o.kind = task::OrderKind::Work;
    o.seq = seq_[static_cast<std::size_t>(g)];
    o.values = std::move(mine);
    ctx.out.order(o);
  }
}

void CollectGcsTask::on_report(const task::Report& r, GcsContext&) {
  if (r.group >= done_.size() || r.values.empty()) return;
  if (static_cast<std::uint32_t>(r.values[0]) != seq_[r.group]) return;  // for an order since replaced
  if (r.state == task::GroupState::Done) done_[r.group] = true;
  const auto& v = r.values;
  for (std::size_t k = 1; k + 3 < v.size(); k += 4) {
    const auto id = static_cast<std::size_t>(v[k]);
    if (v[k] < 0 || id >= owner_.size() || owner_[id] != r.group) continue;  // not the group's
    known_[id] = {v[k + 1], v[k + 2], v[k + 3]};
  }
}

void CollectGcsTask::send_resume(int g, GcsContext& ctx) {
  const auto gu = static_cast<std::size_t>(g);
  std::vector<std::int32_t> values;
  for (std::size_t id = 0; id < owner_.size(); ++id) {
    if (owner_[id] != g || known_[id][0] == collect::kObjectDelivered) continue;
    values.push_back(static_cast<std::int32_t>(id));
    values.insert(values.end(), known_[id].begin(), known_[id].end());
  }
  task::Order o;
  o.group = static_cast<std::uint16_t>(g);
  o.kind = task::OrderKind::Resume;
  o.seq = ++seq_[gu];
  o.values = values;
  ctx.out.order(o);
  ++resumes_;
  std::fprintf(stderr, "gcs: collect: group %d resumed by %s at tick %u with %zu objects\n", g,
               ctx.setup.topology.name_of(static_cast<comm::AgentId>(leader_[gu])).c_str(), ctx.tick(), values.size() / 4);
}

void CollectGcsTask::step(GcsContext& ctx) {
  const comm::LinkParams& lg = ctx.setup.links[comm::LinkClass::LeaderGcs];
  for (int g = 0; g < static_cast<int>(done_.size()); ++g) {
    const auto gu = static_cast<std::size_t>(g);
    if (done_[gu]) continue;
    if (const int now = ctx.leader_of(g); now != leader_[gu] && ctx.alive(now)) {
      // Resume the tick after every report the old leader sent by now has arrived.
      leader_[gu] = now;
      resume_at_[gu] = comm::last_arrival_tick(lg, ctx.tick()) + 1;
    }
    if (resume_at_[gu] && ctx.tick() >= *resume_at_[gu]) {
      resume_at_[gu].reset();
      send_resume(g, ctx);
    }
  }
  bool all = true;
  for (bool d : done_) all = all && d;
  complete_ = all;
}

int CollectGcsTask::delivered_known() const {
  int n = 0;
  for (const auto& k : known_) n += k[0] == collect::kObjectDelivered ? 1 : 0;
  return n;
}

ProgressLine CollectGcsTask::progress(const GcsContext&) const {
  int done = 0;
  for (bool d : done_) done += d ? 1 : 0;
  char detail[96];
  std::snprintf(detail, sizeof detail, "objects %zu  reported delivered %d  groups done %d/%zu", world_.objects.size(),
                delivered_known(), done, done_.size());
  return {"delivered", world_.objects.empty() ? 0.0 : static_cast<double>(delivered_known()) / static_cast<double>(world_.objects.size()),
          detail};
}

nlohmann::json CollectGcsTask::numbers() const {
  return {{"objects", world_.objects.size()},
          {"types", world_.destinations.size()},
          {"objects_per_group", objects_of_group_},
          {"reported_delivered", delivered_known()},
          {"resumes", resumes_}};
}

}  // namespace swarm::gcs
