#include "swarm/gcs/outages.hpp"

#include <algorithm>

namespace swarm::gcs {

void Outages::observe(int who, bool down, std::uint32_t since, std::uint32_t tick) {
  auto& open = open_.at(static_cast<std::size_t>(who));
  if (down && !open) {
    open = intervals_.size();
    intervals_.push_back({who, std::min(since, tick), std::nullopt});
  } else if (!down && open) {
    intervals_[*open].to = tick;
    open.reset();
  }
}

int Outages::down_count() const {
  return static_cast<int>(std::count_if(open_.begin(), open_.end(), [](const auto& o) { return o.has_value(); }));
}

}  // namespace swarm::gcs
