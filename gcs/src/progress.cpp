#include "swarm/gcs/progress.hpp"

#include <cstdio>

namespace swarm::gcs {

Progress::Progress(Style style, std::uint32_t max_ticks) : style_(style), max_ticks_(max_ticks) {}

Progress::Style Progress::parse(const std::string& name) {
  if (name == "bar") return Style::Bar;
  if (name == "none") return Style::None;
  return Style::Plain;
}

void Progress::update(std::uint32_t tick, double mapped, std::uint32_t round, std::size_t frontier_cells,
                      const std::string& note) {
  if (style_ == Style::None) return;
  if (style_ == Style::Plain) {
    if (round == last_round_ && note == last_note_) return;
    last_round_ = round;
    last_note_ = note;
    std::printf("tick %5u  round %3u  mapped %5.1f%%  frontier cells %zu%s%s\n", tick, round, 100.0 * mapped,
                frontier_cells, note.empty() ? "" : "  ", note.c_str());
    std::fflush(stdout);
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(mapped * kWidth + 0.5);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '-';
  bar[kWidth] = '\0';
  // Padding clears what a longer previous note left on the line.
  std::printf("\r[%s] mapped %5.1f%% | tick %5u/%u | round %3u | frontier %5zu %-28s", bar, 100.0 * mapped, tick,
              max_ticks_, round, frontier_cells, note.c_str());
  std::fflush(stdout);
}

void Progress::finish(const std::string& summary) {
  if (style_ == Style::None) return;
  if (style_ == Style::Bar) std::printf("\n");
  std::printf("%s\n", summary.c_str());
  std::fflush(stdout);
}

}  // namespace swarm::gcs
