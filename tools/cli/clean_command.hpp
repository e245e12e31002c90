// `swarm clean MAP`: plowing against Group-k (Jeon, Jo & Noh 2006) on one map, with the paper's
// time model (0.17 m/s, 90 degree turn 1 s, 180 degree turn 2 s; a cell is the map's resolution).
//
//   swarm clean clutter [--start X,Y] [--k 0.5] [--seed N] [--sweep columns|rows] [--margin M]
//                       [--out DIR]
//
// MAP: a built-in name (clutter, empty, open, ...), a map_server YAML or a MovingAI .map (10 cm
// cells). --start is a cell (x right, y up from the lower-left cell); default the paper's (1, 1)
// from the top left. Prints the groups of each stage with their complexities, the cleaning order,
// times to 50/80/90/100 % and Group-k's clean area when plowing is at 40/45/50 %; writes
// DIR/groups-basic.png, groups-released.png, groups.png (final, numbered in cleaning order),
// plow.png, group-k.png, coverage.png and summary.txt (DIR default runs/clean-<map>-<time>).
// Exit status: 0 done; 2 bad input (an unknown or unreadable map, a start outside the map or on a
// blocked cell, k outside (0, 1], a negative margin, an output directory that cannot be written).
// --margin M (not in the paper) widens every group's area by M cells on each side.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace swarm::tools {

struct CleanCommandOptions {
  std::string map;
  std::string start;  // "X,Y"; "" = the top-left start
  double k = 0.5;
  std::uint64_t seed = 1;
  std::string sweep = "columns";
  int margin = 0;  // GroupKConfig::area_margin (not in the paper)
  std::string out_dir;
};

int clean_command(const CleanCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
