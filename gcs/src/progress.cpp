#include "swarm/gcs/progress.hpp"

#include <cstdio>

namespace swarm::gcs {

Progress::Progress(Style style, std::uint32_t max_ticks) : style_(style), max_ticks_(max_ticks) {}

Progress::Style Progress::parse(const std::string& name) {
  if (name == "bar") return Style::Bar;
  if (name == "none") return Style::None;
  return Style::Plain;
}

void Progress::update(std::uint32_t tick, const std::string& label, double fraction, const std::string& detail,
                      const std::string& note) {
  if (style_ == Style::None) return;
  if (style_ == Style::Plain) {
    if (detail == last_detail_ && note == last_note_) return;
    last_detail_ = detail;
    last_note_ = note;
    std::printf("tick %5u  %s %5.1f%%  %s%s%s\n", tick, label.c_str(), 100.0 * fraction, detail.c_str(),
                note.empty() ? "" : "  ", note.c_str());
    std::fflush(stdout);
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth + 0.5);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '-';
  bar[kWidth] = '\0';
  // Padding clears what a longer previous line left.
  std::printf("\r[%s] %s %5.1f%% | tick %5u/%u | %s %-28s", bar, label.c_str(), 100.0 * fraction, tick, max_ticks_,
              detail.c_str(), note.c_str());
  std::fflush(stdout);
}

void Progress::finish(const std::string& summary) {
  if (style_ == Style::None) return;
  if (style_ == Style::Bar) std::printf("\n");
  std::printf("%s\n", summary.c_str());
  std::fflush(stdout);
}

}  // namespace swarm::gcs
