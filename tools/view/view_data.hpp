// What `swarm view RUN_DIR` sends its page: a run record as one JSON document, for replay.
//
//   {"width", "height", "resolution", "origin": [x, y], "groups", "robots_per_group",
//    "names": [robot names by id], "scenario": {"map", "seed", "mission"}, "tick_ns",
//    "truth": "0120..." | null,                      // the map file's cells, row-major from y = 0
//    "maps":   [{"tick", "cells": "0120..."}],        // the GCS's fused map versions
//    "poses":  [{"tick", "phase", "xy": [x0, y0, x1, y1, ...]}],
//    "routes": [{"tick", "phase", "robot", "xy": [...], "region": cells}],  // region > 0: a cover division's
//    "plans":  [{"tick", "group", "frontiers": [x0, y0, ...], "segments": [x0, y0, ...]}],  // exploration
//    "phases": [{"tick", "phase", "task", "ended", "complete"}],
//    "tallies": [{"tick", "vertex", "edge", "blocked", "done", "total", "bytes": [per link class],
//                 "objects": [x, y, holder, ...]}],  // collect: each object's cell and carrier (-1 lying, -2 delivered)
//    "events": [{"tick", "kind": "lost" | "back" | "take_over", "robot", "group"}],
//    "links":  [link class names], "layout": mission_layout(world),
//    "end":    {"tick", "complete"} | null}
// Cells are one character each: 0 unknown, 1 free, 2 wall.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "swarm/config/scenario.hpp"
#include "swarm/planner/grid/grid.hpp"
#include "swarm/proto/run_record.pb.h"

namespace swarm::tools {

// Throws std::runtime_error when the record has no Header or a map version does not decode.
// `layout`: mission_layout of the run's world (an empty array when it cannot be loaded).
[[nodiscard]] nlohmann::json replay_json(const std::vector<record::Frame>& frames, const planner::OccupancyGrid* truth,
                                         const nlohmann::json& layout = nlohmann::json::array());

// What a mission fixes in advance for the page to draw: per collect phase, the objects where they
// lie at its start and each type's drop point:
//   [{"phase": 3, "task": "collect", "objects": [[x, y, type], ...], "destinations": [[x, y], ...]}]
[[nodiscard]] nlohmann::json mission_layout(const config::World& world);

// The link classes' names by comm::LinkClass, as tallies and /status give their bytes.
[[nodiscard]] std::vector<std::string> link_names();

// The live view's /status channel (JSON; not a Foxglove type, so Foxglove shows it as raw fields
// and plots them): {"tick", "phase", "task", "settling", "progress_done", "progress_total",
// "vertex_conflicts", "edge_conflicts", "blocked_moves", "lost_robots", "sent_bytes": {LINK: bytes},
// "objects": [x, y, holder, ...]} (collect: each object's cell and carrier, -1 lying, -2 delivered).
inline constexpr const char* kStatusSchemaName = "swarm.Status";
[[nodiscard]] nlohmann::json status_schema();
struct StatusFacts {
  std::uint32_t tick = 0;
  std::int64_t phase = -1;  // -1: not known yet
  std::string task;
  bool settling = false;
  std::uint32_t vertex_conflicts = 0, edge_conflicts = 0, blocked_moves = 0;
  std::uint32_t progress_done = 0, progress_total = 0;
  std::vector<std::uint64_t> sent_bytes;  // per comm::LinkClass
  int lost_robots = 0;
  std::vector<int> objects;  // collect: x, y, holder per object (msgs::RunTally.objects)
};
[[nodiscard]] nlohmann::json status_message(const StatusFacts& s);

// A /log line for what the clock said happened: "NAME lost at tick T", "NAME back at tick T",
// "NAME leads group G from tick T".
enum class TeamEvent { Lost, Back, TakeOver };
[[nodiscard]] std::string event_text(TeamEvent e, const std::string& robot, int group, std::uint32_t tick);

}  // namespace swarm::tools
