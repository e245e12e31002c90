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

  // Called every tick; draws at most ten times a second (bar) or once per round (plain).
  // `note` (e.g. "leader-1 unreachable") is shown after the numbers; a change of note prints a
  // plain line too.
  void update(std::uint32_t tick, double mapped, std::uint32_t round, std::size_t frontier_cells,
              const std::string& note = "");
  void finish(const std::string& summary);

 private:
  Style style_;
  std::uint32_t max_ticks_;
  std::uint32_t last_round_ = 0;
  std::string last_note_;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace swarm::gcs
