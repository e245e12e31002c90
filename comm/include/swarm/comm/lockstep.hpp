// The lockstep protocol: every process of a run steps through the same ticks, and a tick's
// outcome never depends on thread timing, so one scenario + seed gives one result on any machine.
//
// The simulator is the clock master (LockstepClock); every other process is a LockstepAgent:
//
//   sim:    deliver motion due by k -> move, scan -> send Sense(k) -> publish Clock(k) -> wait Done(k)
//   agent:  wait Clock(k) -> wait until every message due by k is here -> handlers, step -> Done(k)
//
// A conservative barrier, as in parallel discrete-event simulation: each Done(k) says how many
// messages its sender sent to each agent during tick k; the clock master sums them and puts into
// Clock(k) how many messages each agent must hold before acting at k (all agent messages stamped
// before k plus the simulator's own messages stamped k). DDS may deliver them in any order and
// at any time; the mailbox holds each until its deliver tick (link.hpp) and hands the due ones
// over sorted by (deliver tick, subscription order, sender, sequence number).
//
//   LockstepAgent agent(bus, topology, links, self);   // bus: a Participant (DDS) or a FakeBus
//   agent.subscribe<msgs::MapPatch>(topic::patch_up(g), LinkClass::MemberLeader,
//                                   [&](const msgs::MapPatch& p) { node.on_patch(p); });
//   auto& out = agent.advertise<msgs::MapPatch>(topic::kPatchGcs, LinkClass::LeaderGcs, {gcs});
//   agent.announce_ready(timeout);
//   while (const msgs::Clock* clock = agent.begin_tick()) { node.step(*clock); agent.end_tick(); }
//
// Handlers run on the caller's thread inside begin_tick; DDS threads only count and enqueue.
//
// Start-up: discovery is not symmetric in time. A writer may see its reader a few milliseconds
// before the reader sees the writer, and a VOLATILE reader misses what was written meanwhile. So
// an agent announces itself ready only once its writers have matched their readers AND its
// readers have matched their writers (subscribe's `writers`), and it repeats the announcement
// until the first clock comes (the simulator's reader may be the late side).
//
// Restart: a process that dies can be started again as the same agent. It first replays its input
// journal (journal.hpp, written by journal_to()) to rebuild the old process's state, its sends
// muted, then announces itself again (rejoin()). The clock master takes a Ready from a new writer
// of a running agent for a restart: from its next clock J on it waits for the agent again and
// counts its messages afresh (Clock.counted_from[a] = J; expected[a] = the messages stamped from J
// on), and the new process counts only those too, so neither needs what the dead one had heard.
//
// Real-time mode (LinkTable::realtime, for deployment): the clock ticks at a fixed wall rate and
// waits for nobody; messages are held for their link's delay in milliseconds; an agent that falls
// behind skips to the newest tick. Runs are then not reproducible, by nature.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "swarm/comm/cdr.hpp"
#include "swarm/comm/endpoint.hpp"
#include "swarm/comm/journal.hpp"
#include "swarm/comm/link.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/comm/traffic.hpp"

namespace swarm::comm {

inline constexpr std::uint32_t kReadyTick = 0xFFFFFFFFu;

// How long a process waits for its peers before it gives up and names what it waited for.
std::chrono::seconds stall_timeout();  // $SWARM_STALL_TIMEOUT seconds, default 60

class Mailbox {
 public:
  Mailbox(Bus& bus, const Topology& topology, const LinkTable& links, AgentId self);
  virtual ~Mailbox();
  Mailbox(const Mailbox&) = delete;
  Mailbox& operator=(const Mailbox&) = delete;

  template <class T>
  class Outlet;

  // Messages of type T on `topic_name` are held until due and then given to `handler`. Under
  // emulated loss a reliable topic's message arrives late (retransmitted), a best-effort one not.
  // `writers`: how many agents write this topic in the run; readiness waits until this reader has
  // matched them all (0 = do not wait).
  template <class T>
  void subscribe(const std::string& topic_name, LinkClass link, std::function<void(const T&)> handler,
                 Delivery delivery = Delivery::Reliable, int writers = 0);

  // An outlet stamps, emulates the link, accounts and writes. `receivers` are the agents that
  // subscribe to this topic (the barrier counts one message per receiver).
  template <class T>
  Outlet<T>& advertise(const std::string& topic_name, LinkClass link, std::vector<AgentId> receivers);

  // Whether this mailbox already reads / writes a topic (test stand-ins complete a role's set).
  bool subscribes(const std::string& topic_name) const;
  bool advertises(const std::string& topic_name) const;

  // End of run: this agent's traffic and role numbers, sent to the GCS (which calls make_report
  // for its own). Waits briefly for the GCS to acknowledge. In real time it first waits until no
  // message has arrived for max(250 ms, 5 ticks), at most 3 s, so that what peers sent in their
  // last tick is counted as received.
  void send_report(const std::string& role, const std::string& extra_json);
  msgs::AgentReport make_report(const std::string& role, const std::string& extra_json);

  std::uint32_t tick() const { return tick_; }
  AgentId self() const { return self_; }
  // Bookkeeping held for ticks not yet passed (flat over a run: for tests).
  std::size_t arrival_ticks_held() const;
  // A received message that could not be decoded: logged and counted, never acted on. Also for
  // the nodes, which decode some messages after the handler queued them.
  void drop_malformed(const std::string& topic_family, AgentId sender, const std::string& why);
  std::uint64_t malformed_messages() const { return malformed_; }
  // From now on every message handed to a handler is kept in the journal at `path` (cut first to
  // `keep_bytes`: see JournalWriter), and LockstepAgent adds each tick's clock and end.
  void journal_to(const std::string& path, std::uint64_t keep_bytes = 0);
  // While replaying a journal: sends are counted and numbered but not written.
  bool replaying() const { return replaying_; }
  const Topology& topology() const { return topology_; }
  TrafficAccount& traffic() { return traffic_; }
  Bus& bus() { return bus_; }

 protected:
  // Blocks until `expected` messages counted for tick k are here (throws after stall_timeout()),
  // then runs the handlers of every held message due by k in deterministic order.
  void deliver_due(std::uint32_t k, std::uint64_t expected);
  // Real-time mode: runs the handlers of every held message whose delay has passed.
  void deliver_due_now();
  // Messages sent per receiver since the last call; resets the counts.
  std::vector<std::uint32_t> take_sent_counts();
  // Every outlet sees its readers and every reader its writers (see Start-up above).
  bool outlets_matched(std::string* missing) const;
  std::uint64_t arrivals_counted_for(std::uint32_t k);  // caller holds mutex_
  // A restarted process joins at tick k: only messages stamped from k on count (caller: no lock).
  void count_from(std::uint32_t k);
  // Hands a journalled message to the handler of subscription `order`, as on arrival.
  void replay_message(int order, const std::string& bytes);
  std::unique_ptr<JournalWriter> journal_;
  std::atomic<bool> journaling_{false};
  bool replaying_ = false;

  Bus& bus_;
  Topology topology_;
  LinkTable links_;
  AgentId self_;
  // Written by the owner's loop, read by DDS threads (LockstepClock::on_done): atomic.
  std::atomic<std::uint32_t> tick_{0};
  LinkSender link_sender_;
  TrafficAccount traffic_;

  mutable std::mutex mutex_;
  std::condition_variable arrived_;

 private:
  struct Held {
    std::uint32_t deliver_tick;
    std::chrono::steady_clock::time_point due;  // real-time mode
    int order;  // subscription index
    AgentId sender;
    std::uint32_t seq;
    std::function<void()> run;
    std::function<std::string()> bytes;  // the message's CDR, when journalling
    std::uint32_t stamp_tick;
  };
  struct ReaderEntry {
    std::shared_ptr<void> reader;
    std::function<int()> matched;
    int writers;
    std::string name;
    std::function<void(const std::string&)> replay;  // a journalled message to the handler
  };
  struct OutletBase {
    virtual ~OutletBase() = default;
    virtual int matched() const = 0;
    virtual int expected_readers() const = 0;
    virtual const std::string& name() const = 0;
  };

  // The held messages `is_due` selects, removed from held_ (caller holds mutex_).
  std::vector<Held> take_held(const std::function<bool(const Held&)>& is_due);
  // Runs them in the one deterministic order: `key` (deliver tick, or due time in real time),
  // then subscription order, sender, sequence number.
  template <class Key>
  void run_in_order(std::vector<Held>& due, Key key);

  // Counts one arrival for the barrier; keeps it for delivery (at deliver_tick in lockstep, after
  // delay_ms in real time) unless the link dropped it.
  void arrive(const msgs::Stamp& stamp, std::uint32_t deliver_tick, double delay_ms, bool keep, int order,
              std::function<void()> run, std::function<std::string()> bytes);

  void wait_for_quiet();

  std::vector<Held> held_;
  std::chrono::steady_clock::time_point last_arrival_{};
  std::uint64_t malformed_ = 0;
  // Arrivals counted for the barrier: per stamp tick for the ticks still ahead, and one running
  // total for those behind (folded in as the ticks pass, so memory stays flat over long runs).
  struct Arrivals {
    std::uint64_t below = 0;  // arrivals stamped before `watermark`
    std::uint32_t watermark = 0;
    std::uint32_t floor = 0;  // arrivals stamped before it are not counted (a restarted process)
    std::map<std::uint32_t, std::uint64_t> by_tick;
    void add(std::uint32_t tick) {
      if (tick >= floor) tick < watermark ? ++below : ++by_tick[tick];
    }
    std::uint64_t count_before(std::uint32_t k);  // folds every tick < k into `below`
    void count_from(std::uint32_t k);              // forgets every arrival stamped before k
  };
  Arrivals agent_arrivals_;  // from agents: due before acting at k if stamped < k
  Arrivals sim_arrivals_;    // from the sim: due if stamped <= k
  std::vector<std::uint32_t> sent_counts_;
  std::vector<ReaderEntry> readers_;
  std::deque<std::unique_ptr<OutletBase>> outlets_;
  std::unique_ptr<Writer<msgs::AgentReport>> report_writer_;
  int subscriptions_ = 0;
};

template <class T>
class Mailbox::Outlet : public Mailbox::OutletBase {
 public:
  Outlet(Mailbox& box, const std::string& topic_name, LinkClass link, std::vector<AgentId> receivers)
      : box_(box),
        writer_(box.bus_, topic_name),
        name_(topic_name),
        family_(topic::family(topic_name)),
        link_(link),
        topic_hash_(hash_string(topic_name)),
        receivers_(std::move(receivers)) {}

  // Stamps and sends; the message's stamp is overwritten.
  void send(T& msg) {
    msgs::Stamp& s = msg.header();
    const std::size_t bytes = wire_size(msg);
    s.tick(box_.tick_);
    s.sender(box_.self_);
    s.seq(seq_);
    s.deliver_tick(box_.link_sender_.deliver_tick(link_, box_.tick_, bytes, topic_hash_, seq_,
                                                  box_.self_ == box_.topology_.sim()));
    ++seq_;
    box_.traffic_.sent(family_, link_name(link_), bytes, receivers_.size(), box_.link_sender_.last_queued_ticks());
    if (box_.replaying_) return;  // the old process sent it (and the clock master counted it)
    writer_.write(msg);
    {
      std::lock_guard<std::mutex> lock(box_.mutex_);
      for (AgentId r : receivers_) box_.sent_counts_[r] += 1;
    }
  }
  int matched() const override { return writer_.matched(); }
  int expected_readers() const override { return static_cast<int>(receivers_.size()); }
  bool same_route(LinkClass link, const std::vector<AgentId>& receivers) const {
    return link == link_ && receivers == receivers_;
  }
  const std::string& name() const override { return name_; }
  Writer<T>& writer() { return writer_; }

 private:
  Mailbox& box_;
  Writer<T> writer_;
  std::string name_;
  std::string family_;
  LinkClass link_;
  std::uint64_t topic_hash_;
  std::vector<AgentId> receivers_;
  std::uint32_t seq_ = 0;
};

template <class T>
void Mailbox::subscribe(const std::string& topic_name, LinkClass link, std::function<void(const T&)> handler,
                        Delivery delivery, int writers) {
  const int order = subscriptions_++;
  const std::uint64_t topic_hash = hash_string(topic_name);
  const std::string family = topic::family(topic_name);
  auto reader = std::make_shared<Reader<T>>(
      bus_, topic_name, [this, link, order, topic_hash, family, handler, delivery](T&& msg) {
        const msgs::Stamp& h = msg.header();
        // An agent that both writes and reads a topic (a group's candidate leaders: leadership.hpp)
        // never receives its own messages: no outlet counts it among their receivers.
        if (h.sender() == self_) return;
        const std::size_t bytes = wire_size(msg);
        const std::uint32_t lost = lost_transmissions(links_, link, h.sender(), topic_hash, h.seq(), self_);
        const bool dropped = lost > 0 && delivery == Delivery::BestEffort;
        // A best-effort message is given up after its first lost transmission.
        traffic_.received(family, link_name(link), bytes, dropped ? 1 : lost, dropped);
        const LinkParams& p = links_[link];
        const std::uint32_t retry_ticks = dropped ? 0 : lost * p.retransmit_ticks;
        const double delay_ms = p.delay_ms + retry_ticks * links_.tick_ms;
        const std::uint32_t deliver =
            after_cuts(links_, link, h.sender(), self_, h.tick(), h.deliver_tick() + retry_ticks);
        auto shared = std::make_shared<T>(std::move(msg));
        std::function<std::string()> cdr;
        if (journaling_) cdr = [shared] { return to_cdr(*shared); };
        arrive(shared->header(), deliver, delay_ms, !dropped, order, [this, handler, shared, family] {
          // A message that does not decode (a peer's bug, or bytes from outside the swarm) is
          // dropped with a log line; the process goes on.
          try {
            handler(*shared);
          } catch (const std::exception& e) {
            drop_malformed(family, shared->header().sender(), e.what());
          }
        }, std::move(cdr));
      });
  auto replay = [this, handler, family, link](const std::string& bytes) {
    const T msg = from_cdr<T>(bytes);
    traffic_.received(family, link_name(link), wire_size(msg), 0, false);
    try {
      handler(msg);
    } catch (const std::exception& e) {
      drop_malformed(family, msg.header().sender(), e.what());
    }
  };
  readers_.push_back({reader, [reader] { return reader->matched(); }, writers, topic_name, std::move(replay)});
}

template <class T>
Mailbox::Outlet<T>& Mailbox::advertise(const std::string& topic_name, LinkClass link,
                                       std::vector<AgentId> receivers) {
  // One outlet per topic and agent: the parts of one agent (a candidate's member and leader
  // sides) share it, so its sequence numbers stay one series.
  for (const auto& o : outlets_) {
    if (o->name() != topic_name) continue;
    auto* same = dynamic_cast<Outlet<T>*>(o.get());
    if (same == nullptr || !same->same_route(link, receivers)) {
      throw std::logic_error(topology_.name_of(self_) + " advertises " + topic_name + " twice, differently");
    }
    return *same;
  }
  auto outlet = std::make_unique<Outlet<T>>(*this, topic_name, link, std::move(receivers));
  Outlet<T>& ref = *outlet;
  outlets_.push_back(std::move(outlet));
  return ref;
}

// A robot's or the GCS's side of the protocol.
class LockstepAgent : public Mailbox {
 public:
  LockstepAgent(Bus& bus, const Topology& topology, const LinkTable& links, AgentId self);
  ~LockstepAgent() override;

  // Waits until every outlet sees all its receivers, then tells the clock master this agent is
  // ready. Call after every subscribe/advertise.
  void announce_ready();
  // Blocks for the next tick; nullptr once the run has stopped. Handlers of due messages have run
  // when it returns. The pointer stays valid until the next call.
  const msgs::Clock* begin_tick();
  void end_tick(bool mission_complete = false);
  // The clock of the tick being processed, already while its due messages' handlers run.
  const msgs::Clock& clock() const { return current_; }

  // A restarted process (see Restart above), before announce_ready: runs `step` on every complete
  // tick of the journal at `path` with its messages handed to their handlers, sends muted; then
  // journals on after them (journal_to) and marks the restart. Returns what it replayed.
  // Returns every restart the journal records, this one last.
  std::vector<JournalRestart> replay_journal(const std::string& path,
                                             const std::function<void(const msgs::Clock&)>& step);
  // This process is a new one of an agent that was running: it counts only messages stamped from
  // the tick the clock master names it back at (Clock.counted_from, after the replayed ticks) and
  // acts from the first clock it has from then on.
  void rejoin() { rejoining_ = true; }

 private:
  void say_ready();
  void wait_for_join();  // a rejoining process: until the clock that admits it is here
  bool rejoining_ = false;
  std::optional<std::uint32_t> replayed_to_;  // the last tick the journal held

  std::unique_ptr<Writer<msgs::Done>> done_writer_;
  std::unique_ptr<Reader<msgs::Clock>> clock_reader_;
  // Asserts done_writer_'s liveliness every 250 ms from its own thread, so that a busy agent is
  // never taken for dead but a crashed or cut-off one is (the heartbeat profile's 1 s lease).
  std::jthread liveliness_;
  std::map<std::uint32_t, msgs::Clock> clocks_;  // guarded by mutex_
  std::optional<std::uint32_t> next_tick_;
  msgs::Clock current_;
};

// An agent's whole life: announce, then step every tick until the simulator stops the run.
// `step` returns true when the mission is complete (only the GCS ever says so).
void run_lockstep(LockstepAgent& agent, const std::function<bool(const msgs::Clock&)>& step);

// An agent that stopped answering: it never finished `tick` (the one after its last Done), and DDS
// reported its heartbeat writer's liveliness lost (1 s lease, deploy/fastdds_loopback.xml)
// `detection_seconds` after that last Done. An agent
// whose Done messages come back (a healed link) is re-admitted at `rejoined_tick`.
struct AgentLoss {
  AgentId agent = 0;
  std::uint32_t tick = 0;
  double detection_seconds = 0;
  std::optional<std::uint32_t> rejoined_tick;
  bool restarted = false;  // it came back as a new process (see Restart above), not a healed link
};

// The simulator's side: it owns the clock and the barrier counts.
class LockstepClock : public Mailbox {
 public:
  LockstepClock(Bus& bus, const Topology& topology, const LinkTable& links);
  ~LockstepClock() override;

  // Blocks until every agent has announced itself ready (throws after stall_timeout()).
  void wait_ready();
  // Delivers the messages (motion commands) due at tick k to their handlers.
  void begin_tick(std::uint32_t k);
  // Publishes Clock(k) with the barrier counts and each group's leader (the succession rule of
  // leadership.hpp applied to `robots`); call after sending this tick's sensor data. The
  // stop waits up to 5 s for its acknowledgement when an agent is lost (it may be only cut off).
  // `tally` goes to watchers as it is; the clock adds every agent's sent bytes per link class.
  void publish_clock(std::uint32_t k, const std::vector<msgs::RobotState>& robots, bool stop, const msgs::RunTally& tally = {});
  // Blocks until every living agent has finished tick k; returns true when the GCS reported the
  // mission complete. An agent whose heartbeat DDS declares lost is no longer waited for until
  // its Done messages come back (see losses()). Throws, naming the agents it waited for, after
  // stall_timeout().
  bool wait_done(std::uint32_t k);
  // Ends the run early (the simulator's process was asked to stop, app/stop_signal.hpp): from
  // any thread. wait_done returns at once, and wait_ready throws, so that the simulator publishes
  // the stop and every agent reports what it has up to this tick.
  void request_stop();
  [[nodiscard]] bool stop_requested() const;
  std::vector<AgentLoss> losses() const;
  bool is_lost(AgentId a) const;
  // Ticks whose Done markers are held (at most the ones not finished yet: for tests).
  std::size_t done_ticks_held() const;

 private:
  void on_done(msgs::Done&& d, WriterId writer);
  void on_liveliness_lost(WriterId writer);

  std::unique_ptr<Writer<msgs::Clock>> clock_writer_;
  std::unique_ptr<Reader<msgs::Done>> heartbeat_;
  // guarded by mutex_:
  std::vector<std::uint64_t> from_agents_;        // cumulative messages agents sent to each agent
  std::map<std::uint32_t, std::vector<bool>> done_;  // tick -> which agents reported (ticks not yet finished)
  std::vector<bool> ready_;
  bool complete_ = false;
  std::vector<std::uint64_t> from_sim_;  // cumulative messages the sim sent to each agent
  std::chrono::steady_clock::time_point realtime_start_{};
  std::map<WriterId, AgentId> writer_agent_;
  std::vector<bool> lost_;
  std::vector<AgentLoss> losses_;
  bool stopped_ = false;
  std::vector<std::chrono::steady_clock::time_point> last_heard_;  // per agent: its latest Done
  std::vector<std::uint32_t> next_undone_;                          // per agent: tick after its latest Done
  std::vector<AgentId> leaders_;  // each group's leader in the latest clock (leadership.hpp)
  // Bytes sent per link class: each agent's current process's (its latest Done), and those of
  // processes that restarted since.
  std::vector<std::vector<std::uint64_t>> agent_bytes_;
  std::vector<std::uint64_t> retired_bytes_ = std::vector<std::uint64_t>(kLinkClasses, 0);
  // Restarts: each agent's current writer of Done (an older one is a dead process), whether a new
  // process waits to be admitted, and from which tick and which count on each one's counts run.
  std::map<AgentId, WriterId> writer_of_;
  std::vector<bool> restarting_;
  std::vector<std::chrono::steady_clock::time_point> restart_heard_;  // its new process's first hello
  static constexpr std::chrono::milliseconds kRestartSettle{500};
  std::vector<std::uint32_t> counted_from_;
  std::vector<std::uint64_t> base_;
  bool started_ = false;  // the first clock is out
  bool stop_requested_ = false;
};

}  // namespace swarm::comm
