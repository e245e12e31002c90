// `swarm experiment mission`: the chained mission (explore, cover, mapf, collect by default) live
// on every built-in map, over seeds, team sizes and link settings, each run a `swarm run` (every
// role its own process over real DDS). Per phase it tables, plots and saves what says whether the
// robots moved well: the phase's ticks, their ratio to a lower bound (cover: ⌈cells / robots⌉,
// the cells being the simulator's reachable targets; mapf: the makespan driven over the planned
// one, as the plan's own bound), the simulator's vertex and edge conflicts and blocked moves, the
// longest run of ticks a robot was held up by another, and the robots that never moved.
//
// Link settings: base (exact links), delay (member<->leader 3 ± 2 ticks), loss (5 % on every
// link). Written into --out DIR (default runs/experiment-mission-<time>): table.txt, results.csv
// (one row per run and phase), results.json, mission.png (per phase, ticks by map and setting,
// mean ± std over seeds). Exit status 0 when the runs were made (an incomplete run is a table
// entry), 2 on bad input, 1 when the outputs cannot be written.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace swarm::tools {

struct MissionExperimentOptions {
  std::vector<std::string> maps;     // empty: every built-in map
  std::vector<std::string> mission = {"explore", "cover", "mapf", "collect"};
  std::vector<std::string> links = {"base", "delay", "loss"};
  std::vector<std::string> robots = {"3x3"};  // GROUPSxROBOTS_PER_GROUP
  std::int64_t seeds = 2;  // seeds 1..N per map, setting and team
  std::int64_t jobs = 2;   // runs at once
  long timeout_s = 900;    // per run
  bool quick = false;      // small, seed 1, base links only (a smoke test)
  std::string out_dir;
};

int mission_experiment(const MissionExperimentOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
