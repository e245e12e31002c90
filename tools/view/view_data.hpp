// What `swarm view RUN_DIR` sends its page: a run record as one JSON document, for replay.
//
//   {"width", "height", "resolution", "origin": [x, y], "groups", "robots_per_group",
//    "names": [robot names by id], "scenario": {"map", "seed", "mission"},
//    "truth": "0120..." | null,                      // the map file's cells, row-major from y = 0
//    "maps":   [{"tick", "cells": "0120..."}],        // the GCS's fused map versions
//    "poses":  [{"tick", "phase", "xy": [x0, y0, x1, y1, ...]}],
//    "routes": [{"tick", "phase", "robot", "xy": [...]}],
//    "plans":  [{"tick", "group", "frontiers": [x0, y0, ...]}],   // exploration: a group's frontiers
//    "phases": [{"tick", "phase", "task", "ended", "complete"}],
//    "end":    {"tick", "complete"} | null}
// Cells are one character each: 0 unknown, 1 free, 2 wall.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/proto/run_record.pb.h"

namespace swarm::tools {

// Throws std::runtime_error when the record has no Header or a map version does not decode.
[[nodiscard]] nlohmann::json replay_json(const std::vector<record::Frame>& frames, const planner::OccupancyGrid* truth);

}  // namespace swarm::tools
