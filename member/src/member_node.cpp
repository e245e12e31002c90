#include "swarm/member/member_node.hpp"

#include <nlohmann/json.hpp>

#include "swarm/comm/convert.hpp"

namespace swarm::member {

using comm::LinkClass;
namespace topic = comm::topic;

void publish_motion(comm::Mailbox::Outlet<msgs::MotionCommand>& motion, comm::AgentId robot,
                    const RobotAgent::Step& step) {
  if (!step.path_changed) return;
  msgs::MotionCommand cmd;
  cmd.robot(robot);
  cmd.route_id(step.route_id);
  cmd.path_xy(comm::to_xy(step.path));
  cmd.pick_steps(step.pick_steps);
  cmd.drop_steps(step.drop_steps);
  motion.send(cmd);
}

void follow_route(RobotAgent& robot, const msgs::Route& r) {
  robot.follow(r.route_id(), comm::from_xy(r.path_xy()), r.release(), r.pick_steps(), r.drop_steps(), r.start_tick());
}

MemberNode::MemberNode(comm::LockstepAgent& agent, const comm::RoleSetup& setup, int group, int index)
    : agent_(agent),
      group_(group),
      index_(index),
      robot_(setup.world.truth.width(), setup.world.truth.height(), setup.world.truth.resolution()),
      patch_up_(agent.advertise<msgs::MapPatch>(topic::patch_up(group), LinkClass::MemberLeader,
                                                {setup.topology.leader(group)})),
      status_(agent.advertise<msgs::MemberStatus>(topic::status(group), LinkClass::MemberLeader,
                                                  {setup.topology.leader(group)})),
      motion_(agent.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {setup.topology.sim()})),
      progress_(agent.advertise<msgs::RouteProgress>(topic::progress(group), LinkClass::MemberLeader,
                                                     {setup.topology.leader(group)})),
      encoding_(comm::patch_encoding(setup.world.scenario.map_encoding())) {
  agent.subscribe<msgs::Sense>(topic::sense(agent.self()), LinkClass::SimRobot, [this](const msgs::Sense& s) {
    auto changes = robot_.sense({s.x(), s.y()}, s.ranges(), s.max_range(), comm::route_progress(s));
    pending_up_.insert(pending_up_.end(), changes.begin(), changes.end());
  }, comm::Delivery::BestEffort, 1);  // a lost scan is not repeated; the next one is newer
  agent.subscribe<msgs::MapPatch>(topic::patch_down(group), LinkClass::MemberLeader,
                                  [this](const msgs::MapPatch& p) { robot_.learn(comm::decode_patch(p.data(), robot_.map().size())); },
                                  comm::Delivery::Reliable, 1);
  agent.subscribe<msgs::Assignment>(topic::assign(group), LinkClass::MemberLeader, [this](const msgs::Assignment& a) {
    const auto waypoints = comm::optional_cells_from_xy(a.waypoints_xy());
    ++assignments_;
    robot_.assign(a.round(), index_ < static_cast<int>(waypoints.size()) ? waypoints[index_] : std::nullopt);
  }, comm::Delivery::Reliable, 1);
  // Routes and releases go to the whole group; each member keeps its own.
  agent.subscribe<msgs::Route>(topic::route(group), LinkClass::MemberLeader, [this](const msgs::Route& r) {
    if (r.robot() != agent_.self()) return;
    ++routes_;
    follow_route(robot_, r);
  }, comm::Delivery::Reliable, 1);
  agent.subscribe<msgs::RouteRelease>(topic::release(group), LinkClass::MemberLeader,
                                      [this](const msgs::RouteRelease& r) {
                                        if (r.robot() == agent_.self()) robot_.release(r.route_id(), r.release());
                                      }, comm::Delivery::Reliable, 1);
}

void MemberNode::step(const msgs::Clock& clock) {
  if (!pending_up_.empty()) {
    msgs::MapPatch patch;
    patch.group(static_cast<std::uint16_t>(group_));
    patch.data(comm::encode_patch(pending_up_, encoding_));
    patch_up_.send(patch);
    pending_up_.clear();
  }
  const RobotAgent::Step s = robot_.step(clock.tick());
  publish_motion(motion_, agent_.self(), s);
  const planner::RouteProgress p = robot_.following();
  if (p.id != 0 && !(p == reported_)) {
    msgs::RouteProgress m;
    m.robot(agent_.self());
    m.route_id(p.id);
    m.step(p.step);
    m.state(static_cast<std::uint8_t>(p.state));
    progress_.send(m);
    reported_ = p;
  }
  if (s.report) {
    msgs::MemberStatus status;
    status.robot(agent_.self());
    status.round(s.round);
    status.state(static_cast<std::uint8_t>(*s.report));
    status_.send(status);
  }
}

std::string MemberNode::report_json() const {
  return nlohmann::json{{"replans", robot_.replans()}, {"assignments", assignments_}, {"routes", routes_}}.dump();
}

}  // namespace swarm::member
