// Bytes per second per link class over a run, from the clock's tallies in its record
// (record::Tally.sent_bytes: every agent's bytes sent so far, per comm::LinkClass): the bursts at
// round starts and per phase that a total hides. `swarm run` writes RUN_DIR/traffic.csv and
// RUN_DIR/traffic.png from it.
//
// The simulator's link to the robots (sim_robot) carries what a robot's own sensors give it: in a
// deployment it stays on the robot. It is kept apart and labelled so in the CSV
// (sim_robot_on_robot_bytes_per_s) and in the picture (its own panel).
//
//   const TrafficOverTime t = traffic_over_time(frames);   // 1 s bins of simulated time
//   write_traffic_csv(t, "traffic.csv");                  // second, member_leader_bytes_per_s, ...
//   write_traffic_png(t, "traffic.png");
#pragma once

#include <string>
#include <vector>

#include "swarm/proto/run_record.pb.h"

namespace swarm::tools {

struct TrafficOverTime {
  double bin_seconds = 1.0;
  std::vector<double> seconds;                    // each bin's end, in simulated seconds
  std::vector<std::string> links;                 // comm::LinkClass order
  std::vector<std::vector<double>> bytes_per_s;   // [link][bin]
  std::vector<std::pair<double, std::string>> phase_starts;  // (second, task)
};

// Throws std::runtime_error when the record has no Header, or no Poses frame with a tally (a
// record written before tallies existed).
[[nodiscard]] TrafficOverTime traffic_over_time(const std::vector<record::Frame>& frames, double bin_seconds = 1.0);

// The CSV: "second" and one column per link class, in bytes per second, the on-robot link last.
void write_traffic_csv(const TrafficOverTime& t, const std::string& path);
// Two panels: the radio links (member_leader, leader_gcs, telemetry, control) and, apart, the
// simulator's sensing of the robots; the phases' starts marked. Throws when it cannot be written.
void write_traffic_png(const TrafficOverTime& t, const std::string& path);
// RUN_DIR/traffic.csv and RUN_DIR/traffic.png of a run's record (`swarm run` and every run of an
// experiment write them). Throws as the three above do.
void write_traffic_files(const std::vector<record::Frame>& frames, const std::string& run_dir);

}  // namespace swarm::tools
