// `swarm export RUN_DIR --mcap FILE` on a real run of every phase, read back by the tests' own MCAP
// reader (swarm_test/mcap_check.hpp): every CRC and index sound, every message decodes, and the
// counts are the run record's.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "run_swarm.hpp"
#include "swarm/record/record.hpp"
#include "swarm_test/files.hpp"
#include "swarm_test/mcap_check.hpp"

namespace swarm::test {
namespace {

TEST(Export, AWholeChainRunBecomesAnMcapFileThatReadsBackWhole) {
  const std::string dir = fresh_dir("export_chain");
  const CommandResult run = run_swarm("run --map warehouse-5x8 --mission explore,cover,mapf,collect --out " + dir +
                                      "/run --mcap " + dir + "/during.mcap");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const CommandResult r = run_swarm("export " + dir + "/run --mcap " + dir + "/run.mcap");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // `swarm run --mcap` writes the same file, byte for byte.
  EXPECT_EQ(slurp(dir + "/during.mcap"), slurp(dir + "/run.mcap"));

  const McapFile f = read_mcap(slurp(dir + "/run.mcap"));
  for (const std::string& p : f.problems) ADD_FAILURE() << p;
  EXPECT_GT(f.chunks, 0U);
  EXPECT_EQ(f.metadata.at("scenario").at("map"), "warehouse-5x8");
  EXPECT_EQ(f.metadata.at("scenario").at("mission"), "explore,cover,mapf,collect");
  EXPECT_EQ(f.metadata.at("scenario").at("seed"), "1");

  // What the record holds, counted.
  const auto frames = record::read_record(dir + "/run/run.pb");
  const record::Header& h = frames.front().header();
  const int robots = static_cast<int>(h.groups() * h.robots_per_group());
  std::size_t poses = 0, maps = 0, routes = 0, logs = 0, events = 0;
  std::map<std::uint32_t, const record::Poses*> poses_at;
  for (const auto& fr : frames) {
    poses += fr.has_poses();
    maps += fr.has_map();
    routes += fr.has_route();
    logs += fr.has_phase() || fr.has_summary() || fr.has_event();
    events += fr.has_event();
    if (fr.has_poses()) poses_at[fr.poses().tick()] = &fr.poses();
  }
  ASSERT_GT(routes, 0U);
  std::map<std::string, std::size_t> per_kind;
  std::map<std::string, std::string> schema_of;
  for (const auto& [id, ch] : f.channels) schema_of[ch.topic] = f.schema_names.at(ch.schema);
  const std::uint64_t tick_ns = std::uint64_t{h.scenario().tick_ms()} * 1'000'000U;
  for (const McapMessage& m : f.messages) {
    const McapChannel& ch = f.channels.at(m.channel);
    EXPECT_EQ(ch.encoding, "json");
    const nlohmann::json j = nlohmann::json::parse(m.data);  // throws: the test fails
    std::string kind = ch.topic;
    for (const char* prefix : {"/route/", "/scan/"}) {
      if (kind.rfind(prefix, 0) == 0) kind = prefix;
    }
    ++per_kind[kind];
    if (kind == "/tf") {
      // Every robot's frame at the cell the record has it on, at the record's tick.
      ASSERT_EQ(m.log_time % tick_ns, 0U);
      const record::Poses& p = *poses_at.at(static_cast<std::uint32_t>(m.log_time / tick_ns));
      ASSERT_EQ(j["transforms"].size(), static_cast<std::size_t>(robots));
      for (int r = 0; r < robots; ++r) {
        const auto& t = j["transforms"][static_cast<std::size_t>(r)];
        EXPECT_NEAR(t["translation"]["x"].get<double>(), h.origin_x() + (p.xy(2 * r) + 0.5) * h.resolution(), 1e-9);
        EXPECT_NEAR(t["translation"]["y"].get<double>(), h.origin_y() + (p.xy(2 * r + 1) + 0.5) * h.resolution(), 1e-9);
        EXPECT_EQ(t["parent_frame_id"], "map");
      }
    } else if (kind == "/status") {
      // The clock's tally at the record's tick: the conflicts and progress the simulator counted.
      const record::Poses& p = *poses_at.at(static_cast<std::uint32_t>(m.log_time / tick_ns));
      EXPECT_EQ(j["vertex_conflicts"], p.tally().vertex_conflicts());
      EXPECT_EQ(j["progress_done"], p.tally().progress_done());
      EXPECT_EQ(j["sent_bytes"]["member_leader"], p.tally().sent_bytes(1));
    } else if (kind == "/scan/") {
      EXPECT_EQ(j["ranges"].size(), h.scenario().lidar_beams());
    } else if (kind == "/map" || kind == "/map/truth") {
      EXPECT_EQ(j["column_count"], h.width());
      EXPECT_EQ(j["data"].get<std::string>().size(), (h.width() * h.height() + 2) / 3 * 4);  // base64
    }
  }
  EXPECT_EQ(per_kind["/tf"], poses);
  EXPECT_EQ(per_kind["/scan/"], poses * static_cast<std::size_t>(robots));
  EXPECT_EQ(per_kind["/map"], maps);
  EXPECT_EQ(per_kind["/map/truth"], 1U);
  EXPECT_EQ(per_kind["/route/"], routes);
  EXPECT_EQ(per_kind["/log"], logs);
  EXPECT_EQ(per_kind["/robots"], 1U + events);
  EXPECT_EQ(per_kind["/status"], poses);
  EXPECT_EQ(schema_of["/map"], "foxglove.Grid");
  EXPECT_EQ(schema_of["/tf"], "foxglove.FrameTransforms");
  EXPECT_EQ(schema_of["/robots"], "foxglove.SceneUpdate");
  EXPECT_EQ(schema_of["/log"], "foxglove.Log");
  EXPECT_EQ(schema_of["/scan/leader-0"], "foxglove.LaserScan");
  EXPECT_EQ(schema_of["/route/leader-0"], "foxglove.PosesInFrame");

  // Bad input: exit 2 and a message naming the cause.
  const CommandResult not_a_run = run_swarm("export " + dir + " --mcap " + dir + "/x.mcap");
  EXPECT_EQ(not_a_run.exit_code, 2);
  EXPECT_NE(not_a_run.output.find("is not a run directory"), std::string::npos) << not_a_run.output;
  std::filesystem::create_directories(dir + "/cut");
  const std::string whole = slurp(dir + "/run/run.pb");
  std::ofstream(dir + "/cut/run.pb", std::ios::binary) << whole.substr(0, whole.size() - 3);
  const CommandResult truncated = run_swarm("export " + dir + "/cut --mcap " + dir + "/x.mcap");
  EXPECT_EQ(truncated.exit_code, 2);
  EXPECT_NE(truncated.output.find("run.pb"), std::string::npos) << truncated.output;
  const CommandResult no_folder = run_swarm("run --map small --mcap /nonexistent-dir/x.mcap --out " + dir + "/never");
  EXPECT_EQ(no_folder.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir + "/never"));
  const CommandResult unwritable = run_swarm("export " + dir + "/run --mcap /nonexistent-dir/x.mcap");
  EXPECT_EQ(unwritable.exit_code, 2);
  EXPECT_NE(unwritable.output.find("/nonexistent-dir/x.mcap"), std::string::npos) << unwritable.output;
}

}  // namespace
}  // namespace swarm::test
