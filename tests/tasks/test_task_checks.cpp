// tasks::resolve_mission: each task's row checks its phase's settings at load, and every impossible
// value is one line naming its field, what was expected and what was given.
#include <gtest/gtest.h>

#include <string>

#include "swarm/config/scenario.hpp"
#include "swarm/tasks/mapf/mapf_settings.hpp"
#include "swarm/tasks/registry.hpp"
#include "swarm_test/ascii_grid.hpp"
#include "swarm_test/fake_swarm.hpp"

namespace swarm::tasks {
namespace {

std::string check_error(const std::string& text) {
  const auto truth = swarm::test::grid_from(
      {"############", "#..........#", "#..........#", "#..........#", "#..........#", "############"});
  config::World world;
  world.scenario = config::parse_scenario_text("groups: 1 robots_per_group: 2 " + text, "t");
  world.truth = truth;
  world.frame = config::MapFrame::of(truth);
  world.start = {5, 2};
  world.robot_cells = planner::start_cells(truth, world.start, 2);
  try {
    resolve_mission(world, "t.pbtxt");
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "(valid)";
}

TEST(TaskChecks, EachTaskChecksItsOwnSettings) {
  EXPECT_EQ(check_error("mission { phase { explore { traffic: false } } }"),
            std::string("t.pbtxt: field mission.phase[0].explore.traffic: must ") + swarm::tasks::kOnlyTheLayer +
                " (got false)");
  EXPECT_EQ(check_error("mission { phase { cover { traffic: false } } }"),
            std::string("t.pbtxt: field mission.phase[0].cover.traffic: must ") + swarm::tasks::kOnlyTheLayer +
                " (got false)");
  EXPECT_EQ(check_error("mission { phase { collect { traffic: false } } }"),
            std::string("t.pbtxt: field mission.phase[0].collect.traffic: must ") + swarm::tasks::kOnlyTheLayer +
                " (got false)");
  EXPECT_EQ(check_error("mission { phase { cover { traffic: true traffic_window_steps: 0 } } }"),
            "t.pbtxt: field mission.phase[0].cover.traffic_window_steps: must be >= 1 (got 0)");
  EXPECT_EQ(check_error("mission { phase { cover { route_balance_rounds: 257 } } }"),
            "t.pbtxt: field mission.phase[0].cover.route_balance_rounds: must be in [0, 256] (got 257)");
  EXPECT_EQ(check_error("mission { phase { cover { tour_seeds: 0 } } }"),
            "t.pbtxt: field mission.phase[0].cover.tour_seeds: must be in [1, 16] (got 0)");
  EXPECT_EQ(check_error("mission { phase { explore {} } phase { mapf { w: 0.5 time_limit_s: 0 } } }"),
            "t.pbtxt: field mission.phase[1].mapf.w: must be a finite number >= 1 (got 0.5)\n"
            "t.pbtxt: field mission.phase[1].mapf.time_limit_s: must be a number > 0, or inf for no limit (got 0)");
  EXPECT_EQ(check_error("mission { phase { collect { types: 2 objects { at { x: 0.3 y: 0.3 } type: 2 } } } }"),
            "t.pbtxt: field mission.phase[0].collect.objects[0].type: must be below collect.types (2) (got 2)");
  EXPECT_EQ(check_error("mission { phase { explore {} } phase { cover {} } phase { mapf {} } phase { collect {} } }"),
            "(valid)");
}

TEST(TaskChecks, ARendezvousPointLiesOnTheMap) {
  EXPECT_EQ(check_error("mission { phase { rendezvous { point { x: 9 y: 0.5 } } } }"),
            "t.pbtxt: field mission.phase[0].rendezvous.point: must lie inside the map, which spans x [0.00, 2.40) m "
            "and y [0.00, 1.20) m (got (9, 0.5))");
  EXPECT_EQ(check_error("mission { phase { rendezvous { point { x: 1 } home: true w: 0.5 } } }"),
            "t.pbtxt: field mission.phase[0].rendezvous.w: must be a finite number >= 1 (got 0.5)\n"
            "t.pbtxt: field mission.phase[0].rendezvous: must give point or home: true, not both (got both)\n"
            "t.pbtxt: field mission.phase[0].rendezvous.point: must give both x and y in metres (got only x)");
  EXPECT_EQ(check_error("mission { phase { rendezvous { point { x: 1.1 y: 0.5 } } } phase { rendezvous {} } }"),
            "(valid)");
}

// A plan driven by its timing needs every route on time: a re-sent one would set off late.
TEST(TaskChecks, ATimedPlanNeedsBoundedDelivery) {
  EXPECT_EQ(check_error("links { member_leader { loss: 0.2 } } mission { phase { mapf { execution: MAPF_EXECUTE_TIMED } } }"),
            "t.pbtxt: field mission.phase[0].mapf.execution: must be MAPF_EXECUTE_ADG or MAPF_EXECUTE_AUTO "
            "when a link loses messages, has a bandwidth cap or the run is in real time (a plan driven by its "
            "timing needs every route on time) (got MAPF_EXECUTE_TIMED)");
  // Delay and jitter are known in advance: the start tick of a timed plan allows for them.
  EXPECT_EQ(check_error("links { member_leader { delay_ticks: 3 jitter_ticks: 2 } } "
                        "mission { phase { mapf { execution: MAPF_EXECUTE_TIMED } } }"),
            "(valid)");
}

}  // namespace
}  // namespace swarm::tasks
