// The input journal (comm/journal.hpp): ticks written whole come back whole; a process that died
// mid-tick leaves a tail the reader ignores and the next writer cuts off; garbage ends the reading.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "swarm/comm/journal.hpp"

namespace swarm::comm {
namespace {

std::string fresh(const std::string& name) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::remove(path.c_str());
  return path;
}

TEST(Journal, CompleteTicksComeBackInOrderWithTheirMessages) {
  const std::string path = fresh("journal_ticks");
  {
    JournalWriter w(path);
    w.clock(0, "c0");
    w.message(0, 3, "a");
    w.message(0, 1, std::string("b\0c", 3));
    w.tick_end(0);
    w.clock(1, "c1");
    w.tick_end(1);
  }
  const JournalContents j = read_journal(path);
  ASSERT_EQ(j.ticks.size(), 2u);
  EXPECT_EQ(j.ticks[0].tick, 0u);
  EXPECT_EQ(j.ticks[0].clock, "c0");
  ASSERT_EQ(j.ticks[0].messages.size(), 2u);
  EXPECT_EQ(j.ticks[0].messages[0].order, 3);
  EXPECT_EQ(j.ticks[0].messages[0].bytes, "a");
  EXPECT_EQ(j.ticks[0].messages[1].bytes, std::string("b\0c", 3));
  EXPECT_EQ(j.ticks[1].clock, "c1");
  EXPECT_TRUE(j.ticks[1].messages.empty());
  EXPECT_EQ(j.complete_bytes, std::filesystem::file_size(path));
}

// Killed between a tick's clock and its end: that tick is not replayed, and the restarted process
// writes on from the last complete tick (its restart record, then the ticks it lives).
TEST(Journal, AnUnfinishedTickIsIgnoredAndCutOffBeforeAppending) {
  const std::string path = fresh("journal_cut");
  {
    JournalWriter w(path);
    w.clock(0, "c0");
    w.tick_end(0);
    w.clock(1, "c1");
    w.message(1, 0, "lost");  // the process died here
  }
  JournalContents j = read_journal(path);
  ASSERT_EQ(j.ticks.size(), 1u);
  EXPECT_LT(j.complete_bytes, std::filesystem::file_size(path));
  {
    JournalWriter w(path, j.complete_bytes);
    w.restart(0, {1, 0.25});
    w.clock(5, "c5");
    w.tick_end(5);
  }
  j = read_journal(path);
  ASSERT_EQ(j.ticks.size(), 2u);
  EXPECT_EQ(j.ticks[1].tick, 5u);
  ASSERT_EQ(j.restarts.size(), 1u);
  EXPECT_EQ(j.restarts[0].replayed_ticks, 1u);
  EXPECT_DOUBLE_EQ(j.restarts[0].seconds, 0.25);
}

TEST(Journal, AMissingFileIsEmptyAndGarbageEndsTheReading) {
  EXPECT_TRUE(read_journal(fresh("journal_missing")).ticks.empty());
  const std::string path = fresh("journal_garbage");
  {
    JournalWriter w(path);
    w.clock(0, "c0");
    w.tick_end(0);
  }
  std::ofstream(path, std::ios::app | std::ios::binary) << "\x07garbage that is no record at all";
  const JournalContents j = read_journal(path);
  EXPECT_EQ(j.ticks.size(), 1u);
  // A length beyond the file: a cut-off record, not a crash.
  std::ofstream(path, std::ios::app | std::ios::binary) << std::string("\x01\0\0\0\0\0\0\0\0\xff\xff\xff\x00", 13);
  EXPECT_EQ(read_journal(path).ticks.size(), 1u);
}

TEST(Journal, AnUnwritableFileIsAnErrorNamingIt) {
  try {
    JournalWriter w("/nonexistent-folder/x.journal");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x.journal"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swarm::comm
