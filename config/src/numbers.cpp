#include "swarm/config/numbers.hpp"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>

#include "swarm/config/problems.hpp"

namespace swarm::config {
namespace {

namespace pb = google::protobuf;

std::string bound_text(double v) { return std::isinf(v) ? (v > 0 ? "inf" : "-inf") : num(v); }

bool ends_with(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

void check_field(const pb::Message& m, const pb::FieldDescriptor& f, int index, const std::string& path,
                 Problems& p) {
  const pb::Reflection& r = *m.GetReflection();
  const bool repeated = f.is_repeated();
  switch (f.cpp_type()) {
    case pb::FieldDescriptor::CPPTYPE_DOUBLE:
    case pb::FieldDescriptor::CPPTYPE_FLOAT: {
      const double v = f.cpp_type() == pb::FieldDescriptor::CPPTYPE_DOUBLE
                           ? (repeated ? r.GetRepeatedDouble(m, &f, index) : r.GetDouble(m, &f))
                           : (repeated ? r.GetRepeatedFloat(m, &f, index) : r.GetFloat(m, &f));
      const bool limit = ends_with(f.name(), "time_limit_s");
      if (p.has(path)) break;  // its own check said what it must be
      if (std::isnan(v)) {
        p.add(path, "be a number", "nan");
      } else if (std::isinf(v) && !(limit && v > 0)) {
        p.add(path, limit ? "be a number > 0, or inf for no limit" : "be a finite number", num(v));
      }
      break;
    }
    case pb::FieldDescriptor::CPPTYPE_UINT32: {
      const std::uint32_t v = repeated ? r.GetRepeatedUInt32(m, &f, index) : r.GetUInt32(m, &f);
      if (v > static_cast<std::uint32_t>(INT_MAX) && !p.has(path)) p.add(path, "be at most " + std::to_string(INT_MAX), std::to_string(v));
      break;
    }
    case pb::FieldDescriptor::CPPTYPE_MESSAGE: {
      const pb::Message& sub = repeated ? r.GetRepeatedMessage(m, &f, index) : r.GetMessage(m, &f);
      const std::string prefix = path + ".";
      std::vector<const pb::FieldDescriptor*> fields;
      sub.GetReflection()->ListFields(sub, &fields);
      for (const pb::FieldDescriptor* g : fields) {
        const int n = g->is_repeated() ? sub.GetReflection()->FieldSize(sub, g) : 1;
        for (int i = 0; i < n; ++i) {
          check_field(sub, *g, g->is_repeated() ? i : -1,
                      prefix + g->name() + (g->is_repeated() ? "[" + std::to_string(i) + "]" : ""), p);
        }
      }
      break;
    }
    default:
      break;  // int32/int64/uint64 and enums: their own fields' checks say what fits
  }
}

}  // namespace

std::string number_problem(double v, const NumberRule& rule) {
  const bool inf_ok = rule.infinity_ok && std::isinf(v) && v > 0;
  const bool ok = inf_ok || (std::isfinite(v) && (rule.above_min ? v > rule.min : v >= rule.min) &&
                             (rule.below_max ? v < rule.max : v <= rule.max));
  if (ok) return "";
  const bool low = std::isfinite(rule.min), high = std::isfinite(rule.max);
  const std::string noun = rule.noun;
  std::string out;
  if (low && high) {
    out = "be a " + noun + " in " + (rule.above_min ? "(" : "[") + bound_text(rule.min) + ", " + bound_text(rule.max) +
          (rule.below_max ? ")" : "]");
  } else {
    out = std::string("be a ") + (rule.infinity_ok ? "" : "finite ") + noun;
    if (low) out += std::string(rule.above_min ? " > " : " >= ") + bound_text(rule.min);
    if (high) out += std::string(rule.below_max ? " < " : " <= ") + bound_text(rule.max);
  }
  if (rule.infinity_ok) out += ", or inf for no limit";
  return out;
}

std::string whole_number_problem(std::string_view text, bool is_signed) {
  const std::string expected =
      is_signed ? "be a whole number in [" + std::to_string(INT64_MIN) + ", " + std::to_string(INT64_MAX) + "]"
                : "be a whole number in [0, " + std::to_string(UINT64_MAX) + "]";
  std::string_view digits = text;
  if (is_signed && !digits.empty() && digits.front() == '-') digits.remove_prefix(1);
  if (digits.empty()) return expected;
  for (char c : digits) {
    if (c < '0' || c > '9') return expected;
  }
  const char* end = text.data() + text.size();
  if (is_signed) {
    std::int64_t v = 0;
    const auto r = std::from_chars(text.data(), end, v);
    return r.ec == std::errc() && r.ptr == end ? "" : expected;
  }
  std::uint64_t v = 0;
  const auto r = std::from_chars(text.data(), end, v);
  return r.ec == std::errc() && r.ptr == end ? "" : expected;
}

void check_numbers(const pb::Message& message, Problems& problems) {
  std::vector<const pb::FieldDescriptor*> fields;
  message.GetReflection()->ListFields(message, &fields);
  for (const pb::FieldDescriptor* f : fields) {
    const int n = f->is_repeated() ? message.GetReflection()->FieldSize(message, f) : 1;
    for (int i = 0; i < n; ++i) {
      check_field(message, *f, f->is_repeated() ? i : -1, f->name() + (f->is_repeated() ? "[" + std::to_string(i) + "]" : ""),
                  problems);
    }
  }
}

}  // namespace swarm::config
