// metrics.json and the simulator's report: one schema, written and read back unchanged; a missing
// key or another schema version is an error that names it.
#include "swarm/record/metrics.hpp"

#include <gtest/gtest.h>

#include <string>

#include "swarm_test/metrics_fixture.hpp"
#include "swarm_test/text.hpp"

namespace swarm::record {
namespace {

using swarm::test::contains;

std::string error_of(const std::function<void()>& f) { return swarm::test::error_of<MetricsError>(f, "(no MetricsError)"); }

TEST(Metrics, RoundTripsThroughJson) {
  RunMetrics m = swarm::test::run_metrics("maze1", "baseline", 7, 345, 18);
  m.agents_lost.push_back({"member-0-1", 100, std::nullopt, 99, 1.02});
  m.unreachable.push_back({"leader-1", 20, 60});
  m.motion.total.moves = 12;
  m.motion.vertex_conflict_events = 3;
  m.motion.per_robot["leader-0"].blocked_moves = 2;
  m.motion.per_robot["leader-0"].longest_blocked_ticks = 5;
  m.phases[0].task = {{"planning_rounds", 18}};
  m.traffic.by_link["leader_gcs"].queued_ticks = {3, 0, 1};
  m.traffic.by_link["leader_gcs"].busiest_sender = "gcs";
  m.traffic.by_link["leader_gcs"].busiest_sender_bytes = 4100;
  const RunMetrics back = metrics_from_json(to_json(m), "test");
  EXPECT_EQ(back.traffic.by_link.at("leader_gcs").queued_ticks, (std::vector<std::uint64_t>{3, 0, 1}));
  EXPECT_EQ(back.traffic.by_link.at("leader_gcs").busiest_sender, "gcs");
  EXPECT_EQ(back.traffic.by_link.at("leader_gcs").busiest_sender_bytes, 4100u);
  EXPECT_EQ(to_json(back), to_json(m));
  EXPECT_EQ(back.schema_version, kMetricsSchemaVersion);
  EXPECT_EQ(back.agents_lost[0].stopped_answering_at_tick, 99u);
  EXPECT_FALSE(back.agents_lost[0].rejoined_at_tick.has_value());
  EXPECT_EQ(back.motion.per_robot.at("leader-0").blocked_moves, 2u);
  EXPECT_EQ(back.motion.per_robot.at("leader-0").longest_blocked_ticks, 5u);
}

TEST(Metrics, QueueQuantilesOfAHistogramOfTicksWaited) {
  // 10 messages: 5 waited 0 ticks, 3 waited 1, 1 waited 4, 1 waited 9. Half are within 0; 95 % (9.5
  // messages) only within 9.
  const std::vector<std::uint64_t> q = {5, 3, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(queue_quantile(q, 0.5), 0u);
  EXPECT_EQ(queue_quantile(q, 0.8), 1u);
  EXPECT_EQ(queue_quantile(q, 0.9), 4u);
  EXPECT_EQ(queue_quantile(q, 0.95), 9u);
  EXPECT_FALSE(queue_quantile({}, 0.5).has_value());
  EXPECT_FALSE(queue_quantile({0, 0}, 0.5).has_value());
  // In metrics.json: null on an uncapped link.
  RunMetrics m = swarm::test::run_metrics("maze1", "baseline", 7, 345, 18);
  m.traffic.by_link["member_leader"] = {};
  m.traffic.by_link["leader_gcs"].queued_ticks = q;
  const nlohmann::json j = to_json(m)["traffic"]["by_link"];
  EXPECT_TRUE(j["member_leader"]["queue_p95_ticks"].is_null());
  EXPECT_EQ(j["leader_gcs"]["queue_median_ticks"], 0);
  EXPECT_EQ(j["leader_gcs"]["queue_p95_ticks"], 9);
  EXPECT_TRUE(j["member_leader"]["busiest_sender"].is_null());  // nobody sent on it
}

// A record written before the busiest sender was kept reads as naming none.
TEST(Metrics, ALinkWithoutItsBusiestSenderReadsAsNone) {
  RunMetrics m = swarm::test::run_metrics("maze1", "baseline", 7, 345, 18);
  m.traffic.by_link["leader_gcs"].bytes = 10;
  auto j = to_json(m);
  j["traffic"]["by_link"]["leader_gcs"].erase("busiest_sender");
  j["traffic"]["by_link"]["leader_gcs"].erase("busiest_sender_bytes");
  const RunMetrics back = metrics_from_json(j, "test");
  EXPECT_EQ(back.traffic.by_link.at("leader_gcs").bytes, 10u);
  EXPECT_TRUE(back.traffic.by_link.at("leader_gcs").busiest_sender.empty());
  EXPECT_EQ(back.traffic.by_link.at("leader_gcs").busiest_sender_bytes, 0u);
}

TEST(Metrics, AMissingKeyOrAnotherVersionIsNamed) {
  auto j = to_json(swarm::test::run_metrics("maze1", "baseline", 7, 345, 18));
  j["traffic"]["total"].erase("bytes");
  EXPECT_TRUE(contains(error_of([&] { (void)metrics_from_json(j, "run/metrics.json"); }),
                       "run/metrics.json.traffic.total: missing key 'bytes'"));
  j = to_json(swarm::test::run_metrics("maze1", "baseline", 7, 345, 18));
  j["steps"] = "many";
  EXPECT_TRUE(contains(error_of([&] { (void)metrics_from_json(j, "m"); }), "key 'steps' has the wrong type"));
  j.erase("schema_version");
  EXPECT_TRUE(contains(error_of([&] { (void)metrics_from_json(j, "m"); }), "no schema_version"));
  j["schema_version"] = 99;
  EXPECT_TRUE(contains(error_of([&] { (void)metrics_from_json(j, "m"); }), "schema_version 99, but this swarm reads version"));
}

TEST(SimReport, RequiredKeysAreNamedWithTheProcess) {
  SimReport r;
  r.explored_fraction = 0.5;
  r.explored_curve = {{0, 0.1}, {10, 0.5}};
  const SimReport back = sim_report_from_json(to_json(r), "sim");
  EXPECT_DOUBLE_EQ(back.explored_fraction, 0.5);
  EXPECT_EQ(back.explored_curve, r.explored_curve);
  auto j = to_json(r);
  j.erase("explored_fraction");
  EXPECT_EQ(error_of([&] { (void)sim_report_from_json(j, "sim"); }), "sim's report: missing key 'explored_fraction'");
}

}  // namespace
}  // namespace swarm::record
