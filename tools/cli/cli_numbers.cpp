#include "cli_numbers.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <string>

namespace swarm::tools {
namespace {

constexpr const char* kSecondsName = "SECONDS";

// The text as a double the way CLI11 will read it ("inf", "nan", "1e308" included).
std::optional<double> as_double(const std::string& s) {
  const char* b = s.data();
  const char* e = b + s.size();
  if (b != e && *b == '+') ++b;
  double v = 0;
  const auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc::result_out_of_range) return std::nullopt;  // 1e999: no double
  if (r.ec != std::errc() || r.ptr != e) return std::nullopt;
  return v;
}

CLI::Validator rule_check(const config::NumberRule& rule, std::string name) {
  return CLI::Validator(
      [rule](std::string& text) -> std::string {
        const std::optional<double> v = as_double(text);
        const std::string expected = v ? config::number_problem(*v, rule) : config::number_problem(NAN, rule);
        return expected.empty() ? std::string() : "must " + expected + " (got " + text + ")";
      },
      "", std::move(name));
}

bool has_validator(CLI::Option& opt, const std::string& name) {
  try {
    return opt.get_validator(name) != nullptr;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

void check_options_of(CLI::App& app) {
  for (CLI::Option* opt : app.get_options([](const CLI::Option* o) { return o->get_type_size_max() > 0; })) {
    const std::string type = opt->get_type_name();
    const bool is_int = type.rfind("INT", 0) == 0;
    const bool is_uint = type.rfind("UINT", 0) == 0;
    if (is_int || is_uint) {
      // A transform, not a check: only a transform may rewrite the text CLI11 goes on to read.
      opt->transform(CLI::Validator(
          [is_int](std::string& text) -> std::string {
            const std::string expected = config::whole_number_problem(text, is_int);
            if (!expected.empty()) return "must " + expected + " (got " + text + ")";
            // CLI11 reads a leading 0 as octal ("010" = 8): a decimal number it is.
            const std::size_t sign = text[0] == '-' ? 1 : 0;
            const std::size_t first = text.find_first_not_of('0', sign);
            text = first == std::string::npos ? "0" : text.substr(0, sign) + text.substr(first);
            return std::string();
          },
          "", "WHOLE"));
    } else if (type.rfind("FLOAT", 0) == 0 && !has_validator(*opt, kSecondsName)) {
      opt->check(rule_check(config::kFinite, "FINITE"));
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) check_options_of(*sub);
}

}  // namespace

CLI::Validator number(const config::NumberRule& rule) { return rule_check(rule, "NUMBER"); }

CLI::Validator seconds() { return rule_check(config::kTimeLimit, kSecondsName); }

CLI::Validator seconds_or_zero() {
  config::NumberRule rule = config::kTimeLimit;
  rule.above_min = false;
  return rule_check(rule, kSecondsName);
}

CLI::Validator wall_seconds() { return rule_check({0, 1e9}, "NUMBER"); }

void check_number_options(CLI::App& app) { check_options_of(app); }

}  // namespace swarm::tools
