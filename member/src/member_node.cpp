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
  cmd.path_xy(comm::to_xy(step.path));
  motion.send(cmd);
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
      encoding_(comm::patch_encoding(setup.world.scenario.map_encoding())) {
  agent.subscribe<msgs::Sense>(topic::sense(agent.self()), LinkClass::SimRobot, [this](const msgs::Sense& s) {
    auto changes = robot_.sense({s.x(), s.y()}, s.ranges(), s.max_range());
    pending_up_.insert(pending_up_.end(), changes.begin(), changes.end());
  }, comm::Delivery::BestEffort, 1);  // a lost scan is not repeated; the next one is newer
  agent.subscribe<msgs::MapPatch>(topic::patch_down(group), LinkClass::MemberLeader,
                                  [this](const msgs::MapPatch& p) { robot_.learn(comm::decode_patch(p.data())); },
                                  comm::Delivery::Reliable, 1);
  agent.subscribe<msgs::Assignment>(topic::assign(group), LinkClass::MemberLeader, [this](const msgs::Assignment& a) {
    const auto waypoints = comm::optional_cells_from_xy(a.waypoints_xy());
    ++assignments_;
    robot_.assign(a.round(), index_ < static_cast<int>(waypoints.size()) ? waypoints[index_] : std::nullopt);
  }, comm::Delivery::Reliable, 1);
}

void MemberNode::step(const msgs::Clock& /*clock*/) {
  if (!pending_up_.empty()) {
    msgs::MapPatch patch;
    patch.group(static_cast<std::uint16_t>(group_));
    patch.data(comm::encode_patch(pending_up_, encoding_));
    patch_up_.send(patch);
    pending_up_.clear();
  }
  const RobotAgent::Step s = robot_.step();
  publish_motion(motion_, agent_.self(), s);
  if (s.report) {
    msgs::MemberStatus status;
    status.robot(agent_.self());
    status.round(s.round);
    status.state(static_cast<std::uint8_t>(*s.report));
    status_.send(status);
  }
}

std::string MemberNode::report_json() const {
  return nlohmann::json{{"replans", robot_.replans()}, {"assignments", assignments_}}.dump();
}

}  // namespace swarm::member
