// validate(): every impossible value is an error that names its field, what was expected and
// what was given.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"

namespace {

namespace cfg = swarm::config;

std::string validate_error(const std::string& text) {
  const swarm::scenario::Scenario s = cfg::parse_scenario_text(text, "t.pbtxt");
  try {
    cfg::validate(s, "t.pbtxt");
  } catch (const cfg::ConfigError& e) {
    return e.what();
  }
  return "(valid)";
}

struct Impossible {
  const char* text;   // scenario text with one impossible value
  const char* error;  // the whole expected message
};

class ImpossibleValue : public ::testing::TestWithParam<Impossible> {};

TEST_P(ImpossibleValue, ReportsItsField) {
  EXPECT_EQ(validate_error(GetParam().text), GetParam().error);
}

INSTANTIATE_TEST_SUITE_P(
    Validate, ImpossibleValue,
    ::testing::Values(
        Impossible{"groups: 0", "t.pbtxt: field groups: must be >= 1 (got 0)"},
        Impossible{"robots_per_group: 0", "t.pbtxt: field robots_per_group: must be >= 1 (got 0)"},
        Impossible{"groups: 200 robots_per_group: 100",
                   "t.pbtxt: field groups x robots_per_group: must give at most 10000 robots "
                   "(got 200 x 100 = 20000)"},
        Impossible{"sensing_range_m: 0",
                   "t.pbtxt: field sensing_range_m: must be a finite number > 0 (got 0)"},
        Impossible{"sensing_range_m: -3",
                   "t.pbtxt: field sensing_range_m: must be a finite number > 0 (got -3)"},
        Impossible{"sensing_range_m: inf",
                   "t.pbtxt: field sensing_range_m: must be a finite number > 0 (got inf)"},
        Impossible{"lidar_beams: 3", "t.pbtxt: field lidar_beams: must be in [4, 4096] (got 3)"},
        Impossible{"lidar_beams: 5000",
                   "t.pbtxt: field lidar_beams: must be in [4, 4096] (got 5000)"},
        Impossible{"max_ticks: 0", "t.pbtxt: field max_ticks: must be >= 1 (got 0)"},
        Impossible{"tick_seconds: 0",
                   "t.pbtxt: field tick_seconds: must be a finite number > 0 (got 0)"},
        Impossible{"tick_seconds: nan",
                   "t.pbtxt: field tick_seconds: must be a finite number > 0 (got nan)"},
        Impossible{"tick_ms: 0", "t.pbtxt: field tick_ms: must be >= 1 (got 0)"},
        Impossible{"name: \"\"",
                   "t.pbtxt: field name: must be a non-empty name usable as a file name (no '/', "
                   "'\\' or control characters) (got \"\")"},
        Impossible{"name: \"a/b\"",
                   "t.pbtxt: field name: must be a non-empty name usable as a file name (no '/', "
                   "'\\' or control characters) (got \"a/b\")"},
        Impossible{"map: \"\"", "t.pbtxt: field map: must name a built-in map or a map YAML file "
                                "(got \"\")"},
        Impossible{"start { x: 1 }",
                   "t.pbtxt: field start: must give both x and y in metres, e.g. start { x: 10.1 "
                   "y: 10.1 } (got only x)"},
        Impossible{"start { x: 1 y: -inf }",
                   "t.pbtxt: field start.y: must be a finite number (got -inf)"},
        Impossible{"explore { replan_threshold_steps: 0 }",
                   "t.pbtxt: field explore.replan_threshold_steps: must be >= 1 (got 0)"},
        Impossible{"explore { dbscan_eps_cells: 0 }",
                   "t.pbtxt: field explore.dbscan_eps_cells: must be a finite number > 0 (got 0)"},
        Impossible{"explore { dbscan_min_points: 0 }",
                   "t.pbtxt: field explore.dbscan_min_points: must be in [1, 2147483647] (got 0)"},
        Impossible{"explore { small_segment_max_cells: 3000000000 }",
                   "t.pbtxt: field explore.small_segment_max_cells: must be in [0, 2147483647] "
                   "(got 3000000000)"},
        Impossible{"explore { small_segment_radius_cells: -1 }",
                   "t.pbtxt: field explore.small_segment_radius_cells: must be a finite number >= "
                   "0 (got -1)"},
        Impossible{"explore { kmeans_max_iterations: 0 }",
                   "t.pbtxt: field explore.kmeans_max_iterations: must be in [1, 2147483647] "
                   "(got 0)"},
        Impossible{"links { member_leader { loss: 1 } }",
                   "t.pbtxt: field links.member_leader.loss: must be a probability in [0, 1) "
                   "(got 1)"},
        Impossible{"links { sim_robot { loss: -0.1 } }",
                   "t.pbtxt: field links.sim_robot.loss: must be a probability in [0, 1) "
                   "(got -0.1)"},
        Impossible{"links { leader_gcs { bandwidth_bytes_per_s: -5 } }",
                   "t.pbtxt: field links.leader_gcs.bandwidth_bytes_per_s: must be a finite "
                   "number >= 0 (got -5)"},
        Impossible{"links { leader_gcs { delay_ms: -1 } }",
                   "t.pbtxt: field links.leader_gcs.delay_ms: must be a finite number >= 0 "
                   "(got -1)"},
        Impossible{"faults { agent: \"member-3-1\" kill_at_tick: 5 }",
                   "t.pbtxt: field faults[0].agent: must name a robot of this run: leader-G (G < 3) or "
                   "member-G-I (1 <= I < 3), or gcs (got \"member-3-1\")"},
        Impossible{"faults { agent: \"gcs\" kill_at_tick: 5 }",
                   "t.pbtxt: field faults[0]: must kill the GCS with a restart: kill_at_tick and "
                   "restart_after_seconds (--kill gcs@T+S) (got a kill without restart_after_seconds)"},
        Impossible{"faults { agent: \"member-0-1\" kill_at_tick: 5 restart_after_seconds: 2 }",
                   "t.pbtxt: field faults[0].restart_after_seconds: must be given for the GCS only (a robot's "
                   "process is not restarted) (got \"member-0-1\")"},
        Impossible{"leader_standbys: 0 faults { agent: \"leader-1\" kill_at_tick: 5 }",
                   "t.pbtxt: field faults[0].agent: must be a member to be killed: with no standby leader "
                   "(leader_standbys 0, or a group of one robot) a group cannot lose its leader (got leader-1)"},
        Impossible{"leader_standbys: 3",
                   "t.pbtxt: field leader_standbys: must be at most robots_per_group - 1 = 2 (got 3)"},
        Impossible{"faults { agent: \"leader-1\" }",
                   "t.pbtxt: field faults[0]: must say kill_at_tick, cut_from_tick and cut_to_tick, or "
                   "freeze_at_tick and freeze_seconds (got none of them)"},
        Impossible{"faults { agent: \"leader-1\" cut_from_tick: 9 cut_to_tick: 9 }",
                   "t.pbtxt: field faults[0]: must give cut_from_tick < cut_to_tick (got 9 .. 9)"},
        Impossible{"faults { agent: \"leader-1\" freeze_at_tick: 9 freeze_seconds: 30 }",
                   "t.pbtxt: field faults[0].freeze_seconds: must be more than 0 and less than 30 (the "
                   "DDS participant lease) (got 30)"},
        Impossible{"faults { agent: \"member-0-2\" freeze_at_tick: 9 }",
                   "t.pbtxt: field faults[0].freeze_seconds: must be more than 0 and less than 30 (the "
                   "DDS participant lease) (got 0)"},
        // The same robot killed twice: the last kill would silently win.
        Impossible{"faults { agent: \"member-0-1\" kill_at_tick: 5 } faults { agent: \"member-0-1\" kill_at_tick: 8 }",
                   "t.pbtxt: field faults[1].agent: must be killed once: faults[0] already kills it (got "
                   "\"member-0-1\")"},
        // A fault after the last tick never happens.
        Impossible{"max_ticks: 20 faults { agent: \"member-0-1\" kill_at_tick: 100000 }",
                   "t.pbtxt: field faults[0].kill_at_tick: must be below max_ticks (20), or the run ends first "
                   "(got 100000)"},
        // A footprint past any map's side would list its disc's offsets for ever; one past int acted as 0.
        Impossible{"footprint_radius: 4000000000",
                   "t.pbtxt: field footprint_radius: must be in [0, 64] (got 4000000000)"},
        Impossible{"map_resolution_m: 1e308",
                   "t.pbtxt: field map_resolution_m: must be a number in [0.001, 1000] (got 1e+308)"},
        Impossible{"map_resolution_m: 1e-300",
                   "t.pbtxt: field map_resolution_m: must be a number in [0.001, 1000] (got 1e-300)"},
        Impossible{"links { leader_gcs { delay_ms: nan } }",
                   "t.pbtxt: field links.leader_gcs.delay_ms: must be a finite number >= 0 (got nan)"}));

TEST(Validate, ListsEveryProblemOnItsOwnLine) {
  EXPECT_EQ(validate_error("groups: 0 explore { replan_threshold_steps: 0 }"),
            "t.pbtxt: field groups: must be >= 1 (got 0)\n"
            "t.pbtxt: field explore.replan_threshold_steps: must be >= 1 (got 0)");
}

TEST(Validate, AcceptsTheEdgesOfEveryRange) {
  EXPECT_EQ(validate_error(R"(
    groups: 1 robots_per_group: 1 sensing_range_m: 0.01 lidar_beams: 4 max_ticks: 1
    tick_seconds: 1e-3 tick_ms: 1 seed: 0
    explore { replan_threshold_steps: 1 global_map_delay_rounds: 0 dbscan_min_points: 1
              small_segment_max_cells: 0 small_segment_radius_cells: 0 kmeans_max_iterations: 1 }
    links { sim_robot { loss: 0 bandwidth_bytes_per_s: 0 delay_ms: 0 }
            member_leader { loss: 0.999 } }
  )"),
            "(valid)");
  EXPECT_EQ(validate_error(R"(
    faults { agent: "member-2-2" kill_at_tick: 1 }
    faults { agent: "leader-0" cut_from_tick: 0 cut_to_tick: 1 }
    faults { agent: "leader-2" freeze_at_tick: 1 freeze_seconds: 29.9 }
  )"),
            "(valid)");
  EXPECT_EQ(validate_error("lidar_beams: 4096 groups: 100 robots_per_group: 100"), "(valid)");
}

}  // namespace
