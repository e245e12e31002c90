// The MCAP writer, read back by the test's own reader written from the specification
// (swarm_test/mcap_check.hpp): CRCs, chunk and message indexes, summary offsets, statistics.
#include "swarm/record/mcap_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "swarm_test/files.hpp"
#include "swarm_test/mcap_check.hpp"

namespace swarm::record {
namespace {

std::string temp_file(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / name).string();
}

TEST(Mcap, Crc32IsTheIeeeOne) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926U);  // the check value of CRC-32/ISO-HDLC
  EXPECT_EQ(crc32(""), 0U);
  EXPECT_EQ(crc32("6789", crc32("12345")), 0xCBF43926U);  // continued
}

// Several chunks (a small chunk size), two schemas, three channels and metadata, compressed and
// not: every check of the reader passes and every message comes back as written.
TEST(Mcap, WhatIsWrittenReadsBackWithEveryIndexAndCrc) {
  for (const bool compress : {true, false}) {
    SCOPED_TRACE(compress);
    const std::string path = temp_file(compress ? "zstd.mcap" : "plain.mcap");
    McapWriter::Options o;
    o.chunk_bytes = 300;
    o.compress = compress;
    {
      McapWriter w(path, o);
      const auto log = w.add_schema("foxglove.Log", "jsonschema", R"({"type":"object"})");
      const auto grid = w.add_schema("foxglove.Grid", "jsonschema", R"({"type":"object"})");
      const auto a = w.add_channel(log, "/log", "json");
      const auto b = w.add_channel(grid, "/map", "json", {{"frame", "map"}});
      w.add_metadata("scenario", {{"seed", "7"}, {"map", "small"}});
      for (int k = 0; k < 40; ++k) w.write(k % 3 == 0 ? b : a, 1000U * static_cast<unsigned>(k), "{\"k\":" + std::to_string(k) + "}");
      const auto c = w.add_channel(log, "/late", "json");  // a channel added midway
      w.write(c, 50'000, "{}");
      EXPECT_EQ(w.messages(), 41U);
      w.close();
    }
    const swarm::test::McapFile f = swarm::test::read_mcap(swarm::test::slurp(path));
    for (const std::string& p : f.problems) ADD_FAILURE() << p;
    ASSERT_EQ(f.messages.size(), 41U);
    EXPECT_GT(f.chunks, 3U);
    EXPECT_EQ(f.messages[5].data, "{\"k\":5}");
    EXPECT_EQ(f.messages[5].log_time, 5000U);
    EXPECT_EQ(f.messages[4].sequence, 2U);  // the third on /log
    EXPECT_EQ(f.channels.at(2).topic, "/map");
    EXPECT_EQ(f.channels.at(2).metadata.at("frame"), "map");
    EXPECT_EQ(f.schema_names.at(2), "foxglove.Grid");
    EXPECT_EQ(f.metadata.at("scenario").at("seed"), "7");
    EXPECT_EQ(f.library, "swarm");
  }
}

// The reader is not a rubber stamp: a byte changed inside a chunk or in the summary is caught.
TEST(Mcap, TheReaderCatchesACorruptChunkAndSummary) {
  const std::string path = temp_file("corrupt.mcap");
  {
    McapWriter w(path, McapWriter::Options{"", "swarm", 1 << 20, false});
    const auto s = w.add_schema("foxglove.Log", "jsonschema", "{}");
    const auto c = w.add_channel(s, "/log", "json");
    for (int k = 0; k < 5; ++k) w.write(c, static_cast<unsigned>(k), "{\"message\":\"hello\"}");
  }
  const std::string good = swarm::test::slurp(path);
  EXPECT_TRUE(swarm::test::read_mcap(good).problems.empty());
  std::string bad = good;
  const std::size_t hello = bad.find("hello");
  ASSERT_NE(hello, std::string::npos);
  bad[hello] = 'j';
  EXPECT_FALSE(swarm::test::read_mcap(bad).problems.empty());
  bad = good;
  bad[bad.size() - 8 - 29 - 3] ^= 1;  // inside the last Summary Offset
  EXPECT_FALSE(swarm::test::read_mcap(bad).problems.empty());
  EXPECT_FALSE(swarm::test::read_mcap(good.substr(0, good.size() - 1)).problems.empty());
}

TEST(Mcap, AnUnwritablePathThrowsNamingIt) {
  try {
    McapWriter w("/nonexistent-dir/x.mcap");
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.mcap"), std::string::npos);
  }
}

}  // namespace
}  // namespace swarm::record
