// swarm-gcs's node: the mission's phase machine (gcs_task.hpp) wired to its topics, plus the
// run's outputs. It fuses the leaders' map patches, runs each phase's GcsTask (exploration's
// planning rounds, coverage's division, ...), starts the next phase when one is done, declares the
// mission complete after the last, shows progress, records the run (run.pb) and, once the
// simulator stops the run, gathers every agent's report into metrics.json.
//
// Phase boundaries: the next phase plans from where the robots stand, so it starts only once they
// stand still. When a phase is done the node announces the next with `settle` (PhaseStart): each
// leader stops its living robots and, once the simulator has confirmed every stop, reports so
// (TaskReport Held, values [0]; leader/leader_node.hpp). When every group with a living leader
// has, the node announces the phase again without `settle` and starts its task; the simulator
// judges the new phase from then on, so the robots' last moves count in the phase that made them.
//
// Restart (issue 11): the GCS keeps what it needs to resume as the run goes: its input journal
// (journal_path(): every clock and every message its handlers got, comm/journal.hpp) and the wall
// time of tick 0. A process started with --resume (swarm run --kill gcs@T+S starts one S seconds
// after the kill) replays the journal through the same node (lockstep: the same inputs give the
// same state; its sends are muted, and run.pb, rewritten from the start, comes out the same as
// the dead process's), then rejoins the run at the tick the simulator admits it (comm/lockstep.hpp
// "Restart"). What it did not hear meanwhile, the leaders send it again when they see it back
// (Clock.counted_from: the whole group map, and each task's state, GroupTask::gcs_back).
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "swarm/comm/leadership.hpp"
#include "swarm/comm/lockstep.hpp"
#include "swarm/app/role.hpp"
#include "swarm/app/task_wire.hpp"
#include "swarm/gcs/gcs_task.hpp"
#include "swarm/gcs/fused_map.hpp"
#include "swarm/gcs/outages.hpp"
#include "swarm/gcs/progress.hpp"
#include "swarm/planner/grid/map_patch.hpp"
#include "swarm/record/record.hpp"

namespace swarm::gcs {

class GcsNode {
 public:
  // make_task: each phase's task (tasks::gcs_task, the task registry).
  GcsNode(comm::LockstepAgent& agent, const app::RoleSetup& setup, const std::string& run_dir,
          Progress::Style progress, const GcsTaskFactory& make_task);
  // One tick; returns true once the mission is over: complete, or a phase given up.
  bool step(const msgs::Clock& clock);
  // A restarted process, after its journal was replayed: `restarts` are every restart's replay so
  // far (this one last), for metrics.json.
  void resumed(std::vector<comm::JournalRestart> restarts);
  // After the run stopped: waits up to `wait` for the living agents' reports, writes metrics.json
  // and closes run.pb. Throws std::runtime_error naming what is missing when the simulator's
  // report (the ground truth the run is judged by) did not come or lacks a key.
  void finish(std::chrono::milliseconds wait = std::chrono::seconds(15));

 private:
  void on_plan(const msgs::PlanReport& p);
  void record_phase(std::uint32_t tick, bool ended, bool complete);
  // Between phases: starts phase_ once every group with a living leader has reported its robots
  // standing (see the header).
  void settle(GcsContext& ctx);
  // Settling for stall_ticks without every group standing: the phase is given up as stalled.
  void give_up_settling(std::uint32_t tick);

  comm::LockstepAgent& agent_;
  const app::RoleSetup& setup_;
  std::string run_dir_;
  FusedMap fused_;
  std::vector<std::uint32_t> round_ticks_;  // the tick each planning round of the run started
  std::vector<swarm::scenario::Phase> phases_;
  std::vector<std::unique_ptr<GcsTask>> tasks_;
  std::uint32_t phase_ = 0;
  std::vector<std::uint32_t> phase_starts_;
  std::vector<std::uint32_t> phase_ends_;
  GcsOutlets outlets_;
  std::function<void(std::uint32_t, const std::string&, bool settle)> announce_phase_;
  bool settling_ = false;       // phase_ waits for its robots to stand still
  std::vector<bool> settled_;   // per group, while settling: its robots stand
  std::uint32_t settle_since_ = 0;  // the tick settling began
  std::vector<msgs::TaskReport> task_reports_;
  Progress progress_;
  record::RecordWriter record_;
  std::unique_ptr<comm::Reader<msgs::AgentReport>> reports_reader_;
  // The route plans it records, shown to watchers (topic planned): outside the lockstep barrier.
  std::unique_ptr<comm::Writer<msgs::PlannedRoute>> planned_;
  std::mutex reports_mutex_;
  std::map<comm::AgentId, msgs::AgentReport> reports_;

  // Reachability of each group's leader, judged from its per-tick heartbeat.
  // Who led each group when (the clocks' leaders): a message from a robot that did not lead its
  // group at its stamp tick (a deposed leader's, late) is dropped and counted.
  comm::LeaderLog leaders_;
  std::uint64_t not_from_a_leader_ = 0;
  bool from_leader(const msgs::Stamp& stamp);
  // The clock's news for the record: robots lost or back, and leaders that took a group over.
  void record_events(const msgs::Clock& clock);
  std::size_t leader_changes_recorded_ = 0;  // of leaders_.changes()
  std::vector<std::uint32_t> last_heard_;
  std::uint32_t unreachable_after_ticks_ = 3;
  Outages unreachable_;  // per group
  Outages robots_lost_;  // per robot, from the clock's robot states

  std::uint32_t last_tick_ = 0;
  std::optional<std::uint32_t> complete_tick_;
  std::optional<std::string> gave_up_;  // why the current phase was given up (the mission is over)
  // Stall (Scenario.stall_ticks): the current phase's best progress fraction and when it last grew.
  double stall_best_ = -1.0;
  std::uint32_t stall_since_ = 0;
  std::size_t stall_phase_ = 0;  // phase_starts_.size() when they were set
  // Gives the current phase up as stalled when its progress has not grown for stall_ticks.
  void watch_stall(const ProgressLine& line, std::uint32_t tick);
  // Wall time (system clock: a restarted process reads tick 0's from the run directory).
  std::chrono::system_clock::time_point first_tick_time_{};
  std::chrono::system_clock::time_point last_tick_time_{};
  std::vector<comm::JournalRestart> restarts_;
  bool rejoining_ = false;  // resumed, and not yet at its first tick back in the run
};

// Where the GCS of run `run_dir` keeps its input journal.
[[nodiscard]] std::string journal_path(const std::string& run_dir);

}  // namespace swarm::gcs
