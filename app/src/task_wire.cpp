#include "swarm/app/task_wire.hpp"

#include <stdexcept>
#include <string>

#include "swarm/app/convert.hpp"
#include "swarm/comm/leadership.hpp"

namespace swarm::app {

task::Clock task_clock(const msgs::Clock& clock, const comm::Topology& topology) {
  task::Clock out;
  out.tick = clock.tick();
  out.robots.reserve(clock.robots().size());
  for (const auto& r : clock.robots()) out.robots.push_back({{r.x(), r.y()}, r.alive()});
  for (int g = 0; g < topology.groups(); ++g) out.leaders.push_back(static_cast<int>(comm::leader_in(clock, topology, g)));
  return out;
}

msgs::TaskOrder order_msg(const task::Order& o, std::uint32_t phase) {
  msgs::TaskOrder m;
  m.phase(phase);
  m.group(o.group);
  m.kind(static_cast<std::uint8_t>(o.kind));
  m.seq(o.seq);
  m.values(o.values);
  bool acts = false;
  for (const auto& r : o.routes) {
    m.route_robots().push_back(static_cast<std::uint16_t>(r.robot));
    m.routes_xy().push_back(to_xy(r.path));
    acts = acts || !r.pick_steps.empty() || !r.drop_steps.empty();
  }
  for (const auto& r : acts ? o.routes : std::vector<task::PlannedRoute>{}) {
    m.routes_picks().push_back(r.pick_steps);
    m.routes_drops().push_back(r.drop_steps);
  }
  return m;
}

task::Order order_from(const msgs::TaskOrder& m) {
  task::Order o;
  o.group = m.group();
  if (m.kind() > static_cast<std::uint8_t>(task::OrderKind::Rotate)) {
    throw std::runtime_error("an order of unknown kind " + std::to_string(m.kind()));
  }
  o.kind = static_cast<task::OrderKind>(m.kind());
  o.seq = m.seq();
  o.values = m.values();
  if (m.route_robots().size() != m.routes_xy().size()) {
    throw std::runtime_error("an order names " + std::to_string(m.route_robots().size()) + " robots for " +
                             std::to_string(m.routes_xy().size()) + " routes");
  }
  const bool acts = !m.routes_picks().empty() || !m.routes_drops().empty();
  if (acts && (m.routes_picks().size() != m.routes_xy().size() || m.routes_drops().size() != m.routes_xy().size())) {
    throw std::runtime_error("an order gives pick-up and drop steps for " + std::to_string(m.routes_picks().size()) +
                             " and " + std::to_string(m.routes_drops().size()) + " of its " +
                             std::to_string(m.routes_xy().size()) + " routes");
  }
  for (std::size_t k = 0; k < m.routes_xy().size(); ++k) {
    task::PlannedRoute r{m.route_robots()[k], from_xy(m.routes_xy()[k]), {}, {}};
    if (acts) {
      r.pick_steps = m.routes_picks()[k];
      r.drop_steps = m.routes_drops()[k];
      for (const auto& steps : {r.pick_steps, r.drop_steps}) {
        for (const std::uint32_t s : steps) {
          if (s >= r.path.size()) {
            throw std::runtime_error("an order's route " + std::to_string(k) + " acts at step " + std::to_string(s) +
                                     " of " + std::to_string(r.path.size()));
          }
        }
      }
    }
    o.routes.push_back(std::move(r));
  }
  return o;
}

msgs::TaskReport report_msg(const task::Report& r, std::uint32_t phase) {
  msgs::TaskReport m;
  m.phase(phase);
  m.group(r.group);
  m.state(static_cast<std::uint8_t>(r.state));
  m.xy(to_xy(r.cells));
  m.values(r.values);
  return m;
}

task::Report report_from(const msgs::TaskReport& m) {
  task::Report r;
  r.group = m.group();
  if (m.state() > static_cast<std::uint8_t>(task::GroupState::Held)) {
    throw std::runtime_error("a report of unknown state " + std::to_string(m.state()));
  }
  r.state = static_cast<task::GroupState>(m.state());
  r.cells = from_xy(m.xy());
  r.values = m.values();
  return r;
}

msgs::Route route_msg(const task::Route& r, std::uint32_t phase, comm::AgentId robot, std::uint32_t route_id) {
  msgs::Route m;
  m.phase(phase);
  m.robot(robot);
  m.route_id(route_id);
  m.path_xy(to_xy(r.path));
  m.release(r.release);
  m.pick_steps(r.pick_steps);
  m.drop_steps(r.drop_steps);
  m.start_tick(r.start_tick);
  m.replaces(r.replaces);
  return m;
}

msgs::RouteRelease release_msg(comm::AgentId robot, std::uint32_t route_id, std::uint32_t release,
                               const planner::mapf::Watch& watch) {
  msgs::RouteRelease m;
  m.robot(robot);
  m.route_id(route_id);
  m.release(release);
  for (std::size_t w = 0; w < watch.robots.size(); ++w) {
    m.watch_robots().push_back(static_cast<std::uint16_t>(watch.robots[w]));
    m.watch_lengths().push_back(static_cast<std::uint16_t>(watch.routes[w].size()));
    const auto xy = to_xy(watch.routes[w]);
    m.watch_xy().insert(m.watch_xy().end(), xy.begin(), xy.end());
  }
  for (const planner::mapf::Gate& g : watch.gates) {
    m.gate_release().push_back(g.release);
    for (std::uint32_t r : g.reached) m.gate_reached().push_back(static_cast<std::uint16_t>(r));
  }
  return m;
}

planner::mapf::Watch watch_from(const msgs::RouteRelease& m) {
  planner::mapf::Watch w;
  const std::size_t watched = m.watch_robots().size();
  if (m.watch_lengths().size() != watched) throw std::runtime_error("a watch whose robots and routes do not pair up");
  std::size_t cells = 0;
  for (std::uint16_t n : m.watch_lengths()) cells += n;
  if (m.watch_xy().size() != 2 * cells) throw std::runtime_error("a watch whose routes do not fill its cells");
  if (m.gate_reached().size() != m.gate_release().size() * watched) {
    throw std::runtime_error("a watch whose gates do not name every watched robot");
  }
  const std::vector<planner::Cell> all = from_xy(m.watch_xy());
  std::size_t at = 0;
  for (std::size_t i = 0; i < watched; ++i) {
    w.robots.push_back(m.watch_robots()[i]);
    w.routes.emplace_back(all.begin() + static_cast<std::ptrdiff_t>(at),
                          all.begin() + static_cast<std::ptrdiff_t>(at + m.watch_lengths()[i]));
    at += m.watch_lengths()[i];
  }
  for (std::size_t g = 0; g < m.gate_release().size(); ++g) {
    planner::mapf::Gate gate;
    gate.release = m.gate_release()[g];
    for (std::size_t i = 0; i < watched; ++i) gate.reached.push_back(m.gate_reached()[g * watched + i]);
    w.gates.push_back(std::move(gate));
  }
  return w;
}


msgs::PlanReport plan_report_msg(const task::PlanTelemetry& p, int group) {
  msgs::PlanReport m;
  m.group(static_cast<std::uint16_t>(group));
  m.round(p.round);
  m.plan_case(p.plan_case);
  m.waypoints_xy(to_xy(p.waypoints));
  m.group_frontiers_xy(to_xy(p.group_frontiers));
  for (const auto& seg : p.global_segments) m.global_segments_xy().push_back(to_xy(seg));
  m.chosen_segment(p.chosen_segment);
  return m;
}

}  // namespace swarm::app
