#include "swarm/tasks/collect/collect_gcs.hpp"

#include <algorithm>
#include <any>
#include <cmath>
#include <cstdio>
#include <limits>

#include "swarm/tasks/collect/nearest_with_room.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm/planner/tours/tour.hpp"
#include "swarm/tasks/collect/object_facts.hpp"

namespace swarm::gcs {


CollectGcsTask::CollectGcsTask(const swarm::scenario::Collect& config, const swarm::scenario::Mapf& paths,
                               std::uint32_t phase, bool map_given)
    : phase_(phase) {
  MapfGcsTask::Lifelong drive;
  drive.routes = [this](const GcsContext& ctx, const planner::OccupancyGrid& map, const std::vector<int>& robots,
                        const char*) { return tours(ctx, map, robots); };
  drive.window = static_cast<int>(config.traffic_window_steps());
  drive.motion = planner::MotionModel::eight();  // as the tours, and as the phase's robots move
  drive.done = [this](int robot, const MapfGcsTask::Stop& stop, bool reached) { stop_done(robot, stop, reached); };
  drive.picked = [this](int robot, planner::Cell at, const std::vector<std::uint32_t>& objects) {
    picked(robot, at, objects);
  };
  drive_ = std::make_unique<MapfGcsTask>(paths, phase, map_given, std::move(drive));
}

void CollectGcsTask::start(GcsContext& ctx) {
  world_ = std::any_cast<const tasks::CollectWorld&>(ctx.setup.world.phase_data.at(phase_));
  known_.clear();
  for (const auto& o : world_.objects) known_.push_back({collect::kObjectLying, o.cell.x, o.cell.y});
  doubt_.assign(known_.size(), std::nullopt);
  first_pick_.assign(static_cast<std::size_t>(ctx.setup.topology.robots()), planner::Cell{-1, -1});
  drive_->start(ctx);  // plans the tours from where the robots stand (still: gcs/gcs_node.hpp)
}

void CollectGcsTask::on_report(const task::Report& r, GcsContext& ctx) { drive_->on_report(r, ctx); }

void CollectGcsTask::step(GcsContext& ctx) {
  if (complete_ || !gave_up_.empty()) return;
  drive_->step(ctx);
  if (!drive_->complete()) return;
  const int delivered = delivered_known();
  if (delivered == static_cast<int>(world_.objects.size())) {
    complete_ = !any_doubt();  // else the gripper's word on one is still on its way
  } else if (delivered > delivered_at_tours_) {
    // A stop was skipped (an object or destination no robot could reach then): new tours for
    // what is left, from where the robots stand now.
    drive_->restart(ctx, "every tour done, objects left");
  } else {
    gave_up_ = std::to_string(world_.objects.size() - static_cast<std::size_t>(delivered)) +
               " objects that no robot's tour reaches";
    // The usual reason, named: a lost robot stands on the object (no living robot can ever pick
    // it up).
    const comm::Topology& t = ctx.setup.topology;
    int under = 0;
    for (const auto& k : known_) {
      if (k[0] != collect::kObjectLying) continue;
      for (int r = 0; r < t.robots(); ++r) {
        if (!ctx.alive(r) && ctx.cell_of(r) == planner::Cell{k[1], k[2]}) {
          ++under;
          break;
        }
      }
    }
    if (under > 0) gave_up_ += " (" + std::to_string(under) + " under a lost robot)";
  }
}

bool CollectGcsTask::any_doubt() const {
  return std::any_of(doubt_.begin(), doubt_.end(), [](const auto& d) { return d.has_value(); });
}

int CollectGcsTask::delivered_known() const {
  int n = 0;
  for (const auto& k : known_) n += k[0] == collect::kObjectDelivered ? 1 : 0;
  return n;
}

ProgressLine CollectGcsTask::progress(const GcsContext&) const {
  char detail[96];
  std::snprintf(detail, sizeof detail, "objects %zu  delivered %d", world_.objects.size(), delivered_known());
  return {"delivered", world_.objects.empty() ? 0.0 : static_cast<double>(delivered_known()) / static_cast<double>(world_.objects.size()),
          detail};
}

nlohmann::json CollectGcsTask::numbers() const {
  return {{"objects", world_.objects.size()},
          {"types", world_.destinations.size()},
          {"reported_delivered", delivered_known()},
          {"tour_plans", tour_plans_},
          {"doubted_pickups", doubted_},
          {"traffic", drive_->numbers()}};
}

std::string CollectGcsTask::given_up() const {
  if (!gave_up_.empty()) return gave_up_;
  return drive_->given_up();
}

std::vector<std::vector<MapfGcsTask::Stop>> CollectGcsTask::tours(const GcsContext& ctx,
                                                                  const planner::OccupancyGrid& map,
                                                                  const std::vector<int>& robots) {
  using Stop = MapfGcsTask::Stop;
  const comm::Topology& t = ctx.setup.topology;
  ++tour_plans_;
  delivered_at_tours_ = delivered_known();
  // What a lost robot carried lies where the simulator put it down. What it was to pick up where
  // it stood, not known picked up, lies there or beside it: believed beside, where a robot's
  // gripper will tell.
  std::vector<planner::Cell> at;
  for (int r = 0; r < t.robots(); ++r) at.push_back(ctx.cell_of(r));
  const auto beside = [&](int r) { return planner::put_down_cell(map, ctx.cell_of(r), at); };
  for (int r = 0; r < t.robots(); ++r) {
    const planner::Cell first = first_pick_[static_cast<std::size_t>(r)];
    if (ctx.alive(r) || first.x < 0) continue;
    const planner::Cell c = beside(r);
    for (std::size_t id = 0; id < known_.size(); ++id) {
      auto& k = known_[id];
      if (k[0] != collect::kObjectLying || planner::Cell{k[1], k[2]} != first) continue;
      k = {collect::kObjectLying, c.x, c.y};
      doubt_[id] = Doubt{first, c, -1};
      ++doubted_;
    }
  }
  std::fill(first_pick_.begin(), first_pick_.end(), planner::Cell{-1, -1});
  for (auto& k : known_) {
    if (k[0] != collect::kObjectCarried || ctx.alive(k[1])) continue;
    const planner::Cell c = beside(k[1]);
    k = {collect::kObjectLying, c.x, c.y};
  }
  // Tours are planned round the robots that will not move.
  planner::OccupancyGrid around = map;
  for (int r = 0; r < t.robots(); ++r) {
    if (std::find(robots.begin(), robots.end(), r) == robots.end()) around.set(ctx.cell_of(r), planner::CellState::Occupied);
  }
  // Each robot keeps what it carries; each lying object goes to the nearest robot with room left
  // (nearest_with_room.hpp).
  std::vector<std::vector<int>> mine(static_cast<std::size_t>(t.robots()));
  std::vector<int> lying;
  for (std::size_t id = 0; id < known_.size(); ++id) {
    if (known_[id][0] == collect::kObjectCarried) mine[static_cast<std::size_t>(known_[id][1])].push_back(static_cast<int>(id));
    if (known_[id][0] == collect::kObjectLying) lying.push_back(static_cast<int>(id));
  }
  std::vector<planner::Cell> cells, holders;
  std::vector<std::size_t> held;
  for (const int id : lying) cells.push_back({known_[static_cast<std::size_t>(id)][1], known_[static_cast<std::size_t>(id)][2]});
  for (const int r : robots) {
    holders.push_back(ctx.cell_of(r));
    held.push_back(mine[static_cast<std::size_t>(r)].size());
  }
  const std::vector<int> to = collect::nearest_with_room(cells, holders, held);
  for (std::size_t i = 0; i < lying.size(); ++i) {
    if (to[i] >= 0) mine[static_cast<std::size_t>(robots[static_cast<std::size_t>(to[i])])].push_back(lying[i]);
  }
  std::vector<std::vector<Stop>> stops(static_cast<std::size_t>(t.robots()));
  for (const int r : robots) {
    const auto& ids = mine[static_cast<std::size_t>(r)];
    if (ids.empty()) continue;
    planner::TourProblem problem;
    problem.start = ctx.cell_of(r);
    problem.destinations = world_.destinations;
    for (const int id : ids) {
      const auto& k = known_[static_cast<std::size_t>(id)];
      // What it carries is "picked up" where it starts.
      const planner::Cell c = k[0] == collect::kObjectCarried ? problem.start : planner::Cell{k[1], k[2]};
      problem.objects.push_back({c, world_.objects[static_cast<std::size_t>(id)].type});
    }
    planner::TourOptions options;
    options.variant = planner::TourVariant::kDistanceAngle;
    options.search = planner::TourOptions::Search::kExact;
    options.seed = planner::mix_seed({ctx.setup.world.scenario.seed(), tour_plans_, static_cast<std::uint64_t>(r)});
    const planner::TourPlan plan = planner::plan_tour(around, problem, options);
    auto& mine_stops = stops[static_cast<std::size_t>(r)];
    for (const planner::TourLeg& leg : plan.legs) {
      if (leg.stop.kind == planner::TourStop::kDrop) {
        mine_stops.push_back({leg.stop.cell, Stop::Act::kDrop});
      } else if (known_[static_cast<std::size_t>(ids[static_cast<std::size_t>(leg.stop.object)])][0] != collect::kObjectCarried) {
        if (mine_stops.empty() && leg.stop.cell == problem.start) first_pick_[static_cast<std::size_t>(r)] = problem.start;
        mine_stops.push_back({leg.stop.cell, Stop::Act::kPick});
      }
    }
  }
  for (auto& d : doubt_) {
    if (!d) continue;
    d->by = -1;
    for (const int r : robots) {
      for (const Stop& s : stops[static_cast<std::size_t>(r)]) {
        if (s.act == Stop::Act::kPick && s.cell == d->beside) d->by = r;
      }
    }
  }
  return stops;
}

void CollectGcsTask::stop_done(int robot, const MapfGcsTask::Stop& stop, bool reached) {
  first_pick_[static_cast<std::size_t>(robot)] = planner::Cell{-1, -1};  // made, or skipped
  if (!reached || stop.act == MapfGcsTask::Stop::Act::kNone) return;
  // The simulator's rule: a pick-up takes every object lying on the cell; a drop leaves all the
  // robot carries, delivered where it is its type's destination.
  for (std::size_t id = 0; id < known_.size(); ++id) {
    auto& k = known_[id];
    if (stop.act == MapfGcsTask::Stop::Act::kPick && k[0] == collect::kObjectLying && k[1] == stop.cell.x &&
        k[2] == stop.cell.y) {
      k = {collect::kObjectCarried, robot, 0};
    } else if (stop.act == MapfGcsTask::Stop::Act::kDrop && k[0] == collect::kObjectCarried && k[1] == robot) {
      const bool right = world_.destinations[static_cast<std::size_t>(world_.objects[id].type)] == stop.cell;
      k = right ? std::array<std::int32_t, 3>{collect::kObjectDelivered, stop.cell.x, stop.cell.y}
                : std::array<std::int32_t, 3>{collect::kObjectLying, stop.cell.x, stop.cell.y};
    }
  }
}

void CollectGcsTask::picked(int robot, planner::Cell at, const std::vector<std::uint32_t>& objects) {
  for (std::size_t id = 0; id < known_.size(); ++id) {
    if (!doubt_[id] || doubt_[id]->by != robot || doubt_[id]->beside != at) continue;
    auto& k = known_[id];
    if (std::find(objects.begin(), objects.end(), static_cast<std::uint32_t>(id)) != objects.end()) {
      if (k[0] != collect::kObjectDelivered) k = {collect::kObjectCarried, robot, 0};
    } else {
      // Picked up where it was believed put down, and not there: it lies under the lost robot
      // (and was not delivered, if the belief had it so meanwhile).
      k = {collect::kObjectLying, doubt_[id]->under.x, doubt_[id]->under.y};
    }
    doubt_[id].reset();
  }
}

}  // namespace swarm::gcs
