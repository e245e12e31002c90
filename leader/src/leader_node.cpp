#include "swarm/leader/leader_node.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "swarm/comm/convert.hpp"
#include "swarm/member/member_node.hpp"
#include "swarm/planner/map_patch.hpp"

namespace swarm::leader {

using comm::LinkClass;
using planner::Cell;
namespace topic = comm::topic;

namespace {

planner::ExploreConfig explore_config(const swarm::scenario::Scenario& s) {
  const auto& e = s.explore();
  planner::ExploreConfig c;
  c.use_group_frontiers = e.mode() != swarm::scenario::BASELINE;
  c.dbscan_eps_cells = e.dbscan_eps_cells();
  c.dbscan_min_points = static_cast<int>(e.dbscan_min_points());
  c.small_segment_max_cells = static_cast<int>(e.small_segment_max_cells());
  c.small_segment_radius_cells = e.small_segment_radius_cells();
  c.kmeans_max_iterations = static_cast<int>(e.kmeans_max_iterations());
  c.seed = s.seed();
  return c;
}

Cell cell_of(const msgs::RobotState& r) { return {r.x(), r.y()}; }

}  // namespace

LeaderNode::LeaderNode(comm::LockstepAgent& agent, const comm::RoleSetup& setup, int group)
    : agent_(agent),
      topology_(setup.topology),
      group_(group),
      explore_(explore_config(setup.world.scenario)),
      encoding_(comm::patch_encoding(setup.world.scenario.map_encoding())),
      map_(setup.world.truth.width(), setup.world.truth.height(), setup.world.truth.resolution()),
      robot_(setup.world.truth.width(), setup.world.truth.height(), setup.world.truth.resolution()),
      arrived_(setup.topology.robots_per_group(), true),
      alive_(setup.topology.robots_per_group(), true),
      patch_gcs_(agent.advertise<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, {topology_.gcs()})),
      group_status_(agent.advertise<msgs::GroupStatus>(topic::kGroupStatus, LinkClass::LeaderGcs, {topology_.gcs()})),
      plan_report_(agent.advertise<msgs::PlanReport>(topic::kPlanReport, LinkClass::Telemetry, {topology_.gcs()})),
      heartbeat_(agent.advertise<msgs::Heartbeat>(topic::kHeartbeat, LinkClass::LeaderGcs, {topology_.gcs()})),
      motion_(agent.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {topology_.sim()})) {
  const auto members = topology_.members(group);
  if (!members.empty()) {
    patch_down_ = &agent.advertise<msgs::MapPatch>(topic::patch_down(group), LinkClass::MemberLeader, members);
    assign_ = &agent.advertise<msgs::Assignment>(topic::assign(group), LinkClass::MemberLeader, members);
  }
  // Subscription order fixes the order in which same-tick messages are handled.
  agent.subscribe<msgs::Sense>(topic::sense(agent.self()), LinkClass::SimRobot, [this](const msgs::Sense& s) {
    learn(map_.observe(robot_.sense({s.x(), s.y()}, s.ranges(), s.max_range())), true);
  }, comm::Delivery::BestEffort, 1);  // a lost scan is not repeated; the next one is newer
  if (!members.empty()) {
    agent.subscribe<msgs::MapPatch>(topic::patch_up(group), LinkClass::MemberLeader, [this](const msgs::MapPatch& p) {
      learn(map_.observe(comm::decode_patch(p.data())), true);
    }, comm::Delivery::Reliable, static_cast<int>(members.size()));
    agent.subscribe<msgs::MemberStatus>(topic::status(group), LinkClass::MemberLeader,
                                        [this](const msgs::MemberStatus& s) {
                                          if (s.round() == round_) arrived_[topology_.index_of(s.robot())] = true;
                                        }, comm::Delivery::Reliable, static_cast<int>(members.size()));
  }
  agent.subscribe<msgs::RoundStart>(topic::kRound, LinkClass::LeaderGcs, [this](const msgs::RoundStart& r) {
    planner::OccupancyGrid global(r.width(), r.height(), map_.group().resolution());
    comm::decode_map(r.map_rle(), static_cast<planner::PatchEncoding>(r.encoding()), global);
    learn(map_.adopt_global(global), false);
    pending_round_ = r.round();
  }, comm::Delivery::Reliable, 1);
}

void LeaderNode::learn(const std::vector<planner::CellChange>& fresh, bool own_observation) {
  if (fresh.empty()) return;
  if (own_observation) to_gcs_.insert(to_gcs_.end(), fresh.begin(), fresh.end());
  to_members_.insert(to_members_.end(), fresh.begin(), fresh.end());
  robot_.learn(fresh);
}

void LeaderNode::plan(std::uint32_t round, const msgs::Clock& clock) {
  const auto t0 = std::chrono::steady_clock::now();
  planner::ExploreInput in;
  in.global_map = &map_.global();
  in.group_map = &map_.group();
  for (int g = 0; g < topology_.groups(); ++g) in.leader_positions.push_back(cell_of(clock.robots()[topology_.leader(g)]));
  in.group = group_;
  // Only the living robots get waypoints (K-Means with k = living members); index 0, the leader,
  // is always alive.
  std::vector<int> living;
  for (int i = 0; i < topology_.robots_per_group(); ++i) {
    if (!alive_[i]) continue;
    living.push_back(i);
    in.member_positions.push_back(cell_of(clock.robots()[topology_.robot(group_, i)]));
  }
  in.round = static_cast<int>(round);
  planner::ExplorePlan plan = planner::plan_group_exploration(in, explore_);
  std::vector<std::optional<Cell>> waypoints(topology_.robots_per_group());
  for (std::size_t j = 0; j < living.size(); ++j) waypoints[living[j]] = plan.waypoints[j];
  plan.waypoints = waypoints;
  planning_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++rounds_planned_;
  if (plan.plan_case == planner::PlanCase::GroupFrontier) ++case_a_;
  if (plan.plan_case == planner::PlanCase::GlobalAssignment) ++case_b_;

  round_ = round;
  for (int i = 0; i < topology_.robots_per_group(); ++i) arrived_[i] = !plan.waypoints[i].has_value();
  group_reported_ = false;
  robot_.assign(round, plan.waypoints[0]);
  if (assign_ != nullptr) {
    msgs::Assignment a;
    a.round(round);
    a.waypoints_xy(comm::to_xy(plan.waypoints));
    assign_->send(a);
  }
  msgs::PlanReport report;
  report.group(static_cast<std::uint16_t>(group_));
  report.round(round);
  report.plan_case(static_cast<std::uint8_t>(plan.plan_case));
  report.waypoints_xy(comm::to_xy(plan.waypoints));
  report.group_frontiers_xy(comm::to_xy(plan.group_frontiers));
  for (const auto& seg : plan.global_segments) report.global_segments_xy().push_back(comm::to_xy(seg));
  report.chosen_segment(plan.chosen_segment);
  plan_report_.send(report);
}

void LeaderNode::step(const msgs::Clock& clock) {
  // A member the simulator lost gets no waypoints and nobody waits for it; one that comes back
  // (its link healed) is planned for again from the next round.
  for (int i = 1; i < topology_.robots_per_group(); ++i) {
    const bool alive = clock.robots()[topology_.robot(group_, i)].alive();
    if (alive == alive_[i]) continue;
    alive_[i] = alive;
    arrived_[i] = true;
    const std::string name = topology_.name_of(topology_.robot(group_, i));
    if (!alive) {
      members_lost_.push_back({name, clock.tick(), std::nullopt});
    } else if (auto it = std::find_if(members_lost_.rbegin(), members_lost_.rend(),
                                      [&](const MemberLoss& l) { return l.name == name; });
               it != members_lost_.rend()) {
      it->rejoined_tick = clock.tick();
    }
    std::fprintf(stderr, "%s: %s %s at tick %u\n", topology_.name_of(agent_.self()).c_str(), name.c_str(),
                 alive ? "is back; planning for it from the next round" : "lost; planning without it", clock.tick());
  }
  msgs::Heartbeat beat;
  beat.group(static_cast<std::uint16_t>(group_));
  heartbeat_.send(beat);
  if (pending_round_) {
    plan(*pending_round_, clock);
    pending_round_.reset();
  }
  const member::RobotAgent::Step s = robot_.step();
  member::publish_motion(motion_, agent_.self(), s);
  if (s.report && s.round == round_) arrived_[0] = true;

  bool all_arrived = true;
  for (bool a : arrived_) all_arrived = all_arrived && a;
  if (round_ > 0 && all_arrived && !group_reported_) {
    msgs::GroupStatus status;
    status.group(static_cast<std::uint16_t>(group_));
    status.round(round_);
    group_status_.send(status);
    group_reported_ = true;
  }
  if (!to_gcs_.empty()) {
    msgs::MapPatch patch;
    patch.group(static_cast<std::uint16_t>(group_));
    patch.data(comm::encode_patch(to_gcs_, encoding_));
    patch_gcs_.send(patch);
    to_gcs_.clear();
  }
  if (!to_members_.empty()) {
    if (patch_down_ != nullptr) {
      msgs::MapPatch patch;
      patch.group(static_cast<std::uint16_t>(group_));
      patch.data(comm::encode_patch(to_members_, encoding_));
      patch_down_->send(patch);
    }
    to_members_.clear();
  }
}

std::string LeaderNode::report_json() const {
  nlohmann::json lost = nlohmann::json::array();
  for (const auto& l : members_lost_) {
    lost.push_back({{"agent", l.name},
                    {"noticed_at_tick", l.noticed_tick},
                    {"rejoined_at_tick", l.rejoined_tick ? nlohmann::json(*l.rejoined_tick) : nlohmann::json(nullptr)}});
  }
  return nlohmann::json{{"rounds_planned", rounds_planned_},
                        {"members_lost", lost},
                        {"case_a_rounds", case_a_},
                        {"case_b_rounds", case_b_},
                        {"planning_seconds", planning_seconds_},
                        {"replans", robot_.replans()}}
      .dump();
}

}  // namespace swarm::leader
