// Scenario text files: parsing with positioned errors, validation, printing, mode names.
#include "swarm/config/scenario.hpp"
#include "swarm/config/numbers.hpp"
#include "swarm/config/problems.hpp"
#include "swarm/config/task_config.hpp"
#include "swarm/planner/grid/map_io.hpp"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/io/zero_copy_stream_impl_lite.h>
#include <google/protobuf/text_format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <map>
#include <memory>
#include <sstream>

namespace swarm::config {
namespace {

namespace pb = google::protobuf;
using swarm::scenario::Scenario;

// Phase's `task` oneof: one field per task, named as the task.
const pb::OneofDescriptor& task_oneof() {
  return *swarm::scenario::Phase::descriptor()->FindOneofByName("task");
}

// "explore {}, cover {}, mapf {} or collect {}": what a phase may name.
std::string task_list_with_braces() {
  std::string out;
  const int n = task_oneof().field_count();
  for (int i = 0; i < n; ++i) out += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + task_oneof().field(i)->name() + " {}";
  return out;
}

// Keeps the parser's first error with its 0-based position.
class FirstError : public pb::io::ErrorCollector {
 public:
  void AddError(int line, pb::io::ColumnNumber column, const std::string& message) override {
    if (!error) error = Error{line, column, message};
  }
  void AddWarning(int, pb::io::ColumnNumber, const std::string&) override {}

  struct Error {
    int line;
    int column;
    std::string message;
  };
  std::optional<Error> error;
};

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// The enum type of the field named `name` anywhere in a scenario (nullptr when the name is
// not an enum field, or names fields of different enum types).
const pb::EnumDescriptor* enum_of_field(const std::string& name) {
  const pb::EnumDescriptor* found = nullptr;
  std::vector<const pb::Descriptor*> todo{Scenario::descriptor()};
  std::vector<const pb::Descriptor*> seen;
  while (!todo.empty()) {
    const pb::Descriptor* d = todo.back();
    todo.pop_back();
    if (std::find(seen.begin(), seen.end(), d) != seen.end()) continue;
    seen.push_back(d);
    for (int i = 0; i < d->field_count(); ++i) {
      const pb::FieldDescriptor* f = d->field(i);
      if (f->message_type() != nullptr) todo.push_back(f->message_type());
      if (f->enum_type() == nullptr || f->name() != name) continue;
      if (found != nullptr && found != f->enum_type()) return nullptr;
      found = f->enum_type();
    }
  }
  return found;
}

// Adds the fix to protobuf's messages where it can: the nearest field name, the enum's values.
std::string explain(const std::string& message) {
  static const std::regex kNoField(
      R"re(Message type "([^"]+)" has no field named "([^"]+)")re");
  static const std::regex kNoEnum(R"re(Unknown enumeration value of "[^"]*" for field "([^"]+)")re");
  std::smatch m;
  const pb::DescriptorPool* pool = pb::DescriptorPool::generated_pool();
  if (std::regex_search(message, m, kNoField)) {
    const pb::Descriptor* type = pool->FindMessageTypeByName(m[1].str());
    if (type == nullptr || type->field_count() == 0) return message;
    const std::string given = m[2].str();
    std::string names;
    const pb::FieldDescriptor* best = nullptr;
    std::size_t best_distance = SIZE_MAX;
    for (int i = 0; i < type->field_count(); ++i) {
      const pb::FieldDescriptor* f = type->field(i);
      names += (i ? ", " : "") + f->name();
      const std::size_t d = edit_distance(given, f->name());
      if (d < best_distance) best_distance = d, best = f;
    }
    std::string out = message;
    if (best != nullptr && best_distance <= std::max<std::size_t>(2, given.size() / 3)) {
      out += " Did you mean \"" + best->name() + "\"?";
    }
    return out + " (" + type->name() + " fields: " + names + ")";
  }
  if (std::regex_search(message, m, kNoEnum)) {
    const pb::EnumDescriptor* type = enum_of_field(m[1].str());
    if (type == nullptr) return message;
    std::string names;
    for (int i = 0; i < type->value_count(); ++i) {
      names += (i ? ", " : "") + type->value(i)->name();
    }
    return message + " (expected one of " + names + ")";
  }
  return message;
}

// More robots than this is no run this runtime can host (and keeps robot ids far from overflow).
constexpr std::uint64_t kMaxRobots = 10000;
constexpr std::uint64_t kMaxFootprintRadius = 64;

void validate_link(Problems& p, const std::string& name, const swarm::scenario::Link& link) {
  p.probability("links." + name + ".loss", link.loss());
  p.non_negative("links." + name + ".bandwidth_bytes_per_s", link.bandwidth_bytes_per_s());
  p.non_negative("links." + name + ".delay_ms", link.delay_ms());
  // delay_ticks and jitter_ticks are unsigned: every value is a valid delay.
}

// "leader-G" -> {G, 0}, "member-G-I" -> {G, I}; nullopt for anything else.
std::optional<std::pair<long, long>> robot_name(const std::string& name) {
  auto number = [](const std::string& t, long& out) {
    if (t.empty() || t.size() > 6 || !std::all_of(t.begin(), t.end(), ::isdigit)) return false;
    out = std::stol(t);
    return true;
  };
  long g = 0, i = 0;
  if (name.rfind("leader-", 0) == 0 && number(name.substr(7), g)) return std::make_pair(g, 0L);
  if (name.rfind("member-", 0) == 0) {
    const std::string rest = name.substr(7);
    const auto dash = rest.find('-');
    if (dash != std::string::npos && number(rest.substr(0, dash), g) && number(rest.substr(dash + 1), i)) {
      return std::make_pair(g, i);
    }
  }
  return std::nullopt;
}

void validate_fault(Problems& p, const Scenario& s, int index) {
  const auto& f = s.faults(index);
  const std::string field = "faults[" + std::to_string(index) + "]";
  if (f.agent() == "gcs") {
    // The ground station can only be killed to be restarted: without it no mission completes.
    if (!f.has_kill_at_tick() || !f.has_restart_after_seconds() || f.has_cut_from_tick() || f.has_cut_to_tick() ||
        f.has_freeze_at_tick()) {
      p.add(field, "kill the GCS with a restart: kill_at_tick and restart_after_seconds (--kill gcs@T+S)",
            f.has_kill_at_tick() && !f.has_restart_after_seconds() ? "a kill without restart_after_seconds"
                                                                    : "another fault");
      return;
    }
    p.at_least(field + ".kill_at_tick", 1, f.kill_at_tick());
    if (!(f.restart_after_seconds() > 0 && f.restart_after_seconds() < 30)) {
      p.add(field + ".restart_after_seconds", "be more than 0 and less than 30 (the DDS participant lease)",
            num(f.restart_after_seconds()));
    }
    return;
  }
  if (f.has_restart_after_seconds()) {
    p.add(field + ".restart_after_seconds", "be given for the GCS only (a robot's process is not restarted)",
          "\"" + f.agent() + "\"");
  }
  const auto who = robot_name(f.agent());
  const bool member = who && who->second >= 1 && who->second < static_cast<long>(s.robots_per_group());
  const bool known = who && who->first < static_cast<long>(s.groups()) && (who->second == 0 || member);
  if (!known) {
    p.add(field + ".agent",
          "name a robot of this run: leader-G (G < " + std::to_string(s.groups()) + ") or member-G-I (1 <= I < " +
              std::to_string(s.robots_per_group()) + "), or gcs",
          "\"" + f.agent() + "\"");
    return;
  }
  if (!f.has_kill_at_tick() && !f.has_cut_from_tick() && !f.has_cut_to_tick() && !f.has_freeze_at_tick()) {
    p.add(field, "say kill_at_tick, cut_from_tick and cut_to_tick, or freeze_at_tick and freeze_seconds",
          "none of them");
  }
  if (f.has_freeze_at_tick() || f.has_freeze_seconds()) {
    p.at_least(field + ".freeze_at_tick", 1, f.freeze_at_tick());
    // Past the participant lease DDS ends the peer's session and what was sent meanwhile is lost.
    if (!(f.freeze_seconds() > 0 && f.freeze_seconds() < 30)) {
      p.add(field + ".freeze_seconds", "be more than 0 and less than 30 (the DDS participant lease)",
            num(f.freeze_seconds()));
    }
  }
  if (f.has_kill_at_tick()) {
    if (!member && leader_standbys(s) == 0) {
      p.add(field + ".agent",
            "be a member to be killed: with no standby leader (leader_standbys 0, or a group of one robot) a "
            "group cannot lose its leader",
            f.agent());
    }
    p.at_least(field + ".kill_at_tick", 1, f.kill_at_tick());
  }
  if (f.has_cut_from_tick() || f.has_cut_to_tick()) {
    if (!f.has_cut_from_tick() || !f.has_cut_to_tick() || f.cut_from_tick() >= f.cut_to_tick()) {
      p.add(field, "give cut_from_tick < cut_to_tick",
            std::to_string(f.cut_from_tick()) + " .. " + std::to_string(f.cut_to_tick()));
    }
  }
}

// A fault the run never reaches, or a robot killed twice (the last kill would silently win).
void validate_fault_times(Problems& p, const Scenario& s) {
  std::map<std::string, int> killed;  // agent -> the fault that kills it first
  for (int i = 0; i < s.faults_size(); ++i) {
    const auto& f = s.faults(i);
    const std::string field = "faults[" + std::to_string(i) + "]";
    const auto never = [&](const char* name, std::uint32_t tick) {
      if (tick >= s.max_ticks()) {
        p.add(field + "." + name, "be below max_ticks (" + std::to_string(s.max_ticks()) + "), or the run ends first",
              std::to_string(tick));
      }
    };
    if (f.has_kill_at_tick()) never("kill_at_tick", f.kill_at_tick());
    if (f.has_cut_from_tick()) never("cut_from_tick", f.cut_from_tick());
    if (f.has_freeze_at_tick()) never("freeze_at_tick", f.freeze_at_tick());
    if (!f.has_kill_at_tick() || f.agent() == "gcs") continue;  // the GCS is killed to be restarted
    const auto [first, fresh] = killed.emplace(f.agent(), i);
    if (!fresh) {
      p.add(field + ".agent", "be killed once: faults[" + std::to_string(first->second) + "] already kills it",
            "\"" + f.agent() + "\"");
    }
  }
}

std::string normalise_mode(std::string s) {
  for (char& c : s) {
    c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return s;
}

// The tokens of a text as the text-format parser sees them (comments skipped).
struct Token {
  int line;
  int column;
  std::string text;
};

class Silent : public pb::io::ErrorCollector {
 public:
  void AddError(int, pb::io::ColumnNumber, const std::string&) override {}
};

std::vector<Token> tokens_of(const std::string& text) {
  pb::io::ArrayInputStream in(text.data(), static_cast<int>(text.size()));
  Silent silent;
  pb::io::Tokenizer tokenizer(&in, &silent);
  tokenizer.set_comment_style(pb::io::Tokenizer::SH_COMMENT_STYLE);
  std::vector<Token> out;
  while (tokenizer.Next()) {
    const auto& t = tokenizer.current();
    out.push_back({t.line, t.column, t.text});
  }
  return out;
}

bool before(int line_a, int col_a, int line_b, int col_b) {
  return line_a != line_b ? line_a < line_b : col_a < col_b;
}

// The tokenizer counts a tab as reaching the next multiple of 8; editors count characters.
int char_column(const std::string& text, int line, int column) {
  std::size_t pos = 0;
  for (int l = 0; l < line && pos != std::string::npos; ++l) {
    pos = text.find('\n', pos);
    if (pos != std::string::npos) ++pos;
  }
  if (pos == std::string::npos) return column;
  int col = 0;
  int chars = 0;
  for (; pos < text.size() && text[pos] != '\n' && col < column; ++pos, ++chars) {
    col = text[pos] == '\t' ? col + 8 - col % 8 : col + 1;
  }
  return chars;
}

struct Located {
  int line;  // 0-based, -1 = none
  int column;
  std::string message;
};

// The parser reports some errors at the token after the culprit (it has read one token more);
// move those back onto the culprit, explain an unclosed '{' at the end of the file, add the fix.
Located locate(const std::string& text, const FirstError::Error& e) {
  Located out{e.line, e.column, explain(e.message)};
  if (e.line < 0) return out;
  static const std::regex kCulprit(
      R"re((?:has no field named|Non-repeated field|Unknown enumeration value of|Value:) )re"
      R"re("([^"]+)")re");
  const std::vector<Token> tokens = tokens_of(text);
  std::smatch m;
  if (std::regex_search(e.message, m, kCulprit)) {
    for (auto t = tokens.rbegin(); t != tokens.rend(); ++t) {
      if (t->text == m[1].str() && before(t->line, t->column, e.line, e.column)) {
        out.line = t->line;
        out.column = t->column;
        break;
      }
    }
  } else if (e.message == "Expected identifier, got: }" ||
             e.message == "Expected identifier, got: >") {
    out.message += " (it closes nothing: there is no open '{' or '<' here)";
  } else if (e.message.size() >= 5 && e.message.compare(e.message.size() - 5, 5, "got: ") == 0) {
    // "Expected identifier, got: " with nothing after it: the file ended inside a message.
    std::vector<const Token*> open;
    for (const Token& t : tokens) {
      if (t.text == "{" || t.text == "<") open.push_back(&t);
      if ((t.text == "}" || t.text == ">") && !open.empty()) open.pop_back();
    }
    if (!open.empty()) {
      const Token& t = *open.back();
      out.message = "unexpected end of file: the '" + t.text + "' at line " +
                    std::to_string(t.line + 1) + ", column " +
                    std::to_string(char_column(text, t.line, t.column) + 1) +
                    " is never closed (add '" + (t.text == "{" ? "}" : ">") + "')";
    }
  }
  out.column = char_column(text, out.line, out.column);
  return out;
}

}  // namespace

Scenario parse_scenario_text(const std::string& text, const std::string& source_name) {
  Scenario s;
  FirstError errors;
  pb::TextFormat::Parser parser;
  parser.RecordErrorsTo(&errors);
  if (!parser.ParseFromString(text, &s)) {
    if (!errors.error) {
      throw ConfigError(source_name + ": not a valid scenario (protobuf text format)");
    }
    const Located e = locate(text, *errors.error);
    if (e.line < 0) throw ConfigError(source_name + ": " + e.message);
    throw ConfigError(source_name + ":" + std::to_string(e.line + 1) + ":" +
                      std::to_string(e.column + 1) + ": " + e.message);
  }
  return s;
}

Scenario load_scenario(const std::string& path) {
  // A directory opens as a stream that reads nothing, which would parse as the default scenario.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ConfigError(path + ": is a directory, not a scenario file (see scenarios/ for examples)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ConfigError(path + ": cannot open the scenario file (see scenarios/ for examples)");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(path + ": cannot read the scenario file");
  Scenario s = parse_scenario_text(text.str(), path);
  validate(s, path);
  return s;
}

void validate(const Scenario& s, const std::string& source) {
  Problems p(source);

  const std::string& name = s.name();
  const bool bad_name =
      name.empty() || name == "." || name == ".." ||
      std::any_of(name.begin(), name.end(), [](char c) {
        return c == '/' || c == '\\' || std::iscntrl(static_cast<unsigned char>(c)) != 0;
      });
  if (bad_name) {
    p.add("name", "be a non-empty name usable as a file name (no '/', '\\' or control characters)",
          "\"" + name + "\"");
  }
  if (s.map().empty()) p.add("map", "name a built-in map or a map YAML file", "\"\"");
  if (s.has_start()) {
    const auto& st = s.start();
    if (!st.has_x() || !st.has_y()) {
      p.add("start", "give both x and y in metres, e.g. start { x: 10.1 y: 10.1 }",
            std::string(st.has_x() ? "only x" : st.has_y() ? "only y" : "neither"));
    } else {
      p.finite("start.x", st.x());
      p.finite("start.y", st.y());
    }
  }

  p.at_least("groups", 1, s.groups());
  p.at_least("robots_per_group", 1, s.robots_per_group());
  if (s.has_leader_standbys() && s.robots_per_group() >= 1 && s.leader_standbys() > s.robots_per_group() - 1) {
    p.add("leader_standbys", "be at most robots_per_group - 1 = " + std::to_string(s.robots_per_group() - 1),
          std::to_string(s.leader_standbys()));
  }
  const std::uint64_t robots = std::uint64_t{s.groups()} * s.robots_per_group();
  if (robots > kMaxRobots) {
    p.add("groups x robots_per_group", "give at most " + std::to_string(kMaxRobots) + " robots",
          std::to_string(s.groups()) + " x " + std::to_string(s.robots_per_group()) + " = " +
              std::to_string(robots));
  }
  p.positive("sensing_range_m", s.sensing_range_m());
  p.in_range("lidar_beams", 4, 4096, s.lidar_beams());
  p.at_least("max_ticks", 1, s.max_ticks());
  p.positive("tick_seconds", s.tick_seconds());
  p.number("map_resolution_m", s.map_resolution_m(),
           NumberRule{planner::kMinResolutionM, planner::kMaxResolutionM});
  // A robot sweeps a disc of this radius; past a map's side it is every cell, and the disc's
  // offsets are listed once per robot and tick.
  p.in_range("footprint_radius", 0, kMaxFootprintRadius, s.footprint_radius());
  p.at_least("tick_ms", 1, s.tick_ms());

  const auto& e = s.explore();
  if (!swarm::scenario::Mode_IsValid(e.mode())) {
    p.add("explore.mode", "be GROUP_FRONTIER, BASELINE or IDEAL", std::to_string(e.mode()));
  }
  p.at_least("explore.replan_threshold_steps", 1, e.replan_threshold_steps());
  // global_map_delay_rounds: any count of rounds is a valid delay (0 = no delay).
  p.positive("explore.dbscan_eps_cells", e.dbscan_eps_cells());
  p.in_range("explore.dbscan_min_points", 1, INT_MAX, e.dbscan_min_points());
  // 0 turns the small-segment rule off (no segment is that small); it is an ablation, not an error.
  p.in_range("explore.small_segment_max_cells", 0, INT_MAX, e.small_segment_max_cells());
  p.non_negative("explore.small_segment_radius_cells", e.small_segment_radius_cells());
  p.in_range("explore.kmeans_max_iterations", 1, INT_MAX, e.kmeans_max_iterations());

  validate_link(p, "sim_robot", s.links().sim_robot());
  validate_link(p, "member_leader", s.links().member_leader());
  validate_link(p, "leader_gcs", s.links().leader_gcs());

  for (int i = 0; i < s.faults_size(); ++i) validate_fault(p, s, i);
  validate_fault_times(p, s);

  // A phase's own settings are its task's to check (its registry row's `check`,
  // tasks::check_mission), once the map is known.
  for (int i = 0; i < s.mission().phase_size(); ++i) {
    if (s.mission().phase(i).task_case() == swarm::scenario::Phase::TASK_NOT_SET) {
      p.add("mission.phase[" + std::to_string(i) + "]", "name its task: " + task_list_with_braces(), "no task");
    }
  }

  check_numbers(s, p);
  p.throw_if_any();
}

const pb::FieldDescriptor& task_field(const swarm::scenario::Phase& phase) {
  const pb::FieldDescriptor* f = phase.GetReflection()->GetOneofFieldDescriptor(phase, &task_oneof());
  // A phase that names none runs the oneof's first task (exploration), as the default mission does.
  return f == nullptr ? *task_oneof().field(0) : *f;
}

std::string task_name(const swarm::scenario::Phase& phase) { return task_field(phase).name(); }

std::vector<std::string> task_names() {
  std::vector<std::string> out;
  for (int i = 0; i < task_oneof().field_count(); ++i) out.push_back(task_oneof().field(i)->name());
  return out;
}

int leader_standbys(const Scenario& s) {
  const int most = s.robots_per_group() > 0 ? static_cast<int>(s.robots_per_group()) - 1 : 0;
  return std::min(static_cast<int>(s.leader_standbys()), most);
}

std::vector<swarm::scenario::Phase> mission_phases(const Scenario& s) {
  std::vector<swarm::scenario::Phase> out;
  for (const auto& ph : s.mission().phase()) out.push_back(ph);
  if (out.empty()) {
    auto& ph = out.emplace_back();
    ph.GetReflection()->MutableMessage(&ph, task_oneof().field(0));
  }
  const pb::Descriptor& top = *Scenario::descriptor();
  for (auto& ph : out) {
    if (ph.task_case() == swarm::scenario::Phase::TASK_NOT_SET) continue;  // validate() refuses it
    const pb::FieldDescriptor& task = task_field(ph);
    for (int i = 0; i < top.field_count(); ++i) {
      const pb::FieldDescriptor* defaults = top.field(i);
      if (defaults->is_repeated() || defaults->message_type() != task.message_type()) continue;
      pb::Message* own = ph.GetReflection()->MutableMessage(&ph, &task);
      std::unique_ptr<pb::Message> merged(own->New());
      merged->CopyFrom(s.GetReflection()->GetMessage(s, defaults));
      merged->MergeFrom(*own);
      own->CopyFrom(*merged);
    }
  }
  return out;
}

void set_mission(Scenario& s, const std::vector<std::string>& tasks) {
  const std::vector<std::string> names = task_names();
  s.clear_mission();
  for (const std::string& t : tasks) {
    if (std::find(names.begin(), names.end(), t) == names.end()) {
      std::string accepted;
      for (std::size_t i = 0; i < names.size(); ++i) {
        accepted += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
      }
      throw ConfigError("unknown task '" + t + "': expected " + accepted);
    }
    auto* ph = s.mutable_mission()->add_phase();
    ph->GetReflection()->MutableMessage(ph, task_oneof().containing_type()->FindFieldByName(t));
  }
}

std::string to_text(const Scenario& s) {
  std::string out;
  pb::TextFormat::Printer printer;
  if (!printer.PrintToString(s, &out)) {
    throw ConfigError("cannot print scenario '" + s.name() + "'");
  }
  return out;
}

swarm::scenario::Mode parse_mode(const std::string& name) {
  const std::string n = normalise_mode(name);
  if (n == "group-frontier") return swarm::scenario::GROUP_FRONTIER;
  if (n == "baseline") return swarm::scenario::BASELINE;
  if (n == "ideal") return swarm::scenario::IDEAL;
  throw ConfigError("unknown mode '" + name + "': expected one of group-frontier, baseline, ideal");
}

std::string mode_name(swarm::scenario::Mode mode) {
  switch (mode) {
    case swarm::scenario::GROUP_FRONTIER:
      return "group-frontier";
    case swarm::scenario::BASELINE:
      return "baseline";
    case swarm::scenario::IDEAL:
      return "ideal";
  }
  return "mode(" + std::to_string(static_cast<int>(mode)) + ")";
}

}  // namespace swarm::config
