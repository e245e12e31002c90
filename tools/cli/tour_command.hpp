// `swarm tour FILE`: plan a collection tour (Kim & Lee 2025, planner/tours/tour.hpp) for a tour file
// (tour_file.hpp), print the paper's per-run table (length and rotation of each variant) and
// write a picture per variant, the table and the legs as JSON.
//
//   swarm tour scenarios/tour/scenario1.tour [--variants nna,distance,distance-angle]
//              [--search ga|ga-polished|exact] [--seed N] [--generations G]
//              [--skip-unreachable] [--out DIR]
//
// Writes DIR/table.txt, DIR/tour.json and DIR/tour-<variant>.png (DIR default
// runs/tour-<file stem>-<time>). Exit status: 0 done; 2 bad input (the file's problems name its
// line; an unreachable object unless --skip-unreachable, which plans without it and says so; an
// unknown variant or search; G < 1; an output directory that cannot be written).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace swarm::tools {

struct TourCommandOptions {
  std::string file;
  std::vector<std::string> variants;  // empty = all three
  std::string search = "ga";
  std::uint64_t seed = 1;
  int generations = 1000;
  bool skip_unreachable = false;
  std::string out_dir;
};

int tour_command(const TourCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
