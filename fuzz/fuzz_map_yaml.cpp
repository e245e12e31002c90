// map_server maps: the YAML file and the PGM image it names. The input is the YAML text, a NUL
// byte, then the image bytes (written as map.pgm beside the YAML, which may name it). Bad input
// throws planner::MapFileError; a map that loads has a sane size.
#include <cstdint>
#include <cstring>

#include "fuzz_files.hpp"
#include "swarm/planner/grid/map_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
  const std::size_t yaml_size = nul ? static_cast<std::size_t>(nul - data) : size;
  const std::size_t image_at = nul ? yaml_size + 1 : size;
  (void)swarm::fuzz::temp_file("map.pgm", data + image_at, size - image_at);
  const std::string yaml = swarm::fuzz::temp_file("map.yaml", data, yaml_size);
  try {
    const auto map = swarm::planner::load_map_yaml(yaml);
    if (map.width() <= 0 || map.height() <= 0) __builtin_trap();
  } catch (const swarm::planner::MapFileError&) {
  }
  return 0;
}
