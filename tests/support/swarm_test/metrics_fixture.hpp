// metrics.json fixtures for tests of the tools that read it: a RunMetrics with the numbers a test
// cares about, written through the one writer (record/metrics.hpp), so fixtures follow the schema.
#pragma once

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "swarm/record/metrics.hpp"

namespace swarm::test {

// The phase called `name` in a metrics.json (the first such); throws if there is none.
inline const nlohmann::json& phase_named(const nlohmann::json& metrics, const std::string& name) {
  for (const auto& p : metrics.at("phases")) {
    if (p.at("name") == name) return p;
  }
  throw std::runtime_error("no phase " + name + " in " + metrics.at("phases").dump());
}

inline record::RunMetrics run_metrics(const std::string& map, const std::string& mode, std::uint64_t seed,
                                      std::uint32_t steps, std::uint32_t rounds, bool complete = true,
                                      double explored = 0.999) {
  record::RunMetrics m;
  m.scenario = "default";
  m.map = map;
  m.mode = mode;
  m.seed = seed;
  m.groups = 3;
  m.robots_per_group = 3;
  m.robots = 9;
  m.steps = steps;
  m.steps_to_99 = steps - 10;
  m.planning_rounds = rounds;
  m.explored_fraction = explored;
  m.complete = complete;
  m.ended = complete ? "complete" : "max_ticks (" + std::to_string(steps + 1) + ") reached";
  m.ticks_run = steps + 1;
  m.wall_seconds = 2.5;
  m.ticks_per_second = m.ticks_run / m.wall_seconds;
  m.traffic.by_topic["patch_up"].bytes = 1000;
  m.traffic.by_topic["patch_gcs"].bytes = 500;
  m.traffic.by_topic["sense"].bytes = 99999;
  m.traffic.total_messages = 10;
  m.traffic.total_bytes = 101499;
  m.phases.push_back({"explore", 0, complete ? std::optional<std::uint32_t>(steps) : std::nullopt, complete, {}, {}});
  return m;
}

}  // namespace swarm::test
