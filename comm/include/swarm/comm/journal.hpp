// An agent's input journal: what a process that restarts needs to become again exactly what it
// was (issue 11, "the GCS can restart"). Every tick it records the clock it acted on and every
// message handed to its handlers, in the order they ran; a new process of the same agent reads
// the journal back and runs the same handlers and steps on the same inputs (lockstep makes a node
// a pure function of them), its sends muted, and so rebuilds the old process's state tick by tick
// before it joins the run again (LockstepAgent::replay_journal, rejoin).
//
// File: a sequence of records, each [kind u8][tick u32][order u32][length u32][length bytes],
// little-endian. Kinds: a tick's Clock (CDR), a message (its subscription order and CDR bytes), the
// tick's end (the step ran and its Done was sent), a restart (the ticks replayed and the seconds
// it took, as text). A tick counts only once its end is written: a process that died mid-tick
// left a tail that the reader ignores and the writer cuts off before appending.
//
//   JournalWriter w(path);                 // appends after the last complete tick
//   w.clock(k, bytes); w.message(k, order, bytes); ...; w.tick_end(k);   // flushed per tick
//   for (const JournalTick& t : read_journal(path)) { ... t.clock, t.messages ... }
// Not thread-safe: one agent loop writes it.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace swarm::comm {

struct JournalMessage {
  int order = 0;  // the subscription it came through (Mailbox subscription order)
  std::string bytes;
};

struct JournalTick {
  std::uint32_t tick = 0;
  std::string clock;  // CDR of msgs::Clock
  std::vector<JournalMessage> messages;
};

struct JournalRestart {
  std::uint32_t replayed_ticks = 0;
  double seconds = 0;
};

struct JournalContents {
  std::vector<JournalTick> ticks;        // complete ticks, in order
  std::vector<JournalRestart> restarts;  // earlier restarts' replays
  std::uint64_t complete_bytes = 0;      // the file's length up to the last complete tick
};

// Reads every complete tick of the journal at `path` (none if the file does not exist). A malformed
// or cut-off record ends the reading there (what follows is the dead process's unfinished tick).
[[nodiscard]] JournalContents read_journal(const std::string& path);

class JournalWriter {
 public:
  // Opens `path` for appending, first cutting it to `keep_bytes` (a dead process's unfinished tail;
  // read_journal's complete_bytes), or creating it. Throws std::runtime_error naming the file.
  JournalWriter(const std::string& path, std::uint64_t keep_bytes = 0);
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;

  void clock(std::uint32_t tick, const std::string& cdr);
  void message(std::uint32_t tick, int order, const std::string& cdr);
  void tick_end(std::uint32_t tick);  // and flushes: the tick survives a crash of the process
  void restart(std::uint32_t tick, const JournalRestart& r);

 private:
  void record(std::uint8_t kind, std::uint32_t tick, std::uint32_t order, const std::string& bytes);
  std::string path_;
  std::FILE* file_ = nullptr;
};

}  // namespace swarm::comm
