// The task seam's messages (app/task_messages.hpp) on the wire (idl/swarm_msgs.idl TaskOrder,
// TaskReport, Route, ...) and back: the GCS's and the leaders' nodes call these; tasks never do.
// Decoders throw std::runtime_error on a message that does not decode (the node drops it with a
// log line, comm/lockstep.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/app/task_messages.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/planner/grid/map_patch.hpp"
#include "swarm/planner/mapf/release_watch.hpp"
#include "swarm_msgs.h"

namespace swarm::app {

// A tick's clock as a task reads it (the leaders of a hand-made clock without them: the
// topology's first candidates).
task::Clock task_clock(const msgs::Clock& clock, const comm::Topology& topology);

msgs::TaskOrder order_msg(const task::Order& order, std::uint32_t phase);
// Throws on an unknown kind, or routes whose pick-up and drop steps do not fit them.
task::Order order_from(const msgs::TaskOrder& msg);

msgs::TaskReport report_msg(const task::Report& report, std::uint32_t phase);
task::Report report_from(const msgs::TaskReport& msg);

msgs::Route route_msg(const task::Route& route, std::uint32_t phase, comm::AgentId robot, std::uint32_t route_id);

// A release with the watch that may open the route further (planner/mapf/release_watch.hpp; the
// watched robots by agent id, the gates' releases in steps of the route as sent).
msgs::RouteRelease release_msg(comm::AgentId robot, std::uint32_t route_id, std::uint32_t release,
                               const planner::mapf::Watch& watch);
// Throws on a watch whose parts do not fit together.
planner::mapf::Watch watch_from(const msgs::RouteRelease& msg);


msgs::PlanReport plan_report_msg(const task::PlanTelemetry& plan, int group);

}  // namespace swarm::app
