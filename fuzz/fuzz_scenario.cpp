// Scenario files (protobuf text format): parsing and validation, as `swarm run --scenario` and
// every role do. Bad input throws config::ConfigError naming the field.
#include <cstdint>
#include <string>

#include "swarm/config/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto s = swarm::config::parse_scenario_text(text, "fuzz");
    swarm::config::validate(s, "fuzz");
    (void)swarm::config::mission_phases(s);
    (void)swarm::config::to_text(s);
  } catch (const swarm::config::ConfigError&) {
  }
  return 0;
}
