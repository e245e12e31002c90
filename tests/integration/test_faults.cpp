// Faults without Docker: a member or a leader crashes, a leader's links are cut and heal, a leader
// freezes and comes back; and real-time mode.
// The same runtime paths serve the docker-compose deployment (deploy/).
#include <gtest/gtest.h>

#include "run_swarm.hpp"
#include "swarm/record/record.hpp"
#include "swarm_test/files.hpp"

namespace swarm::test {
namespace {

const std::string kSmall = "run --scenario " + source_path("scenarios/small.pbtxt");

// member-1-1 crashes at tick 30: the simulator notices through DDS (its heartbeat writer's 1 s
// liveliness lease runs out), every process sees it marked dead at the next tick,
// its leader plans without it, and the mission still completes.
TEST(Faults, KilledMemberIsNoticedAndTheMissionCompletes) {
  const std::string dir = fresh_dir("kill_member") + "/run";
  const CommandResult r = run_swarm(kSmall + " --kill member-1-1@30 --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = read_json(dir + "/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>());
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
  const auto& lost = m["faults"]["agents_lost"];
  ASSERT_EQ(lost.size(), 1u) << lost;
  EXPECT_EQ(lost[0]["agent"], "member-1-1");
  EXPECT_EQ(lost[0]["stopped_answering_at_tick"], 30);
  EXPECT_EQ(lost[0]["marked_lost_at_tick"], 31);
  // The bound: the 1 s liveliness lease of deploy/fastdds_loopback.xml, plus slack for a busy CI.
  EXPECT_GE(lost[0]["detection_seconds"].get<double>(), 0.9);
  EXPECT_LT(lost[0]["detection_seconds"].get<double>(), 4.0);
  EXPECT_TRUE(lost[0]["rejoined_at_tick"].is_null());
  const auto& noticed = m["agents"]["leader-1"]["members_lost"];
  ASSERT_EQ(noticed.size(), 1u);
  EXPECT_EQ(noticed[0]["agent"], "member-1-1");
  EXPECT_EQ(noticed[0]["noticed_at_tick"], 31);
  // The dead member never reports; everybody else does.
  EXPECT_EQ(m["reports_missing"], nlohmann::json::array({"member-1-1"}));
}

// leader-1's links are down for ticks 20..60: the GCS shows it unreachable meanwhile, and what
// the group mapped while cut reaches the GCS after the link heals (nothing is lost).
TEST(Faults, CutLeaderIsUnreachableThenCatchesUp) {
  const std::string dir = fresh_dir("cut_leader") + "/run";
  const CommandResult r = run_swarm(kSmall + " --cut leader-1@20-60 --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("leader-1 unreachable"), std::string::npos) << r.output;
  const auto m = read_json(dir + "/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>());
  const auto& unreachable = m["faults"]["unreachable"];
  ASSERT_EQ(unreachable.size(), 1u) << unreachable;
  EXPECT_EQ(unreachable[0]["agent"], "leader-1");
  // Its last heartbeat before the cut was sent at 19 and seen at 20; the first after it is seen at 60.
  EXPECT_GE(unreachable[0]["from_tick"].get<int>(), 19);
  EXPECT_LE(unreachable[0]["from_tick"].get<int>(), 22);
  EXPECT_EQ(unreachable[0]["to_tick"], 60);
  const auto& patches = m["traffic"]["by_topic"]["patch_gcs"];
  EXPECT_EQ(patches["messages"], patches["received_messages"]);
  EXPECT_TRUE(m["reports_missing"].empty());
}

// leader-1's whole process stops at tick 20 for 3 s (maze1 in real time, 20 ms ticks, so mid-
// mission): to the others it is
// a leader whose network was cut, over real DDS. The simulator declares it lost after the 1 s
// liveliness lease, the GCS shows it unreachable, and when it resumes it is re-admitted, and
// everything sent to or by it meanwhile arrives (the 30 s participant lease keeps the DDS
// sessions): each map patch sent was received, and the mission completes.
TEST(Faults, FrozenLeaderIsReadmittedAndNothingIsLost) {
  const std::string dir = fresh_dir("freeze_leader") + "/run";
  const CommandResult r = run_swarm("run --realtime --tick-ms 20 --freeze leader-1@20+3 --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("leader-1 unreachable"), std::string::npos) << r.output;
  const auto m = read_json(dir + "/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>());
  const auto& lost = m["faults"]["agents_lost"];
  ASSERT_EQ(lost.size(), 1u) << lost;
  EXPECT_EQ(lost[0]["agent"], "leader-1");
  ASSERT_TRUE(lost[0].contains("stopped_answering_at_tick")) << lost;  // the simulator's side of it
  EXPECT_LE(lost[0]["stopped_answering_at_tick"].get<int>(), 21);  // real time may skip a tick
  EXPECT_GE(lost[0]["detection_seconds"].get<double>(), 0.9);
  EXPECT_LT(lost[0]["detection_seconds"].get<double>(), 4.0);
  ASSERT_FALSE(lost[0]["rejoined_at_tick"].is_null()) << lost;
  // 3 s is 150 ticks of 20 ms; it is back within a few seconds of resuming.
  const int away = lost[0]["rejoined_at_tick"].get<int>() - lost[0]["stopped_answering_at_tick"].get<int>();
  EXPECT_GE(away, 100) << lost;
  EXPECT_LE(away, 350) << lost;
  // Its standby took the group over when the simulator declared it lost, and kept it: the
  // frozen leader came back as a member (its one term as leader ended at the hand-over).
  const auto& h = m["faults"]["leader_handovers"];
  ASSERT_EQ(h.size(), 1u) << h;
  EXPECT_EQ(h[0]["from"], "leader-1");
  EXPECT_EQ(h[0]["to"], "member-1-1");
  EXPECT_EQ(h[0]["at_tick"], lost[0]["marked_lost_at_tick"]);
  // leader-1 learns it was replaced at the first clock it reads after resuming (in real time it
  // skips to the newest), and was frozen until then: it never led after the hand-over.
  const auto& old_terms = m["agents"]["leader-1"]["led"];
  ASSERT_EQ(old_terms.size(), 1u) << old_terms;
  EXPECT_GE(old_terms[0]["to_tick"].get<int>(), h[0]["at_tick"].get<int>());
  EXPECT_EQ(m["agents"]["leader-1"]["member"]["orders_not_from_the_leader"], 0);
  const auto& new_terms = m["agents"]["member-1-1"]["led"];
  ASSERT_EQ(new_terms.size(), 1u) << new_terms;
  EXPECT_EQ(new_terms[0]["from_tick"], h[0]["at_tick"]);
  EXPECT_TRUE(new_terms[0]["to_tick"].is_null());
  // The GCS heard group 1 again as soon as the standby led: unreachable for about the lease.
  const auto& unreachable = m["faults"]["unreachable"];
  ASSERT_EQ(unreachable.size(), 1u) << unreachable;
  EXPECT_EQ(unreachable[0]["agent"], "leader-1");
  EXPECT_LT(unreachable[0]["to_tick"].get<int>() - unreachable[0]["from_tick"].get<int>(), 100) << unreachable;
  // Every message reached every receiver it was meant for (the standbys hear the members too).
  for (const char* topic : {"patch_up", "patch_gcs", "task_report", "task_order"}) {
    const auto& t = m["traffic"]["by_topic"][topic];
    EXPECT_EQ(t["addressed_messages"], t["received_messages"]) << topic;
  }
  EXPECT_TRUE(m["reports_missing"].empty()) << m["reports_missing"];
}

// leader-1 crashes at tick 30: the simulator declares it lost at 31 (1 s liveliness lease), the
// clock names its standby member-1-1 leader from that tick, member-1-1 takes the group over (its
// own map and the GCS's rounds), and the mission completes with the whole map explored.
TEST(Faults, KilledLeaderIsReplacedByItsStandbyAndTheMissionCompletes) {
  const std::string dir = fresh_dir("kill_leader") + "/run";
  const CommandResult r = run_swarm(kSmall + " --kill leader-1@30 --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = read_json(dir + "/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>());
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
  const auto& h = m["faults"]["leader_handovers"];
  ASSERT_EQ(h.size(), 1u) << h;
  EXPECT_EQ(h[0]["group"], 1);
  EXPECT_EQ(h[0]["from"], "leader-1");
  EXPECT_EQ(h[0]["to"], "member-1-1");
  EXPECT_EQ(h[0]["at_tick"], 31);
  EXPECT_EQ(h[0]["from_stopped_at_tick"], 30);
  EXPECT_EQ(h[0]["leaderless_ticks"], 1);
  EXPECT_GE(h[0]["detection_seconds"].get<double>(), 0.9);
  const auto& led = m["agents"]["member-1-1"]["led"];
  ASSERT_EQ(led.size(), 1u) << led;
  EXPECT_EQ(led[0]["from_tick"], 31);
  EXPECT_GT(m["agents"]["member-1-1"]["rounds_planned"].get<int>(), 0);
  EXPECT_EQ(m["reports_missing"], nlohmann::json::array({"leader-1"}));
}

// Real-time mode: wall-rate ticks and millisecond delays; the metrics carry the same fields.
// The last fused map a run recorded (run.pb's last MapVersion frame).
std::string last_map(const std::string& run_dir) {
  std::string rle;
  for (const auto& f : record::read_record(run_dir + "/run.pb")) {
    if (f.has_map()) rle = f.map().rle();
  }
  return rle;
}

// The GCS's process is killed at tick 40 and started again 2 s later: it rebuilds its state from
// its journal (40 ticks replayed), the simulator admits it back, the leaders send it their group
// maps again, and the mission completes with the same explored map as without the fault. The run
// record is one valid file (read whole here), rewritten by the new process from tick 0.
TEST(Faults, KilledGcsIsRestartedAndTheMissionCompletesWithTheSameMap) {
  const std::string base = fresh_dir("kill_gcs");
  const CommandResult plain = run_swarm(kSmall + " --out " + base + "/plain");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const CommandResult r = run_swarm(kSmall + " --kill gcs@40+2 --out " + base + "/restart");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = read_json(base + "/restart/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>());
  EXPECT_GE(m["explored_fraction"].get<double>(), 0.99);
  const auto& restarts = m["faults"]["gcs_restarts"];
  ASSERT_EQ(restarts.size(), 1u) << restarts;
  EXPECT_EQ(restarts[0]["stopped_at_tick"], 40);
  EXPECT_EQ(restarts[0]["replayed_ticks"], 40);
  EXPECT_GT(restarts[0]["rejoined_at_tick"].get<int>(), 40);
  EXPECT_TRUE(m["reports_missing"].empty()) << m["reports_missing"];
  // Nothing lost: the final fused map is the fault-free run's, cell for cell.
  const std::string restarted = last_map(base + "/restart");
  ASSERT_FALSE(restarted.empty());
  EXPECT_EQ(restarted, last_map(base + "/plain"));
  EXPECT_NE(slurp(base + "/restart/logs/gcs.log").find("gcs: resumed: 40 ticks of the journal replayed"),
            std::string::npos);
}

TEST(RealTime, SmallMissionCompletes) {
  const std::string dir = fresh_dir("realtime") + "/run";
  const CommandResult r = run_swarm(kSmall + " --realtime --tick-ms 20 --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = read_json(dir + "/metrics.json");
  EXPECT_TRUE(m["complete"].get<bool>());
  for (const char* key : {"steps", "steps_to_99", "planning_rounds", "explored_fraction", "wall_seconds",
                          "ticks_per_second", "traffic"}) {
    EXPECT_TRUE(m.contains(key)) << key;
  }
  // 20 ms ticks: the clock runs at about 50 ticks/s, never faster.
  EXPECT_LT(m["ticks_per_second"].get<double>(), 55.0);
}

}  // namespace
}  // namespace swarm::test
