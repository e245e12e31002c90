// Checks on a phase of metrics.json that several tasks' tests share.
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace swarm::test {

// The simulator counted no conflict and no blocked move in the phase (the traffic layer's promise).
inline void expect_no_conflict(const nlohmann::json& phase) {
  const auto& motion = phase.at("motion");
  EXPECT_EQ(motion["vertex_conflicts"], 0) << motion.dump();
  EXPECT_EQ(motion["edge_conflicts"], 0) << motion.dump();
  EXPECT_EQ(motion["blocked_moves"], 0) << motion.dump();
}

}  // namespace swarm::test
