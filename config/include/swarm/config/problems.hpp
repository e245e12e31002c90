// What is wrong with a scenario, one line per problem, all reported at once:
//   "SOURCE: field PATH: must EXPECTED (got GIVEN)"
// validate() fills one for the scenario's own fields; each task's registry row fills one for its
// phase's settings (tasks/api/include/swarm/tasks/task_row.hpp, `check`).
//
//   Problems p("t.pbtxt");
//   p.at_least("groups", 1, s.groups());
//   p.throw_if_any();   // ConfigError with every line, or nothing
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace swarm::config {

struct NumberRule;

class Problems {
 public:
  explicit Problems(std::string source) : source_(std::move(source)) {}

  void add(const std::string& field, const std::string& expected, const std::string& got);
  void at_least(const std::string& field, std::uint64_t min, std::uint64_t v);
  void in_range(const std::string& field, std::uint64_t min, std::uint64_t max, std::uint64_t v);
  // Numbers by the rules every input shares (numbers.hpp).
  void number(const std::string& field, double v, const NumberRule& rule);
  void positive(const std::string& field, double v);
  void non_negative(const std::string& field, double v);
  void finite(const std::string& field, double v);
  void probability(const std::string& field, double v);
  void time_limit(const std::string& field, double v);  // > 0 seconds; inf: no limit

  [[nodiscard]] bool empty() const { return lines_.empty(); }
  [[nodiscard]] bool has(const std::string& field) const;  // a problem of this field is listed
  // Throws ConfigError with every line, one per line; nothing when there is no problem.
  void throw_if_any() const;

 private:
  std::string source_;
  std::vector<std::string> lines_;
  std::vector<std::string> fields_;
};

// Shortest text that reads back as the same double ("0.2", "1e-09", "nan").
[[nodiscard]] std::string num(double v);

}  // namespace swarm::config
