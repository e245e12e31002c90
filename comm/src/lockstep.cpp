#include "swarm/comm/lockstep.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "swarm/comm/leadership.hpp"

namespace swarm::comm {

std::chrono::seconds stall_timeout() {
  if (const char* v = std::getenv("SWARM_STALL_TIMEOUT")) {
    const long s = std::strtol(v, nullptr, 10);
    if (s > 0) return std::chrono::seconds(s);
  }
  return std::chrono::seconds(60);
}

Mailbox::Mailbox(Bus& bus, const Topology& topology, const LinkTable& links, AgentId self)
    : bus_(bus),
      topology_(topology),
      links_(links),
      self_(self),
      link_sender_(links_),
      sent_counts_(topology.agents(), 0) {
  if (self != topology.gcs()) report_writer_ = std::make_unique<Writer<msgs::AgentReport>>(bus, topic::kReport);
}

msgs::AgentReport Mailbox::make_report(const std::string& role, const std::string& extra_json) {
  msgs::AgentReport report;
  report.agent(self_);
  report.role(role);
  report.extra_json(extra_json);
  for (const auto& [key, c] : traffic_.snapshot()) {
    msgs::TopicTraffic t;
    t.topic(key.first);
    t.link(key.second);
    t.sent_messages(c.sent_messages);
    t.sent_bytes(c.sent_bytes);
    t.addressed_messages(c.addressed_messages);
    t.received_messages(c.received_messages);
    t.received_bytes(c.received_bytes);
    t.lost_transmissions(c.lost_transmissions);
    t.dropped_messages(c.dropped_messages);
    t.queued_ticks(c.queued_ticks);
    report.traffic().push_back(t);
  }
  return report;
}

void Mailbox::send_report(const std::string& role, const std::string& extra_json) {
  if (!report_writer_) return;
  if (links_.realtime) wait_for_quiet();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (report_writer_->matched() < 1 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  msgs::AgentReport report = make_report(role, extra_json);
  report_writer_->write(report);
  report_writer_->wait_acknowledged(std::chrono::seconds(10));
}

void Mailbox::wait_for_quiet() {
  // A peer still finishing the tick before the stop may send after this agent read the stop;
  // its message is counted on arrival, so wait until nothing has arrived for a few ticks.
  const auto quiet = std::max(std::chrono::milliseconds(250),
                              std::chrono::milliseconds(static_cast<int>(5 * links_.tick_ms)));
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  std::unique_lock<std::mutex> lock(mutex_);
  while (std::chrono::steady_clock::now() < give_up) {
    const auto until = std::min(give_up, last_arrival_ + quiet);
    if (std::chrono::steady_clock::now() >= until) return;
    arrived_.wait_until(lock, until);
  }
}

Mailbox::~Mailbox() {
  // Readers first: their callbacks touch this object.
  readers_.clear();
  outlets_.clear();
  report_writer_.reset();
}

void Mailbox::arrive(const msgs::Stamp& stamp, std::uint32_t deliver_tick, double delay_ms, bool keep, int order,
                     std::function<void()> run, std::function<std::string()> bytes) {
  const auto due = std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double, std::milli>(delay_ms));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_arrival_ = std::chrono::steady_clock::now();
    // Real time waits for nobody, so nothing is counted (the counts would only grow).
    if (!links_.realtime) (stamp.sender() == topology_.sim() ? sim_arrivals_ : agent_arrivals_).add(stamp.tick());
    if (keep) {
      held_.push_back({deliver_tick, due, order, stamp.sender(), stamp.seq(), std::move(run), std::move(bytes), stamp.tick()});
    }
  }
  arrived_.notify_all();
}

std::uint64_t Mailbox::Arrivals::count_before(std::uint32_t k) {
  if (k > watermark) {
    for (auto it = by_tick.begin(); it != by_tick.end() && it->first < k; it = by_tick.erase(it)) below += it->second;
    watermark = k;
  }
  std::uint64_t n = below;
  for (auto it = by_tick.begin(); it != by_tick.end() && it->first < k; ++it) n += it->second;
  return n;
}

void Mailbox::Arrivals::count_from(std::uint32_t k) {
  by_tick.erase(by_tick.begin(), by_tick.lower_bound(k));
  below = 0;
  watermark = k;
  floor = k;
}

void Mailbox::count_from(std::uint32_t k) {
  std::lock_guard<std::mutex> lock(mutex_);
  agent_arrivals_.count_from(k);
  sim_arrivals_.count_from(k);
  // What came before k is the dead process's business (its journal replayed it), and whether it
  // reached this one depended on timing: dropped, so the inputs from k on are those counted.
  std::erase_if(held_, [k](const Held& h) { return h.stamp_tick < k; });
}

void Mailbox::journal_to(const std::string& path, std::uint64_t keep_bytes) {
  journal_ = std::make_unique<JournalWriter>(path, keep_bytes);
  journaling_ = true;
}

void Mailbox::replay_message(int order, const std::string& bytes) {
  if (order < 0 || static_cast<std::size_t>(order) >= readers_.size()) {
    throw std::runtime_error(topology_.name_of(self_) + ": the journal names subscription " + std::to_string(order) +
                             " of " + std::to_string(readers_.size()) + " (a journal of another build or role?)");
  }
  readers_[static_cast<std::size_t>(order)].replay(bytes);
}

void Mailbox::drop_malformed(const std::string& topic_family, AgentId sender, const std::string& why) {
  ++malformed_;
  std::fprintf(stderr, "%s: tick %u: dropped a malformed %s message from %s: %s\n", topology_.name_of(self_).c_str(),
               tick_.load(), topic_family.c_str(),
               sender < topology_.agents() ? topology_.name_of(sender).c_str() : "an unknown sender", why.c_str());
}

std::size_t Mailbox::arrival_ticks_held() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return agent_arrivals_.by_tick.size() + sim_arrivals_.by_tick.size() + held_.size();
}

std::uint64_t Mailbox::arrivals_counted_for(std::uint32_t k) {
  // Agents' messages stamped before k, the simulator's stamped up to k (see the file comment).
  return agent_arrivals_.count_before(k) + sim_arrivals_.count_before(k + 1);
}

void Mailbox::deliver_due(std::uint32_t k, std::uint64_t expected) {
  if (links_.realtime) {
    deliver_due_now();
    return;
  }
  std::vector<Held> due;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!arrived_.wait_for(lock, stall_timeout(), [&] { return arrivals_counted_for(k) >= expected; })) {
      std::ostringstream msg;
      msg << topology_.name_of(self_) << ": at tick " << k << " still waiting for messages: "
          << arrivals_counted_for(k) << " of " << expected << " arrived after " << stall_timeout().count()
          << " s (a peer process stalled or died)";
      throw std::runtime_error(msg.str());
    }
    due = take_held([k](const Held& h) { return h.deliver_tick <= k; });
  }
  run_in_order(due, [](const Held& h) { return h.deliver_tick; });
}

void Mailbox::deliver_due_now() {
  const auto now = std::chrono::steady_clock::now();
  std::vector<Held> due;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    due = take_held([now](const Held& h) { return h.due <= now; });
  }
  run_in_order(due, [](const Held& h) { return h.due; });
}

std::vector<Mailbox::Held> Mailbox::take_held(const std::function<bool(const Held&)>& is_due) {
  auto split = std::partition(held_.begin(), held_.end(), [&](const Held& h) { return !is_due(h); });
  std::vector<Held> due(std::make_move_iterator(split), std::make_move_iterator(held_.end()));
  held_.erase(split, held_.end());
  return due;
}

template <class Key>
void Mailbox::run_in_order(std::vector<Held>& due, Key key) {
  std::sort(due.begin(), due.end(), [&](const Held& a, const Held& b) {
    if (key(a) != key(b)) return key(a) < key(b);
    if (a.order != b.order) return a.order < b.order;
    if (a.sender != b.sender) return a.sender < b.sender;
    return a.seq < b.seq;
  });
  for (Held& h : due) {
    if (journal_ && h.bytes) journal_->message(tick_, h.order, h.bytes());
    h.run();
  }
}

std::vector<std::uint32_t> Mailbox::take_sent_counts() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::uint32_t> out(topology_.agents(), 0);
  out.swap(sent_counts_);
  return out;
}

bool Mailbox::subscribes(const std::string& topic_name) const {
  return std::any_of(readers_.begin(), readers_.end(), [&](const ReaderEntry& r) { return r.name == topic_name; });
}

bool Mailbox::advertises(const std::string& topic_name) const {
  return std::any_of(outlets_.begin(), outlets_.end(), [&](const auto& o) { return o->name() == topic_name; });
}

bool Mailbox::outlets_matched(std::string* missing) const {
  // An agent that both writes and reads a topic (a candidate leader) has its own writer matched by
  // its own reader: DDS matches the endpoints of one participant with each other, at once. The
  // writers and readers expected are the other agents', so the agent's own match is not counted;
  // counted, it let an agent announce itself ready before a slow peer (a late DDS-Security
  // handshake) had matched, and the messages of tick 0 never reached that peer.
  for (const auto& r : readers_) {
    const int others = r.matched() - (advertises(r.name) ? 1 : 0);
    if (others < r.writers) {
      if (missing != nullptr) {
        *missing = r.name + " (" + std::to_string(std::max(others, 0)) + " of " + std::to_string(r.writers) + " writers)";
      }
      return false;
    }
  }
  for (const auto& o : outlets_) {
    const int others = o->matched() - (subscribes(o->name()) ? 1 : 0);
    if (others < o->expected_readers()) {
      if (missing != nullptr) {
        *missing = o->name() + " (" + std::to_string(std::max(others, 0)) + " of " +
                   std::to_string(o->expected_readers()) + " readers)";
      }
      return false;
    }
  }
  return true;
}

namespace {

// A start-up wait that stalls says what it waits for and how far each DDS peer got (discovered,
// authenticated: peers.hpp), every 10 s and in its final error, so a stuck secure handshake names
// the peer and the step instead of only a topic.
class StartupWait {
 public:
  StartupWait(const Bus& bus, std::string who) : bus_(bus), who_(std::move(who)) {}

  // What to print while `missing` is still awaited; throws once the stall timeout has passed.
  void check(const std::string& doing, const std::string& missing) {
    const auto now = std::chrono::steady_clock::now();
    if (now > deadline_) {
      throw std::runtime_error(who_ + ": " + doing + " did not complete in " + std::to_string(stall_timeout().count()) +
                               " s; still waiting for " + missing + ". DDS peers: " + peers());
    }
    if (now >= next_note_) {
      const auto waited = std::chrono::duration_cast<std::chrono::seconds>(now - start_).count();
      std::fprintf(stderr, "%s: %s: still waiting for %s after %lld s. DDS peers: %s\n", who_.c_str(), doing.c_str(),
                   missing.c_str(), static_cast<long long>(waited), peers().c_str());
      next_note_ = now + kNoteEvery;
    }
  }

 private:
  static constexpr std::chrono::seconds kNoteEvery{10};
  std::string peers() const { return describe_peers(bus_.peers(), bus_.secure()); }

  const Bus& bus_;
  const std::string who_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  const std::chrono::steady_clock::time_point deadline_ = start_ + stall_timeout();
  std::chrono::steady_clock::time_point next_note_ = start_ + kNoteEvery;
};

}  // namespace

// ---------------------------------------------------------------------------------------------
LockstepAgent::LockstepAgent(Bus& bus, const Topology& topology, const LinkTable& links, AgentId self)
    : Mailbox(bus, topology, links, self) {
  done_writer_ = std::make_unique<Writer<msgs::Done>>(bus, topic::kDone, EndpointKind::Heartbeat);
  clock_reader_ = std::make_unique<Reader<msgs::Clock>>(bus, topic::kClock, [this](msgs::Clock&& c) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      clocks_.emplace(c.tick(), std::move(c));
    }
    arrived_.notify_all();
  });
  liveliness_ = std::jthread([this](std::stop_token stop) {
    std::mutex m;
    std::condition_variable_any wake;
    std::unique_lock<std::mutex> lock(m);
    while (!stop.stop_requested()) {
      done_writer_->assert_liveliness();
      wake.wait_for(lock, stop, std::chrono::milliseconds(250), [] { return false; });
    }
  });
}

LockstepAgent::~LockstepAgent() {
  liveliness_ = {};  // stops and joins before the writer goes
  clock_reader_.reset();
}

void LockstepAgent::announce_ready() {
  StartupWait wait(bus_, topology_.name_of(self_));
  std::string missing;
  for (;;) {
    if (done_writer_->matched() < 1 || clock_reader_->matched() < 1) {
      missing = "the simulator (done, clock)";
    } else if (outlets_matched(&missing)) {
      break;
    }
    wait.check("DDS discovery", missing);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  say_ready();
}

void LockstepAgent::say_ready() {
  msgs::Done hello;
  hello.agent(self_);
  hello.tick(kReadyTick);
  done_writer_->write(hello);
}

void LockstepAgent::wait_for_join() {
  std::unique_lock<std::mutex> lock(mutex_);
  // Admitted: a clock names a tick to count from after the ticks the journal held (an earlier one
  // was a dead process's). It may name a clock this process never heard (DDS had not matched it
  // yet): then it starts at the first one it has.
  std::uint32_t count_from_tick = 0;
  auto admitted = [&]() -> std::optional<std::uint32_t> {
    for (const auto& [tick, c] : clocks_) {
      if (c.stop()) return tick;
      if (c.counted_from().size() <= self_) continue;
      const std::uint32_t from = c.counted_from()[self_];
      if (from > 0 && (!replayed_to_ || from > *replayed_to_)) {
        count_from_tick = from;
        return tick;
      }
    }
    return std::nullopt;
  };
  const auto deadline = std::chrono::steady_clock::now() + stall_timeout();
  std::optional<std::uint32_t> join;
  while (!(join = admitted())) {
    if (std::chrono::steady_clock::now() > deadline) {
      throw std::runtime_error(topology_.name_of(self_) + ": the simulator did not admit this restarted process in " +
                               std::to_string(stall_timeout().count()) + " s");
    }
    lock.unlock();
    say_ready();  // until the clock master has heard it
    lock.lock();
    arrived_.wait_for(lock, std::chrono::milliseconds(100));
  }
  clocks_.erase(clocks_.begin(), clocks_.lower_bound(*join));
  next_tick_ = *join;
  rejoining_ = false;
  lock.unlock();
  count_from(count_from_tick);
  std::fprintf(stderr, "%s: joins the run again at tick %u (counting from tick %u)\n", topology_.name_of(self_).c_str(),
               *join, count_from_tick);
}

std::vector<JournalRestart> LockstepAgent::replay_journal(const std::string& path,
                                                          const std::function<void(const msgs::Clock&)>& step) {
  const auto t0 = std::chrono::steady_clock::now();
  const JournalContents j = read_journal(path);
  replaying_ = true;
  for (const JournalTick& t : j.ticks) {
    current_ = from_cdr<msgs::Clock>(t.clock);
    tick_ = t.tick;
    for (const JournalMessage& m : t.messages) replay_message(m.order, m.bytes);
    step(current_);
  }
  replaying_ = false;
  (void)take_sent_counts();
  JournalRestart r{static_cast<std::uint32_t>(j.ticks.size()),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
  if (!j.ticks.empty()) replayed_to_ = j.ticks.back().tick;
  journal_to(path, j.complete_bytes);
  journal_->restart(j.ticks.empty() ? 0 : j.ticks.back().tick, r);
  std::vector<JournalRestart> all = j.restarts;
  all.push_back(r);
  return all;
}

const msgs::Clock* LockstepAgent::begin_tick() {
  if (rejoining_) wait_for_join();
  {
    std::unique_lock<std::mutex> lock(mutex_);
    auto has_next = [&] {
      if (clocks_.empty()) return false;
      return !next_tick_ || clocks_.begin()->first >= *next_tick_ || clocks_.begin()->second.stop();
    };
    // Before the first clock, repeat the ready announcement: the simulator's reader may have
    // matched this agent's writer after the first one was written.
    const auto deadline = std::chrono::steady_clock::now() + stall_timeout();
    while (!next_tick_ && !has_next() && std::chrono::steady_clock::now() < deadline) {
      if (arrived_.wait_for(lock, std::chrono::milliseconds(100), has_next)) break;
      lock.unlock();
      say_ready();
      lock.lock();
    }
    if (!arrived_.wait_until(lock, deadline, has_next)) {
      throw std::runtime_error(topology_.name_of(self_) + ": no clock from the simulator for " +
                               std::to_string(stall_timeout().count()) + " s after tick " +
                               (next_tick_ ? std::to_string(*next_tick_) : std::string("start")));
    }
    // Real time: an agent that fell behind skips to the newest tick (a stop is never skipped).
    auto pick = clocks_.begin();
    if (links_.realtime) {
      pick = std::prev(clocks_.end());
      for (auto it = clocks_.begin(); it != clocks_.end(); ++it) {
        if (it->second.stop()) pick = it;
      }
    }
    current_ = std::move(pick->second);
    clocks_.erase(clocks_.begin(), std::next(pick));
  }
  if (current_.stop()) return nullptr;
  tick_ = current_.tick();
  next_tick_ = tick_ + 1;
  if (journal_) journal_->clock(tick_, to_cdr(current_));
  deliver_due(tick_, current_.expected().at(self_));
  return &current_;
}

void LockstepAgent::end_tick(bool mission_complete) {
  msgs::Done done;
  done.agent(self_);
  done.tick(tick_);
  done.sent(take_sent_counts());
  done.mission_complete(mission_complete);
  done.sent_bytes(traffic_.sent_bytes_by_link());
  // The tick is journalled whole before anyone hears it is done: a restart replays it.
  if (journal_) journal_->tick_end(tick_);
  done_writer_->write(done);
}

void run_lockstep(LockstepAgent& agent, const std::function<bool(const msgs::Clock&)>& step) {
  agent.announce_ready();
  while (const msgs::Clock* clock = agent.begin_tick()) agent.end_tick(step(*clock));
}

// ---------------------------------------------------------------------------------------------
LockstepClock::LockstepClock(Bus& bus, const Topology& topology, const LinkTable& links)
    : Mailbox(bus, topology, links, topology.sim()),
      from_agents_(topology.agents(), 0),
      ready_(topology.agents(), false),
      from_sim_(topology.agents(), 0),
      lost_(topology.agents(), false),
      last_heard_(topology.agents(), std::chrono::steady_clock::now()),
      next_undone_(topology.agents(), 0),
      leaders_(topology.leaders()),
      agent_bytes_(topology.agents(), std::vector<std::uint64_t>(kLinkClasses, 0)),
      restarting_(topology.agents(), false),
      restart_heard_(topology.agents()),
      counted_from_(topology.agents(), 0),
      base_(topology.agents(), 0) {
  ready_[topology.sim()] = true;
  clock_writer_ = std::make_unique<Writer<msgs::Clock>>(bus, topic::kClock);
  // The agents' Done heartbeats, and the bus's verdict on their liveliness.
  heartbeat_ = std::make_unique<Reader<msgs::Done>>(
      bus, topic::kDone, [this](msgs::Done&& d, WriterId w) { on_done(std::move(d), w); },
      [this](WriterId w) { on_liveliness_lost(w); }, EndpointKind::Heartbeat);
}

void LockstepClock::on_done(msgs::Done&& d, WriterId writer) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (d.agent() >= topology_.agents()) return;
    writer_agent_[writer] = d.agent();
    const AgentId a = d.agent();
    const bool newest = !writer_of_.count(a) || writer_of_[a] == writer;
    if (d.tick() == kReadyTick && started_ && !newest && !restarting_[a]) {
      // A new process of a running agent (Restart): waited for again from the next clock on.
      // If DDS has not declared the old one lost yet, it is lost now.
      if (!lost_[a]) losses_.push_back({a, next_undone_[a], 0.0, std::nullopt, false});
      lost_[a] = true;
      restarting_[a] = true;
      restart_heard_[a] = std::chrono::steady_clock::now();
      writer_of_[a] = writer;
      arrived_.notify_all();
      return;
    }
    if (!writer_of_.count(a)) writer_of_[a] = writer;
    if (!newest && d.tick() == kReadyTick) return;  // a restarted process repeating its hello
    last_heard_[d.agent()] = std::chrono::steady_clock::now();
    if (lost_[d.agent()] && d.tick() != kReadyTick && !restarting_[a]) {
      writer_of_[a] = writer;  // the same process, its session perhaps rediscovered
      // A lost agent that speaks again was cut off, not dead: its link healed. Waited for again.
      lost_[d.agent()] = false;
      for (auto it = losses_.rbegin(); it != losses_.rend(); ++it) {
        if (it->agent == d.agent()) {
          it->rejoined_tick = tick_;
          break;
        }
      }
    }
    if (d.tick() == kReadyTick) {
      ready_[d.agent()] = true;
    } else {
      // A rejoining agent works through the ticks it missed; those are over, so only their
      // message counts matter, not a done marker that nobody would ever erase.
      if (d.tick() >= tick_) {
        auto& seen = done_[d.tick()];
        if (seen.empty()) seen.assign(topology_.agents(), false);
        seen[d.agent()] = true;
      }
      next_undone_[d.agent()] = std::max(next_undone_[d.agent()], d.tick() + 1);
      // A restarted receiver counts only messages stamped from its join tick on: a late Done of an
      // earlier tick (an agent catching up after a cut) is not for it.
      for (std::size_t a = 0; a < d.sent().size() && a < from_agents_.size(); ++a) {
        if (d.tick() >= counted_from_[a]) from_agents_[a] += d.sent()[a];
      }
      if (newest && d.sent_bytes().size() == static_cast<std::size_t>(kLinkClasses)) {
        // Cumulative per process: a smaller count is a restarted process's, which began from 0.
        std::vector<std::uint64_t>& now = agent_bytes_[a];
        for (std::size_t c = 0; c < now.size(); ++c) {
          if (d.sent_bytes()[c] >= now[c]) continue;
          for (std::size_t l = 0; l < now.size(); ++l) retired_bytes_[l] += now[l];
          break;
        }
        now = d.sent_bytes();
      }
      if (d.mission_complete()) complete_ = true;
    }
  }
  arrived_.notify_all();
}

void LockstepClock::on_liveliness_lost(WriterId writer) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = writer_agent_.find(writer);
    // After the stop every agent leaves; that is not a loss. Nor is a restarted agent's old process.
    if (stopped_ || it == writer_agent_.end() || lost_[it->second]) return;
    if (writer_of_.count(it->second) && writer_of_[it->second] != writer) return;
    lost_[it->second] = true;
    const double waited =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_heard_[it->second]).count();
    losses_.push_back({it->second, next_undone_[it->second], waited, std::nullopt});
  }
  arrived_.notify_all();
}

std::vector<AgentLoss> LockstepClock::losses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return losses_;
}

std::size_t LockstepClock::done_ticks_held() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return done_.size();
}

bool LockstepClock::is_lost(AgentId a) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return lost_[a];
}

LockstepClock::~LockstepClock() { heartbeat_.reset(); }

void LockstepClock::wait_ready() {
  StartupWait wait(bus_, "sim");
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    std::string missing;
    for (int a = 0; a < topology_.agents(); ++a) {
      if (!ready_[a]) missing += (missing.empty() ? "" : ", ") + topology_.name_of(static_cast<AgentId>(a));
    }
    if (!missing.empty()) missing = "these processes to be ready: " + missing;
    bool outlets_ok = true;
    if (missing.empty()) {
      lock.unlock();
      outlets_ok = outlets_matched(&missing) && clock_writer_->matched() >= topology_.agents() - 1 &&
                   heartbeat_->matched() >= topology_.agents() - 1;
      if (outlets_ok) return;
      if (missing.empty()) missing = "clock readers";
      lock.lock();
    }
    if (stop_requested_) throw std::runtime_error("sim: asked to stop before the run started; waiting for " + missing);
    wait.check("start-up", missing);
    arrived_.wait_for(lock, std::chrono::milliseconds(5));
  }
}

void LockstepClock::request_stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_requested_ = true;
  }
  arrived_.notify_all();
}

bool LockstepClock::stop_requested() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stop_requested_;
}

void LockstepClock::begin_tick(std::uint32_t k) {
  tick_ = k;
  if (links_.realtime) {
    // Ticks at a fixed wall rate from the first one; nobody is waited for.
    if (k == 0) realtime_start_ = std::chrono::steady_clock::now();
    std::this_thread::sleep_until(realtime_start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                        std::chrono::duration<double, std::milli>(k * links_.tick_ms)));
    deliver_due_now();
    return;
  }
  std::uint64_t expected;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    expected = from_agents_[self_];
  }
  deliver_due(k, expected);
}

void LockstepClock::publish_clock(std::uint32_t k, const std::vector<msgs::RobotState>& robots, bool stop,
                                  const msgs::RunTally& tally) {
  const std::vector<std::uint32_t> sent = take_sent_counts();
  msgs::Clock clock;
  clock.tick(k);
  clock.stop(stop);
  clock.tally(tally);
  std::vector<std::uint32_t> expected(topology_.agents(), 0);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::uint64_t> bytes = traffic_.sent_bytes_by_link();
    for (std::size_t l = 0; l < bytes.size(); ++l) {
      bytes[l] += retired_bytes_[l];
      for (const std::vector<std::uint64_t>& agent : agent_bytes_) bytes[l] += agent[l];
    }
    clock.sent_bytes(bytes);
    started_ = true;
    const auto now = std::chrono::steady_clock::now();
    for (int a = 0; a < topology_.agents(); ++a) {
      // A restarted process joins at the first clock a while after its hello (its peers' writers
      // have matched its readers by then, as its readers matched theirs before it spoke). It
      // counts the messages stamped from k on, and so do we (every Done of tick k - 1 is in: the
      // agents' messages stamped before k are counted). It is waited for again from its first
      // Done, as a cut-off agent is (it may have missed this very clock and start at a later one).
      if (restarting_[a] && now - restart_heard_[a] >= kRestartSettle) {
        restarting_[a] = false;
        counted_from_[a] = k;
        base_[a] = from_agents_[a] + from_sim_[a];
        for (auto it = losses_.rbegin(); it != losses_.rend(); ++it) {
          if (it->agent != a) continue;
          it->restarted = true;
          break;
        }
      }
      from_sim_[a] += sent[a];
      expected[a] = static_cast<std::uint32_t>(from_agents_[a] + from_sim_[a] - base_[a]);
    }
  }
  clock.expected(expected);
  clock.counted_from(counted_from_);
  clock.robots(robots);
  leaders_ = next_leaders(topology_, leaders_, robots);
  clock.leaders(leaders_);
  bool anyone_lost = false;
  if (stop) {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    anyone_lost = std::find(lost_.begin(), lost_.end(), true) != lost_.end();
  }
  clock_writer_->write(clock);
  // An agent lost at the stop may be cut off rather than dead: DDS still holds the stop for it,
  // but only while this process lives. Give it a few seconds to come back and hear that the run
  // is over (a dead one never acknowledges, so this is the price of a crash at the end).
  if (anyone_lost) clock_writer_->wait_acknowledged(std::chrono::seconds(5));
}

bool LockstepClock::wait_done(std::uint32_t k) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (links_.realtime) {
    done_.clear();  // nobody is waited for; only the GCS's completion matters
    return complete_;
  }
  auto all_done = [&] {
    auto it = done_.find(k);
    for (int a = 0; a < topology_.agents(); ++a) {
      if (a == topology_.sim() || lost_[a]) continue;
      if (it == done_.end() || !it->second[a]) return false;
    }
    return true;
  };
  if (!arrived_.wait_for(lock, stall_timeout(), [&] { return stop_requested_ || all_done(); })) {
    std::string missing;
    auto it = done_.find(k);
    for (int a = 0; a < topology_.agents(); ++a) {
      if (a == topology_.sim()) continue;
      if (lost_[a]) continue;
      if (it == done_.end() || !it->second[a]) missing += (missing.empty() ? "" : ", ") + topology_.name_of(static_cast<AgentId>(a));
    }
    throw std::runtime_error("sim: tick " + std::to_string(k) + " never finished in " +
                             std::to_string(stall_timeout().count()) + " s; waiting for " + missing);
  }
  done_.erase(done_.begin(), done_.upper_bound(k));
  return complete_;
}

}  // namespace swarm::comm
