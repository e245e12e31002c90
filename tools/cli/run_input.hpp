// A run directory given to a command that reads it (`swarm export`, `swarm view`): its record,
// checked, and the world it was made in.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"
#include "swarm/proto/run_record.pb.h"

namespace swarm::tools {

// The whole record of RUN_DIR/run.pb, starting with its Header; nullopt, with a message on `err`
// prefixed by `me`, when the directory is not a run, or the record is truncated or damaged.
std::optional<std::vector<record::Frame>> read_run(const std::string& run_dir, const std::string& me, std::ostream& err);

// The world a record was made in (its map file's cells, for ground truth and LiDAR): the
// scenario's map taken from the run directory (a relative path), else from the working directory.
// nullopt, with `why` set, when neither place has the map.
std::optional<config::World> world_of_record(const record::Header& header, const std::string& run_dir, std::string& why);

}  // namespace swarm::tools
