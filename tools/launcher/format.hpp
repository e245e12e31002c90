// Numbers and times as the tools print them.
#pragma once

#include <ctime>
#include <string>

namespace swarm::tools {

// "12.35" with `decimals` digits; "-" for a value that is not finite (a run that gave none).
[[nodiscard]] std::string fixed(double v, int decimals);

// "YYYYmmdd-HHMMSS" in local time, for default output directory names.
[[nodiscard]] std::string local_timestamp(std::time_t now = std::time(nullptr));

}  // namespace swarm::tools
