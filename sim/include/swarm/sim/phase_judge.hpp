// The simulator's side of the task seam: a task's ground-truth judge (tasks/<task>/, made for each
// phase through the task registry, tasks/registry.hpp).
//
// The simulator keeps what every phase has (its start, the moves and conflicts since, the run's
// steps to 99 % explored) and hands it over as PhaseFacts; the judge keeps what only its task
// measures (covered cells, delivered objects, their curves), from the World it is given:
//   start(world, tick)       the phase begins: set the world up (coverage targets, objects)
//   after_tick(world, k)     every tick of the phase, once the robots moved and scanned
//   last_tick(world, k)      the run ends in this phase at tick k
//   judge(world, facts)      its numbers: merged into metrics.json phases[i].task; among them
//                            record::kGroundTruthDone, whether the ground truth says the work is
//                            done (null: it cannot tell), which the phase's completion needs
//   progress(world)          the work done so far, for watchers (msgs::RunTally, every tick)
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarm/record/metrics.hpp"
#include "swarm/sim/world.hpp"

namespace swarm::sim {

// What the simulator knows of any phase, from ground truth.
struct PhaseFacts {
  std::uint32_t start_tick = 0;
  std::optional<std::uint32_t> first_move_tick;  // the first and last tick a robot moved in it
  std::optional<std::uint32_t> last_move_tick;
  record::MotionNumbers motion;                  // since the phase began
  std::uint64_t diagonal_moves = 0;              // since the phase began
  std::optional<std::uint32_t> steps_to_99;      // the run's: the tick 99 % of the map was explored
  std::vector<bool> alive;                       // per robot id, when judged
};

// A phase's work so far in its task's unit (cells, robots, objects); total 0 = not counted.
// Collect also says where its objects are (World::object_states), so watchers see them picked.
struct Progress {
  std::uint64_t done = 0;
  std::uint64_t total = 0;
  std::vector<int> objects;
};

class PhaseJudge {
 public:
  virtual ~PhaseJudge() = default;
  [[nodiscard]] virtual Progress progress(const World&) const { return {}; }
  virtual void start(World&, std::uint32_t /*tick*/) {}
  virtual void after_tick(const World&, std::uint32_t /*k*/) {}
  virtual void last_tick(const World&, std::uint32_t /*k*/) {}
  [[nodiscard]] virtual nlohmann::json judge(const World& world, const PhaseFacts& facts) const = 0;
};

}  // namespace swarm::sim
