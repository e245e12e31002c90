// metrics.json: the one schema of a run's numbers, as typed structs, written in one place
// (write_metrics, by the GCS) and read in one place (read_metrics, by `swarm run`, `swarm report`,
// the experiments and tests). Also the simulator's end-of-run report to the GCS (SimReport), whose
// keys are required: a missing one is an error naming the process and the key, never a silent 0.
//
// Versioning: `schema_version` is kMetricsSchemaVersion; a reader refuses any other version with
// a message saying which it found and which it reads (re-run, or use the swarm that wrote it).
//
// Definitions:
//   steps       the tick at which the GCS declared the mission complete; for a run that did not
//               complete (stopped at max_ticks), the ticks it ran: a lower bound, flagged by
//               complete = false. ticks_run is always the ticks actually run.
//   phases      one entry per mission phase that started, in order: its name, the ticks it began
//               and ended (end_tick null while it never ended), whether it completed, the
//               simulator's ground-truth judge of it (motion: moves, conflicts, ...) and the
//               task's own numbers.
//
//   RunMetrics m = read_metrics(run_dir + "/metrics.json");   // throws MetricsError
//   write_metrics(run_dir + "/metrics.json", m);
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace swarm::record {

inline constexpr int kMetricsSchemaVersion = 6;  // 6: ended; 5: phases' ground truth verdicts; 4: longest_blocked_ticks; 3: leader hand-overs

class MetricsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A partial metrics.json: the run ended early and the launcher wrote only what the run record
// held (tools/launcher/run_end.hpp). Tables skip such runs, saying so.
class PartialMetricsError : public MetricsError {
 public:
  using MetricsError::MetricsError;
};

// What the simulator judged robots did, from ground truth (sim/world.hpp).
struct MotionCounts {
  std::uint64_t moves = 0;
  std::uint64_t waits = 0;
  std::uint64_t vertex_conflicts = 0;  // per robot: conflicts it took part in
  std::uint64_t edge_conflicts = 0;
  std::uint64_t blocked_moves = 0;
  std::uint64_t wall_stops = 0;
  std::uint64_t routes_rejected = 0;
  std::uint64_t turn_eighths = 0;  // rotation between consecutive moves, eighths of a turn (turns.hpp)
  // The longest run of consecutive ticks on which the robot's move failed because of another
  // robot (a blocked move, or a vertex or edge conflict): a robot stuck behind another. Not a sum:
  // += keeps the larger, and a difference keeps the left's (the simulator measures it per phase).
  std::uint64_t longest_blocked_ticks = 0;
  MotionCounts& operator+=(const MotionCounts& o);
  MotionCounts operator-(const MotionCounts& o) const;
};

struct MotionNumbers {
  MotionCounts total;
  std::uint64_t vertex_conflict_events = 0;  // one per cell and tick
  std::uint64_t edge_conflict_events = 0;    // one per swapping pair and tick
  std::map<std::string, MotionCounts> per_robot;
};

struct TopicTraffic {
  std::string link;
  std::uint64_t messages = 0;
  std::uint64_t bytes = 0;
  std::uint64_t addressed_messages = 0;  // messages x their receivers: what received_messages should be
  std::uint64_t received_messages = 0;
  std::uint64_t lost_transmissions = 0;
  std::uint64_t dropped_messages = 0;
};

struct LinkTraffic {
  std::uint64_t messages = 0;
  std::uint64_t bytes = 0;
  std::uint64_t lost_transmissions = 0;
  std::uint64_t dropped_messages = 0;
  // Under a bandwidth cap: queued_ticks[d] = messages that waited d ticks behind earlier ones
  // (comm::TrafficCount); empty on an uncapped link.
  std::vector<std::uint64_t> queued_ticks;
  // The agent that sent the most bytes on the link, and how many: a cap binds per sender
  // (comm/link.hpp: one token bucket per sender and class), so it is the busiest sender, not the
  // average one, that a cap holds up first. Empty when nobody sent on the link.
  std::string busiest_sender;
  std::uint64_t busiest_sender_bytes = 0;
};

// The q-quantile (0..1) of the ticks in a queued_ticks histogram: the smallest d with at least
// q of the messages at or below it. nullopt for an empty histogram.
[[nodiscard]] std::optional<std::uint32_t> queue_quantile(const std::vector<std::uint64_t>& queued_ticks, double q);

struct Traffic {
  std::map<std::string, TopicTraffic> by_topic;
  std::map<std::string, LinkTraffic> by_link;
  std::uint64_t total_messages = 0;
  std::uint64_t total_bytes = 0;
};

struct AgentLost {
  std::string agent;
  std::uint32_t marked_lost_at_tick = 0;
  std::optional<std::uint32_t> rejoined_at_tick;
  std::optional<std::uint32_t> stopped_answering_at_tick;
  std::optional<double> detection_seconds;
};

// The GCS's process killed and started again (gcs/gcs_node.hpp "Restart"): it stopped answering at
// `stopped_at_tick` (DDS noticed after `detection_seconds`), rebuilt its state by replaying
// `replayed_ticks` ticks of its journal in `replay_seconds`, and took part again from
// `rejoined_at_tick` on; it heard nothing in between.
struct GcsRestart {
  std::optional<std::uint32_t> stopped_at_tick;
  std::optional<double> detection_seconds;
  std::optional<std::uint32_t> rejoined_at_tick;
  std::uint32_t replayed_ticks = 0;
  double replay_seconds = 0;
};

// A group's leadership passing from one robot to another (comm/leadership.hpp): the clock named
// `to` at `at_tick`; `from` stopped answering at `from_stopped_at_tick` (the simulator's loss
// record: null when it was not lost), so the group had no leader for `leaderless_ticks` ticks and
// `detection_seconds` of wall time (how long DDS took to declare `from` lost).
struct Handover {
  int group = 0;
  std::string from;
  std::string to;
  std::uint32_t at_tick = 0;
  std::optional<std::uint32_t> from_stopped_at_tick;
  std::optional<std::uint32_t> leaderless_ticks;
  std::optional<double> detection_seconds;
};

struct Unreachable {
  std::string agent;
  std::uint32_t from_tick = 0;
  std::uint32_t to_tick = 0;
};

// The key of a phase judge's verdict (sim/phase_judge.hpp): true when the ground truth says the
// phase's work is done, null where the simulator cannot tell. It becomes PhaseMetrics's
// ground_truth_done.
inline constexpr const char* kGroundTruthDone = "ground_truth_done";

struct PhaseMetrics {
  std::string name;  // explore | cover | mapf | collect
  std::uint32_t start_tick = 0;
  std::optional<std::uint32_t> end_tick;
  // Done by the GCS's judgement and, where the simulator can tell, by the ground truth too.
  bool complete = false;
  std::optional<std::string> gave_up;  // why the GCS ended it incomplete (gcs_task.hpp given_up)
  // The simulator's verdict from the ground truth (the task's judge: ground_truth_done; none where
  // it cannot tell, e.g. random mapf goals only the GCS knows), and, when it says the work is not
  // done although the GCS ended the phase complete, what they disagree on.
  std::optional<bool> ground_truth_done;
  std::optional<std::string> disagreement;
  MotionNumbers motion;
  nlohmann::json task = nlohmann::json::object();  // the task's own numbers (its README section)
};

struct RunMetrics {
  int schema_version = kMetricsSchemaVersion;
  std::string scenario;
  std::string map;
  std::string mode;
  std::uint64_t seed = 0;
  std::uint32_t groups = 0;
  std::uint32_t robots_per_group = 0;
  std::uint32_t robots = 0;
  std::uint32_t steps = 0;
  std::optional<std::uint32_t> steps_to_99;
  std::uint32_t planning_rounds = 0;
  double explored_fraction = 0;
  bool complete = false;
  // Why the run ended, for a person: "complete", "given up: ...", "max_ticks (3000) reached", or
  // how it was stopped early ("interrupted: ...", "timed out: ...", "process member-0-1 failed
  // ...", which the launcher writes in, tools/launcher/run_end.hpp).
  std::string ended;
  std::uint32_t ticks_run = 0;
  double wall_seconds = 0;
  double ticks_per_second = 0;
  Traffic traffic;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> rounds;  // (round, start tick)
  std::vector<std::pair<std::uint32_t, double>> explored_curve;  // (tick, explored fraction)
  double planning_seconds_total = 0;
  double planning_ms_per_group_round = 0;
  std::vector<AgentLost> agents_lost;
  std::vector<Unreachable> unreachable;
  std::vector<Handover> leader_handovers;
  std::vector<GcsRestart> gcs_restarts;
  std::uint64_t messages_from_deposed_leaders = 0;  // heard by the GCS from a robot no longer leading, dropped
  MotionNumbers motion;  // the whole run
  std::vector<PhaseMetrics> phases;
  std::map<std::string, nlohmann::json> agents;  // each agent's own numbers, by name
  std::vector<std::string> reports_missing;
};

[[nodiscard]] nlohmann::json to_json(const RunMetrics& m);
// Throws MetricsError naming `source` and the first missing or mistyped key, or an unknown
// schema_version.
[[nodiscard]] RunMetrics metrics_from_json(const nlohmann::json& j, const std::string& source);
void write_metrics(const std::string& path, const RunMetrics& m);  // throws MetricsError
[[nodiscard]] RunMetrics read_metrics(const std::string& path);    // throws MetricsError

// The simulator's report at the end of a run (AgentReport.extra_json of the "sim" agent).
struct SimPhase {
  std::uint32_t phase = 0;
  std::string name;
  std::uint32_t start_tick = 0;
  MotionNumbers motion;
  nlohmann::json judge = nlohmann::json::object();  // the phase's ground-truth numbers (covered, ...)
};

struct SimReport {
  std::uint32_t last_tick = 0;
  std::optional<std::uint32_t> steps_to_99;
  double explored_fraction = 0;
  std::uint32_t reachable_free_cells = 0;
  std::vector<std::pair<std::uint32_t, double>> explored_curve;
  MotionNumbers motion;
  std::vector<SimPhase> phases;
  struct Loss {
    std::string agent;
    std::uint32_t missed_tick = 0;
    double detection_seconds = 0;
    std::optional<std::uint32_t> rejoined_tick;
    bool restarted = false;  // it came back as a new process (comm/lockstep.hpp "Restart")
  };
  std::vector<Loss> agents_lost;
};

[[nodiscard]] nlohmann::json to_json(const SimReport& r);
// Throws MetricsError: "<process>'s report: missing key 'explored_fraction'".
[[nodiscard]] SimReport sim_report_from_json(const nlohmann::json& j, const std::string& process);

nlohmann::json to_json(const MotionNumbers& m);
MotionNumbers motion_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace swarm::record
