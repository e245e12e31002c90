#include "swarm/member/member_node.hpp"

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm/app/task_wire.hpp"

namespace swarm::member {

using comm::LinkClass;
namespace topic = comm::topic;

void publish_motion(comm::Mailbox::Outlet<msgs::MotionCommand>& motion, comm::AgentId robot,
                    const RobotAgent::Step& step) {
  if (!step.path_changed) return;
  msgs::MotionCommand cmd;
  cmd.robot(robot);
  cmd.route_id(step.route_id);
  cmd.path_xy(app::to_xy(step.path));
  cmd.pick_steps(step.pick_steps);
  cmd.drop_steps(step.drop_steps);
  cmd.start_tick(step.start_tick);
  motion.send(cmd);
}

std::vector<comm::AgentId> leaders_except_self(const comm::Topology& t, int group, comm::AgentId self) {
  std::vector<comm::AgentId> out;
  for (comm::AgentId c : t.candidates(group)) {
    if (c != self) out.push_back(c);
  }
  return out;
}

void follow_route(RobotAgent& robot, const msgs::Route& r) {
  robot.follow(r.route_id(), app::from_xy(r.path_xy()), r.release(), r.pick_steps(), r.drop_steps(), r.start_tick(),
               r.replaces());
}

MemberNode::MemberNode(comm::LockstepAgent& agent, const app::RoleSetup& setup, int group, RobotAgent& robot)
    : agent_(agent),
      group_(group),
      robot_(robot),
      leaders_(setup.topology),
      patch_up_(agent.advertise<msgs::MapPatch>(topic::patch_up(group), LinkClass::MemberLeader,
                                                leaders_except_self(setup.topology, group, agent.self()))),
      motion_(agent.advertise<msgs::MotionCommand>(topic::kMotion, LinkClass::SimRobot, {setup.topology.sim()})),
      progress_(agent.advertise<msgs::RouteProgress>(topic::progress(group), LinkClass::MemberLeader,
                                                     leaders_except_self(setup.topology, group, agent.self()))),
      encoding_(app::patch_encoding(setup.world.scenario.map_encoding())) {
  // Every other candidate of the group writes the leader's topics (only the leader of the moment
  // sends). Readiness waits for those; whether DDS also matches this process's own writers does
  // not matter.
  const int leaders = static_cast<int>(leaders_except_self(setup.topology, group, agent.self()).size());
  agent.subscribe<msgs::Sense>(topic::sense(agent.self()), LinkClass::SimRobot, [this](const msgs::Sense& s) {
    auto changes = robot_.sense({s.x(), s.y()}, s.ranges(), s.max_range(), app::route_progress(s));
    robot_.sense_gripper(s.carrying());
    if (to_leader_) {
      to_leader_(changes);
    } else {
      pending_up_.insert(pending_up_.end(), changes.begin(), changes.end());
    }
  }, comm::Delivery::BestEffort, 1);  // a lost scan is not repeated; the next one is newer
  agent.subscribe<msgs::MapPatch>(topic::patch_down(group), LinkClass::MemberLeader, [this](const msgs::MapPatch& p) {
    if (from_leader(p.header())) robot_.learn(app::decode_patch(p.data(), robot_.map().size()));
  }, comm::Delivery::Reliable, leaders);
  // Routes and releases go to the whole group; each member keeps its own.
  agent.subscribe<msgs::Route>(topic::route(group), LinkClass::MemberLeader, [this](const msgs::Route& r) {
    if (r.robot() != agent_.self() || !from_leader(r.header())) return;
    ++routes_;
    follow_route(robot_, r);
  }, comm::Delivery::Reliable, leaders);
  agent.subscribe<msgs::RouteRelease>(topic::release(group), LinkClass::MemberLeader,
                                      [this](const msgs::RouteRelease& r) {
                                        if (r.robot() != agent_.self() || !from_leader(r.header())) return;
                                        robot_.release(r.route_id(), r.release());
                                        planner::mapf::Watch w = app::watch_from(r);
                                        if (!w.gates.empty()) watched_.watch(r.route_id(), r.header().tick(), std::move(w));
                                      }, comm::Delivery::Reliable, leaders);
}

bool MemberNode::from_leader(const msgs::Stamp& stamp) {
  // The clock being processed first: in real time a process that fell behind reads messages sent
  // after the last clock it stepped.
  leaders_.observe(agent_.clock());
  if (leaders_.led_at(stamp.sender(), stamp.tick())) return true;
  ++not_from_leader_;
  return false;
}

void MemberNode::lead(std::function<void(const std::vector<planner::CellChange>&)> to_leader) {
  to_leader_ = std::move(to_leader);
  if (!pending_up_.empty()) to_leader_(pending_up_);
  pending_up_.clear();
}

void MemberNode::follow() { to_leader_ = nullptr; }

void MemberNode::step(const msgs::Clock& clock) {
  observe(clock);
  if (!pending_up_.empty()) {
    msgs::MapPatch patch;
    patch.group(static_cast<std::uint16_t>(group_));
    patch.data(app::encode_patch(pending_up_, encoding_));
    patch_up_.send(patch);
    pending_up_.clear();
  }
  // The robots' cells in this clock may open a watched release: the robot then sets off now.
  std::vector<planner::Cell> cells;
  cells.reserve(clock.robots().size());
  for (const msgs::RobotState& r : clock.robots()) cells.push_back({r.x(), r.y()});
  watched_.see(clock.tick(), std::move(cells));
  if (const auto open = watched_.opened()) robot_.release(open->route_id, open->release);
  const RobotAgent::Step s = robot_.step(clock.tick());
  publish_motion(motion_, agent_.self(), s);
  // Progress and what the robot holds go to the leader when they change, all again to a new
  // leader (a standby that took the group over knows nothing of this robot yet), and again every
  // kProgressRefreshTicks (a lost report of a robot's last step would leave its leader waiting).
  const planner::RouteProgress p = robot_.following();
  const comm::AgentId leader = comm::leader_in(clock, agent_.topology(), group_);
  const bool refresh = clock.tick() % kProgressRefreshTicks == 0;
  if (p.id != 0 && (refresh || !(p == reported_) || robot_.carrying() != reported_carrying_ || leader != reported_to_)) {
    msgs::RouteProgress m;
    m.robot(agent_.self());
    m.route_id(p.id);
    m.step(p.step);
    m.state(static_cast<std::uint8_t>(p.state));
    m.acted(p.acted);
    m.carrying(robot_.carrying());
    progress_.send(m);
    reported_ = p;
    reported_carrying_ = robot_.carrying();
    reported_to_ = leader;
  }
}

std::string MemberNode::report_json() const {
  return nlohmann::json{{"routes", routes_},
                        {"releases_watched", watched_.releases_opened()},
                        {"orders_not_from_the_leader", not_from_leader_}}
      .dump();
}

}  // namespace swarm::member
