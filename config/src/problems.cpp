#include "swarm/config/problems.hpp"

#include <charconv>
#include <cmath>

#include "swarm/config/scenario.hpp"

namespace swarm::config {

void Problems::add(const std::string& field, const std::string& expected, const std::string& got) {
  lines_.push_back(source_ + ": field " + field + ": must " + expected + " (got " + got + ")");
}

void Problems::at_least(const std::string& field, std::uint64_t min, std::uint64_t v) {
  if (v < min) add(field, "be >= " + std::to_string(min), std::to_string(v));
}

void Problems::in_range(const std::string& field, std::uint64_t min, std::uint64_t max, std::uint64_t v) {
  if (v < min || v > max) add(field, "be in [" + std::to_string(min) + ", " + std::to_string(max) + "]", std::to_string(v));
}

void Problems::positive(const std::string& field, double v) {
  if (!(std::isfinite(v) && v > 0)) add(field, "be a finite number > 0", num(v));
}

void Problems::non_negative(const std::string& field, double v) {
  if (!(std::isfinite(v) && v >= 0)) add(field, "be a finite number >= 0", num(v));
}

void Problems::finite(const std::string& field, double v) {
  if (!std::isfinite(v)) add(field, "be a finite number", num(v));
}

void Problems::probability(const std::string& field, double v) {
  if (!(v >= 0 && v < 1)) add(field, "be a probability in [0, 1)", num(v));
}

void Problems::throw_if_any() const {
  if (lines_.empty()) return;
  std::string all;
  for (const std::string& l : lines_) all += (all.empty() ? "" : "\n") + l;
  throw ConfigError(all);
}

std::string num(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace swarm::config
