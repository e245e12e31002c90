// How every number a user gives is judged: a scenario field (Problems, check_numbers), a flag of
// any `swarm` command (tools/cli/cli_numbers.hpp) and an offline tool's input read the same rules,
// so `--seed -1`, `w: nan` and `--time-limit inf` get one answer wherever they are written.
//
//   number_problem(0.0, kPositive)             -> "be a finite number > 0"
//   number_problem(inf, kTimeLimit)            -> ""          (inf: no limit)
//   whole_number_problem("-1", false)          -> "be a whole number in [0, 18446744073709551615]"
#pragma once

#include <limits>
#include <string>
#include <string_view>

namespace google::protobuf {
class Message;
}

namespace swarm::config {

class Problems;

struct NumberRule {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool above_min = false;    // min itself is refused
  bool below_max = false;    // max itself is refused
  bool infinity_ok = false;  // +inf is accepted: "no limit" (time limits)
  const char* noun = "number";  // what messages call it ("probability")
};

inline constexpr NumberRule kFinite{};
inline constexpr NumberRule kPositive{0, std::numeric_limits<double>::infinity(), true};
inline constexpr NumberRule kNonNegative{0};
inline constexpr NumberRule kProbability{0, 1, false, true, false, "probability"};
// Seconds a search may take: more than 0; inf (or any limit past the clock's range) is no limit.
inline constexpr NumberRule kTimeLimit{0, std::numeric_limits<double>::infinity(), true, false, true};

// "" when `v` keeps the rule; otherwise what it must be, as "be ..." (NaN never keeps a rule).
[[nodiscard]] std::string number_problem(double v, const NumberRule& rule);

// A whole number as typed: decimal digits, a '-' in front only if `is_signed`, within 64 bits.
// "" when it is one; otherwise what it must be. Octal, hex, spaces and signs on unsigned
// numbers are refused, so that "-1" never wraps to 18446744073709551615.
[[nodiscard]] std::string whole_number_problem(std::string_view text, bool is_signed);

// The numbers of a whole message, checked by their type, each named by its path
// ("mission.phase[2].cover.darp_time_limit_s"): NaN is refused in every floating field, +-inf in
// every one but a time limit (a name ending in "time_limit_s"), and an unsigned 32-bit value
// above 2^31 - 1 in every field (the runtime counts cells, ticks and robots in int).
void check_numbers(const google::protobuf::Message& message, Problems& problems);

}  // namespace swarm::config
