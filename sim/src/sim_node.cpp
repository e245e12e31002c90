#include "swarm/sim/sim_node.hpp"

#include <nlohmann/json.hpp>

#include "swarm/comm/convert.hpp"

namespace swarm::sim {

using comm::LinkClass;
namespace topic = comm::topic;

namespace {
LidarConfig lidar_of(const comm::RoleSetup& setup) {
  const auto& s = setup.world.scenario;
  return {static_cast<int>(s.lidar_beams()),
          static_cast<float>(s.sensing_range_m() / setup.world.truth.resolution())};
}
}  // namespace

SimNode::SimNode(comm::LockstepClock& clock, const comm::RoleSetup& setup)
    : clock_(clock),
      world_(setup.world.truth, setup.world.robot_cells, lidar_of(setup)),
      max_ticks_(setup.world.scenario.max_ticks()),
      alive_(setup.world.robot_cells.size(), true) {
  const comm::Topology& t = setup.topology;
  for (comm::AgentId r : t.robot_ids()) {
    sense_.push_back(&clock.advertise<msgs::Sense>(topic::sense(r), LinkClass::SimRobot, {r}));
  }
  clock.subscribe<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, [this, &t](const msgs::MotionCommand& m) {
    if (t.is_robot(m.robot()) && alive_[m.robot()]) world_.command(m.robot(), comm::from_xy(m.path_xy()));
  }, comm::Delivery::Reliable, t.robots());
}

std::vector<msgs::RobotState> SimNode::states() const {
  std::vector<msgs::RobotState> out;
  for (const auto& c : world_.robots()) {
    msgs::RobotState s;
    s.x(static_cast<std::int16_t>(c.x));
    s.y(static_cast<std::int16_t>(c.y));
    s.alive(alive_[out.size()]);
    out.push_back(s);
  }
  return out;
}

std::uint32_t SimNode::run() {
  clock_.wait_ready();
  std::vector<float> ranges;
  for (std::uint32_t k = 0;; ++k) {
    clock_.begin_tick(k);
    for (std::size_t r = 0; r < alive_.size(); ++r) {
      const bool lost = clock_.is_lost(static_cast<comm::AgentId>(r));
      // A lost robot stands where it was; one whose link healed senses and moves again.
      if (alive_[r] && lost) world_.command(static_cast<int>(r), {});
      alive_[r] = !lost;
    }
    if (k > 0) world_.move();
    for (std::size_t r = 0; r < sense_.size(); ++r) {
      if (!alive_[r]) continue;
      world_.scan(static_cast<int>(r), ranges);
      msgs::Sense s;
      s.x(static_cast<std::int16_t>(world_.robots()[r].x));
      s.y(static_cast<std::int16_t>(world_.robots()[r].y));
      s.max_range(world_.lidar().range_cells);
      s.ranges(ranges);
      sense_[r]->send(s);
    }
    const double explored = world_.explored_fraction();
    if (!steps_to_99_ && explored >= 0.99) steps_to_99_ = k;
    if (k % 10 == 0) curve_.emplace_back(k, explored);
    clock_.publish_clock(k, states(), false);
    complete_ = clock_.wait_done(k);
    last_tick_ = k;
    if (complete_ || k + 1 >= max_ticks_) {
      curve_.emplace_back(k, explored);
      clock_.publish_clock(k + 1, states(), true);
      return k;
    }
  }
}

std::string SimNode::report_json() const {
  nlohmann::json curve = nlohmann::json::array();
  for (const auto& [tick, f] : curve_) curve.push_back({tick, f});
  nlohmann::json losses = nlohmann::json::array();
  for (const auto& l : clock_.losses()) {
    losses.push_back({{"agent", clock_.topology().name_of(l.agent)},
                      {"missed_tick", l.tick},
                      {"detection_seconds", l.detection_seconds},
                      {"rejoined_tick", l.rejoined_tick ? nlohmann::json(*l.rejoined_tick) : nlohmann::json(nullptr)}});
  }
  return nlohmann::json{{"last_tick", last_tick_},
                        {"agents_lost", losses},
                        {"steps_to_99", steps_to_99_ ? nlohmann::json(*steps_to_99_) : nlohmann::json(nullptr)},
                        {"explored_fraction", world_.explored_fraction()},
                        {"reachable_free_cells", world_.reachable_free_cells()},
                        {"moves", world_.moves()},
                        {"blocked_moves", world_.blocked_moves()},
                        {"wall_stops", world_.wall_stops()},
                        {"explored_curve", curve}}
      .dump();
}

}  // namespace swarm::sim
