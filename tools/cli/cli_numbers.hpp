// Numbers on the command line, by the rules scenario files use (swarm/config/numbers.hpp).
//
//   c->add_option("--scale", scale)->check(number(config::kPositive));
//   c->add_option("--time-limit", limit)->check(seconds());   // inf: no limit
//   ...
//   check_number_options(app);   // once every command is declared: every numeric flag
//
// check_number_options gives every integer flag a whole-number check (decimal digits, a sign only
// where the type has one: `--seed -1` is refused, never wrapped to 2^64 - 1) and every floating
// flag a finite-number check (NaN is refused; inf only where the flag's own check is `seconds`).
// The messages name the flag: "--seed: must be a whole number in [0, 18446744073709551615] (got -1)".
#pragma once

#include <CLI/CLI.hpp>

#include "swarm/config/numbers.hpp"

namespace swarm::tools {

[[nodiscard]] CLI::Validator number(const config::NumberRule& rule);
[[nodiscard]] CLI::Validator seconds();          // config::kTimeLimit: > 0, inf = no limit
[[nodiscard]] CLI::Validator seconds_or_zero();  // >= 0 seconds, 0 = no limit; inf also no limit
// A wall-clock limit in whole seconds: 0 (none) up to a billion (past it the clock would wrap).
[[nodiscard]] CLI::Validator wall_seconds();

void check_number_options(CLI::App& app);

}  // namespace swarm::tools
