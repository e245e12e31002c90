#include "swarm/config/problems.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "swarm/config/numbers.hpp"
#include "swarm/config/scenario.hpp"

namespace swarm::config {

void Problems::add(const std::string& field, const std::string& expected, const std::string& got) {
  lines_.push_back(source_ + ": field " + field + ": must " + expected + " (got " + got + ")");
  fields_.push_back(field);
}

bool Problems::has(const std::string& field) const {
  return std::find(fields_.begin(), fields_.end(), field) != fields_.end();
}

void Problems::at_least(const std::string& field, std::uint64_t min, std::uint64_t v) {
  if (v < min) add(field, "be >= " + std::to_string(min), std::to_string(v));
}

void Problems::in_range(const std::string& field, std::uint64_t min, std::uint64_t max, std::uint64_t v) {
  if (v < min || v > max) add(field, "be in [" + std::to_string(min) + ", " + std::to_string(max) + "]", std::to_string(v));
}

void Problems::number(const std::string& field, double v, const NumberRule& rule) {
  const std::string expected = number_problem(v, rule);
  if (!expected.empty()) add(field, expected, num(v));
}

void Problems::positive(const std::string& field, double v) { number(field, v, kPositive); }
void Problems::non_negative(const std::string& field, double v) { number(field, v, kNonNegative); }
void Problems::finite(const std::string& field, double v) { number(field, v, kFinite); }
void Problems::probability(const std::string& field, double v) { number(field, v, kProbability); }
void Problems::time_limit(const std::string& field, double v) { number(field, v, kTimeLimit); }

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
