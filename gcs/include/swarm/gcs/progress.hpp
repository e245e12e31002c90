// The GCS's progress display: a redrawn bar on a terminal, plain lines in a log, or nothing.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace swarm::gcs {

class Progress {
 public:
  enum class Style { Bar, Plain, None };
  Progress(Style style, std::uint32_t max_ticks);
  static Style parse(const std::string& name);  // "bar" | "plain" | "none"

  // Called every tick with what the current phase shows (e.g. "mapped", 0.42, "round 12 frontier
  // cells 40"); draws at most ten times a second (bar), or a plain line when the detail or the
  // note changes (plain). `note` (e.g. "leader-1 unreachable") is shown after the numbers.
  void update(std::uint32_t tick, const std::string& label, double fraction, const std::string& detail,
              const std::string& note = "");
  void finish(const std::string& summary);

 private:
  Style style_;
  std::uint32_t max_ticks_;
  std::string last_detail_;
  std::string last_note_;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace swarm::gcs
