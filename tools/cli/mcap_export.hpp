// A run record (RUN_DIR/run.pb) as an MCAP file that Foxglove and Lichtblick open: the robots,
// maps, routes, LiDAR and the phases' log, in Foxglove's schemas, JSON encoded
// (record/mcap_writer.hpp writes the file).
//
// Channels (frame "map": metres, the map's origin; each robot's frame "leader-G" / "member-G-I"):
//   /map             foxglove.Grid            the GCS's fused map, at each version the record holds
//   /map/truth       foxglove.Grid            the map file's cells, once (with the world)
//   /tf              foxglove.FrameTransforms every robot's frame at every recorded tick
//   /robots          foxglove.SceneUpdate     one cube and label per robot, in its group's colour,
//                                             locked to its frame (sent once; /tf moves them)
//   /route/ROBOT     foxglove.PosesInFrame    each route a task gave the robot (cover, mapf, collect)
//   /scan/ROBOT      foxglove.LaserScan       the robot's LiDAR at each tick, cast on the map file
//                                             as the simulator casts it (with the world)
//   /log             foxglove.Log             phases starting and ending, and the run's end
// Metadata "scenario": the seed, map, team, mission, tick length and the whole scenario as text.
// Log times are the ticks at the scenario's tick length (tick 0 = 0 ns).
//
//   McapExport e = export_mcap(frames, &world, "run.mcap");   // world: nullptr without a map
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"
#include "swarm/proto/run_record.pb.h"

namespace swarm::tools {

struct McapExport {
  std::uint64_t messages = 0;
  std::uint64_t bytes = 0;
  std::map<std::string, std::uint64_t> per_topic;  // "/scan/..." and "/route/..." summed as one each
};

// Throws std::runtime_error when the file cannot be written, or the record has no Header.
McapExport export_mcap(const std::vector<record::Frame>& frames, const config::World* world, const std::string& path);

}  // namespace swarm::tools
