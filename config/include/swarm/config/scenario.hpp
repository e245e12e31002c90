// Scenario files: the one file that drives every process of a run (docs/design.md, "One scenario file
// drives every process").
//
// A scenario is a `swarm.scenario.Scenario` message (idl/scenario.proto) in protobuf text format;
// every field is optional and defaults to the paper's Table 1 (docs/papers.md section 1). Reading one
// takes two steps, both at the process edge:
//   1. load_scenario: parse + validate(). Every impossible value (a count of 0, a negative range,
//      a loss probability of 1, ...) is a ConfigError naming the file, the field, what was
//      expected and what was given.
//   2. resolve_world: find and load the map (a built-in name or a ROS map_server YAML path), pick
//      the start (scenario.start, or the free cell nearest the map centre) and every robot's start
//      cell. Problems that need the map (start in a wall, start sealed off) are ConfigErrors too.
//   3. tasks::resolve_mission (tasks/registry.hpp): each phase's task checks its settings and
//      resolves what they fix in advance (World::phase_data).
// Callers print ConfigError::what() and exit with status 2.
//
//   namespace cfg = swarm::config;
//   try {
//     swarm::scenario::Scenario s = cfg::load_scenario(path);
//     s.set_groups(flag_groups);                       // a flag overrides one field...
//     cfg::validate(s, path + " (with flags)");        // ...so validate again
//     cfg::World w = cfg::resolve_world(s, std::filesystem::path(path).parent_path().string());
//     // w.truth, w.robot_cells[group * robots_per_group + index] (index 0 = the group's leader)
//   } catch (const cfg::ConfigError& e) {
//     std::cerr << e.what() << "\n";
//     return 2;
//   }
//
// Units: metres (map frame) for positions and ranges, cells for grid indices, ticks for steps.
// All functions are thread-safe (no shared state; data_dir() reads the environment).
#pragma once

#include <any>

#include <stdexcept>
#include <string>
#include <vector>

#include "swarm/config/task_config.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::config {

// A scenario or map that cannot be used. what() is a complete message (one line per problem)
// that names the file and tells the fix.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// ---- Scenario files --------------------------------------------------------------------------

// Reads and parses `path`, then validate()s it. Parse errors read
//   "scenarios/x.pbtxt:3:19: Expected integer, got: abc"
// (line and column 1-based); unknown field names suggest the nearest known one.
[[nodiscard]] swarm::scenario::Scenario load_scenario(const std::string& path);

// Parses protobuf text format only (no validate()); `source_name` prefixes error messages.
[[nodiscard]] swarm::scenario::Scenario parse_scenario_text(const std::string& text,
                                                            const std::string& source_name);

// Throws ConfigError listing every impossible value, one line each, e.g.
//   "scenarios/x.pbtxt: field explore.replan_threshold_steps: must be >= 1 (got 0)"
// Checks only what needs no map; resolve_world checks the rest. A phase's own settings are its
// task's to check (tasks::check_mission, each registry row's `check`).
void validate(const swarm::scenario::Scenario& scenario, const std::string& source);

// Protobuf text format of every set field (unset fields keep their defaults when read back):
// parse_scenario_text(to_text(s), ...) equals s.
[[nodiscard]] std::string to_text(const swarm::scenario::Scenario& scenario);

// "group-frontier" | "baseline" | "ideal" (case and '-'/'_' do not matter); otherwise a
// ConfigError listing the accepted names.
[[nodiscard]] swarm::scenario::Mode parse_mode(const std::string& name);
// The inverse of parse_mode: "group-frontier", "baseline" or "ideal".
[[nodiscard]] std::string mode_name(swarm::scenario::Mode mode);

// ---- Missions ----------------------------------------------------------------------------------

// A phase's task is its field of scenario.proto's Phase `task` oneof; the field's name is the
// task's name everywhere ("explore", "cover", ...: --mission, metrics.json, logs). Read from the
// schema, so a task added there is known here without a change.
// The name of the phase's task (the oneof's first, exploration, for a phase that names none:
// validate() refuses such a phase in a scenario).
[[nodiscard]] std::string task_name(const swarm::scenario::Phase& phase);
// The phase's field in that oneof (the first for a phase that names none): its options say what
// the task needs of the run (idl/scenario.proto `learns_map`).
[[nodiscard]] const google::protobuf::FieldDescriptor& task_field(const swarm::scenario::Phase& phase);
// Every task name, in the oneof's order.
[[nodiscard]] std::vector<std::string> task_names();

// The phases a scenario's mission runs, in order, each with its full configuration: the mission's
// phases, or (no mission) the oneof's first task alone (exploration). A top-level field of the
// scenario of a task's settings type gives that task's defaults: a phase's own settings are merged
// over it (so the top-level `explore` and `--mode` apply to every explore phase).
[[nodiscard]] std::vector<swarm::scenario::Phase> mission_phases(const swarm::scenario::Scenario& scenario);
// The standby leaders per group the run really has: leader_standbys, at most robots_per_group - 1.
[[nodiscard]] int leader_standbys(const swarm::scenario::Scenario& scenario);

// `--mission explore,cover`: replaces the scenario's mission by these phases with default settings.
// Throws ConfigError naming an unknown task.
void set_mission(swarm::scenario::Scenario& scenario, const std::vector<std::string>& tasks);

// ---- Data files and the world ----------------------------------------------------------------

// The folder holding maps/ and scenarios/: $SWARM_DATA_DIR if set and non-empty, else the source
// tree this library was built from.
[[nodiscard]] std::string data_dir();

// The name of a swarm-member process running robots first..last of `group` (its log, its
// certificate): "member-G-I" for one robot, "members-G-F-L" for several.
[[nodiscard]] std::string member_process_name(int group, int first, int last);

// The Fast DDS XML profile every process of a run loads (and the run's discovery server):
// $SWARM_DDS_PROFILE if set and non-empty, else data_dir()/deploy/fastdds_loopback.xml.
[[nodiscard]] std::string dds_profile_path();

// The built-in maps, in maps/ of data_dir(): open, maze1, maze2, small, clutter, empty (Group-k's
// cleaning rooms), warehouse-5x8 (the MAPF paper's world, one-cell aisles), terminal, rectangle
// (the DARP comparisons' complex and near-empty maps).
[[nodiscard]] std::vector<std::string> builtin_map_names();

// A built-in name gives data_dir()/maps/NAME.yaml; anything else is a path to a map_server YAML
// file or a MovingAI `.map`, relative paths taken from `scenario_dir` (the scenario file's folder;
// "" = the working directory). Throws ConfigError if neither exists.
[[nodiscard]] std::string resolve_map_path(const std::string& map, const std::string& scenario_dir);
// Is the file a MovingAI benchmark map (by its `.map` extension)? It is read with the scenario's
// map_resolution_m; any other file as a map_server YAML.
[[nodiscard]] bool is_movingai_map(const std::string& path);

// The largest map side a run accepts: cells travel as 16-bit signed coordinates.
inline constexpr int kMaxMapSide = 32767;

// The map's extent and placement: the area to work in, which every role knows. Its cells only the
// simulator holds, and a role only when the scenario gives the robots the map (map_given).
struct MapFrame {
  int width = 0;
  int height = 0;
  double resolution = 0.2;
  double origin_x = 0.0;
  double origin_y = 0.0;
  std::size_t cells() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  // A grid of this frame with every cell Unknown: where a role's own map starts.
  swarm::planner::OccupancyGrid unknown() const { return {width, height, resolution, origin_x, origin_y}; }
  // Does the point (metres in the map frame) lie on the map?
  bool contains(double x, double y) const {
    return x >= origin_x && y >= origin_y && x < origin_x + width * resolution && y < origin_y + height * resolution;
  }
  // What the map spans, for messages: "x [0.00, 8.00) m and y [0.00, 8.00) m".
  std::string extent_text() const;
  static MapFrame of(const swarm::planner::OccupancyGrid& g) {
    return {g.width(), g.height(), g.resolution(), g.origin_x(), g.origin_y()};
  }
};

// Everything a run needs that follows from the scenario and its map. Only the simulator (and
// offline tools) may hold `truth`: agents learn the world from their scans.
struct World {
  swarm::scenario::Scenario scenario;  // validated; `start` set to the start actually used
  swarm::planner::OccupancyGrid truth;  // the map file's cells
  MapFrame frame;                       // truth's extent
  swarm::planner::Cell start;           // the drop-off cell every robot starts around
  // groups * robots_per_group distinct Free cells around `start`; robot id = group *
  // robots_per_group + index, index 0 being the group's leader.
  std::vector<swarm::planner::Cell> robot_cells;
  std::string map_path;  // the YAML file read
  // Per phase of mission_phases(scenario): what its task fixes in advance from the scenario and the
  // map (a mapf phase's goals, a collect phase's objects), resolved and checked once at load by the
  // task's registry row (tasks::resolve_mission), so every process agrees without reading the map
  // itself; empty for a task that fixes nothing.
  std::vector<std::any> phase_data;
};

// validate()s `scenario`, loads its map, picks the start and the robots' cells (see World).
// `source` names the scenario in messages (default: "scenario 'NAME'"). Throws ConfigError when
// the map cannot be read, or the start lies outside the map, in a wall or unknown cell, or where
// fewer free cells are reachable than there are robots, or the map has a side longer than
// kMaxMapSide; the message suggests a start that works.
[[nodiscard]] World resolve_world(const swarm::scenario::Scenario& scenario,
                                  const std::string& scenario_dir, const std::string& source = {});

}  // namespace swarm::config
