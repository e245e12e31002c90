// numbers.hpp: one judgement of a number for scenario fields, flags and offline tools.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "swarm/config/numbers.hpp"
#include "swarm/config/problems.hpp"
#include "swarm/config/scenario.hpp"

namespace {

namespace cfg = swarm::config;
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(NumberProblem, SaysWhatTheNumberMustBe) {
  EXPECT_EQ(cfg::number_problem(1.0, cfg::kPositive), "");
  EXPECT_EQ(cfg::number_problem(0.0, cfg::kPositive), "be a finite number > 0");
  EXPECT_EQ(cfg::number_problem(kInf, cfg::kPositive), "be a finite number > 0");
  EXPECT_EQ(cfg::number_problem(NAN, cfg::kNonNegative), "be a finite number >= 0");
  EXPECT_EQ(cfg::number_problem(1.0, cfg::kProbability), "be a probability in [0, 1)");
  EXPECT_EQ(cfg::number_problem(0.5, cfg::kProbability), "");
  EXPECT_EQ(cfg::number_problem(65, cfg::NumberRule{1, 64}), "be a number in [1, 64]");
  EXPECT_EQ(cfg::number_problem(-kInf, cfg::kFinite), "be a finite number");
}

TEST(NumberProblem, ATimeLimitMayBeInfiniteButNeverNaNOrZero) {
  EXPECT_EQ(cfg::number_problem(kInf, cfg::kTimeLimit), "");
  EXPECT_EQ(cfg::number_problem(1e300, cfg::kTimeLimit), "");
  EXPECT_EQ(cfg::number_problem(NAN, cfg::kTimeLimit), "be a number > 0, or inf for no limit");
  EXPECT_EQ(cfg::number_problem(0, cfg::kTimeLimit), "be a number > 0, or inf for no limit");
  EXPECT_EQ(cfg::number_problem(-kInf, cfg::kTimeLimit), "be a number > 0, or inf for no limit");
}

TEST(WholeNumberProblem, NeverWraps) {
  EXPECT_EQ(cfg::whole_number_problem("18446744073709551615", false), "");
  EXPECT_EQ(cfg::whole_number_problem("0", false), "");
  const std::string unsigned_range = "be a whole number in [0, 18446744073709551615]";
  EXPECT_EQ(cfg::whole_number_problem("-1", false), unsigned_range);
  EXPECT_EQ(cfg::whole_number_problem("18446744073709551616", false), unsigned_range);
  EXPECT_EQ(cfg::whole_number_problem("99999999999999999999", false), unsigned_range);
  EXPECT_EQ(cfg::whole_number_problem("0x10", false), unsigned_range);
  EXPECT_EQ(cfg::whole_number_problem("1e3", false), unsigned_range);
  EXPECT_EQ(cfg::whole_number_problem(" 7", false), unsigned_range);
  EXPECT_EQ(cfg::whole_number_problem("", false), unsigned_range);
  EXPECT_EQ(cfg::whole_number_problem("-9223372036854775808", true), "");
  EXPECT_EQ(cfg::whole_number_problem("-9223372036854775809", true),
            "be a whole number in [-9223372036854775808, 9223372036854775807]");
  EXPECT_EQ(cfg::whole_number_problem("-", true), "be a whole number in [-9223372036854775808, 9223372036854775807]");
}

std::string problems_of(const std::string& text) {
  const swarm::scenario::Scenario s = cfg::parse_scenario_text(text, "t.pbtxt");
  cfg::Problems p("t.pbtxt");
  cfg::check_numbers(s, p);
  try {
    p.throw_if_any();
  } catch (const cfg::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckNumbers, NamesEveryNaNOrInfiniteFieldByItsPath) {
  EXPECT_EQ(problems_of("links { member_leader { delay_ms: nan } }"),
            "t.pbtxt: field links.member_leader.delay_ms: must be a number (got nan)");
  EXPECT_EQ(problems_of("mission { phase { explore {} } phase { mapf { w: nan } } }"),
            "t.pbtxt: field mission.phase[1].mapf.w: must be a number (got nan)");
  EXPECT_EQ(problems_of("start { x: inf y: 1 }"), "t.pbtxt: field start.x: must be a finite number (got inf)");
}

TEST(CheckNumbers, ATimeLimitMayBeInfinite) {
  EXPECT_EQ(problems_of("mission { phase { cover { darp_time_limit_s: inf } } }"), "");
  EXPECT_EQ(problems_of("mission { phase { mapf { time_limit_s: -inf } } }"),
            "t.pbtxt: field mission.phase[0].mapf.time_limit_s: must be a number > 0, or inf for no limit (got -inf)");
}

TEST(CheckNumbers, AnUnsignedFieldPastIntIsRefused) {
  EXPECT_EQ(problems_of("footprint_radius: 4000000000"),
            "t.pbtxt: field footprint_radius: must be at most 2147483647 (got 4000000000)");
  EXPECT_EQ(problems_of("max_ticks: 2147483647"), "");
}

}  // namespace
