// What the MAPF file readers (movingai_scen.cpp, graph_file.cpp) share: the error that names the
// file and line, and strict number fields (the whole word, nothing after it).
#pragma once

#include <charconv>
#include <cmath>
#include <string>

#include "swarm/planner/grid/map_io.hpp"

namespace swarm::planner::mapf::detail {

// Throws MapFileError "FILE:LINE: what" ("FILE: what" for line 0: the file as a whole).
[[noreturn]] inline void fail(const std::string& file, int line, const std::string& what) {
  throw MapFileError(file + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
}

inline bool parse_int(const std::string& s, int& out) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size() && !s.empty();
}

inline bool parse_double(const std::string& s, double& out) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size() && !s.empty() && std::isfinite(out);
}

}  // namespace swarm::planner::mapf::detail
