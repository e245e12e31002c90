// swarm-sim's node: the World driven by the lockstep clock. Each tick it applies the motion
// commands due, moves the robots, sends each robot its scan (with the progress of its route),
// publishes the clock, and waits for every agent; it stops the run when the GCS declares the
// mission complete or at max_ticks.
//
//   SimNode node(clock, setup, tasks::sim_part);  // each phase's motion model and judge

//   node.run();                       // the whole run (swarm-sim's main)
// or, one tick at a time (unit tests on a FakeBus, with the agents stepped in between):
//   clock.wait_ready();
//   for (k = 0; node.begin_tick(k), step the agents, !node.end_tick(k); ++k) {}
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/record/metrics.hpp"
#include "swarm/sim/phase_judge.hpp"
#include "swarm/sim/world.hpp"

namespace swarm::sim {

// A phase's part in the simulator: how its robots move, and its ground-truth judge.
struct PhaseSim {
  planner::MotionModel motion;
  std::unique_ptr<PhaseJudge> judge;
};
// Makes the simulator's part of phase `index` of the mission (tasks/registry.hpp: tasks::sim_part).
using PhaseSimFactory =
    std::function<PhaseSim(const swarm::scenario::Phase& phase, const app::RoleSetup& setup, std::uint32_t index)>;

class SimNode {
 public:
  SimNode(comm::LockstepClock& clock, const app::RoleSetup& setup, PhaseSimFactory phase_sim);
  // The whole run; returns the last tick.
  std::uint32_t run();
  // Tick k up to the clock: motion, scans, Clock(k).
  void begin_tick(std::uint32_t k);
  // Waits for every agent to finish tick k; true when the run stopped (the stop is published).
  bool end_tick(std::uint32_t k);
  std::string report_json() const;
  const World& world() const { return world_; }

 private:
  std::vector<msgs::RobotState> states() const;
  msgs::RunTally tally() const;  // for watchers: conflicts, blocked moves and the phase's progress
  // Phase `index` of the mission begins at `tick`: the motion model of its task, and its judge.
  void start_phase(std::uint32_t index, std::uint32_t tick);
  // The ground-truth numbers of the phase in force, frozen when the next one starts.
  void judge_phase();
  struct PhaseLog;
  [[nodiscard]] nlohmann::json judge_of(const PhaseLog& p, record::MotionNumbers& motion) const;
  // What robots did since `start` (per-robot counts then; empty = the start of the run).
  // The robots' motion since `start` (a phase's start: the current phase's, as World::mark() was
  // called there), or over the whole run (start empty).
  record::MotionNumbers motion_since(const std::vector<MotionCounts>& start, const ConflictEvents& events) const;

  comm::LockstepClock& clock_;
  World world_;
  std::uint32_t max_ticks_;
  std::chrono::milliseconds pace_while_gcs_lost_{0};  // a GCS restart is scheduled: see the constructor
  std::vector<comm::Mailbox::Outlet<msgs::Sense>*> sense_;
  std::optional<std::uint32_t> steps_to_99_;
  std::vector<std::pair<std::uint32_t, double>> curve_;  // (tick, explored fraction)
  std::vector<bool> alive_;
  const app::RoleSetup& setup_;
  PhaseSimFactory phase_sim_;
  std::vector<float> ranges_;

  // The mission's phases as the GCS announces them, and what the simulator judged in each.
  std::vector<swarm::scenario::Phase> mission_;
  std::optional<std::uint32_t> next_phase_;
  struct PhaseLog {
    std::uint32_t index = 0;
    std::string task;
    std::uint32_t start_tick = 0;
    std::vector<MotionCounts> counts_at_start;
    ConflictEvents events_at_start;
    std::uint64_t diagonals_at_start = 0;
    std::unique_ptr<PhaseJudge> judge_part;            // the task's own measures
    std::optional<std::uint32_t> first_move_tick;        // the first and last tick a robot moved
    std::optional<std::uint32_t> last_move_tick;         // in the phase
    nlohmann::json judge = nlohmann::json::object();
    record::MotionNumbers motion;
    bool judged = false;
  };
  std::vector<PhaseLog> phases_;
  std::uint32_t last_tick_ = 0;
  std::uint32_t tick_ = 0;  // the tick being begun: a command for a later one is held (World::command_at)
  bool complete_ = false;
};

}  // namespace swarm::sim
