// Intervals during which something was down, fed once per tick: a robot the simulator declared
// lost (until its link heals), a leader whose heartbeats stopped reaching the GCS. One piece of
// bookkeeping serves both, and metrics.json's faults section is read off it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace swarm::gcs {

class Outages {
 public:
  explicit Outages(int count) : open_(static_cast<std::size_t>(count)) {}

  struct Interval {
    int who = 0;
    std::uint32_t from = 0;             // first tick down
    std::optional<std::uint32_t> to;    // first tick up again; none while still down
  };

  // What was seen at `tick`: `who` is down (since tick `since` <= tick) or up. Opens an interval
  // when it goes down, closes it when it comes back.
  void observe(int who, bool down, std::uint32_t since, std::uint32_t tick);
  bool down(int who) const { return open_.at(static_cast<std::size_t>(who)).has_value(); }
  int down_count() const;
  // Every interval, in the order they opened.
  const std::vector<Interval>& intervals() const { return intervals_; }

 private:
  std::vector<std::optional<std::size_t>> open_;  // per who: index of its open interval
  std::vector<Interval> intervals_;
};

}  // namespace swarm::gcs
