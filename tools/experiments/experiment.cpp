#include "experiment.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "experiment_analysis.hpp"
#include "run_command.hpp"
#include "swarm/record/metrics.hpp"
#include "swarm/config/scenario.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
namespace cfg = swarm::config;
using nlohmann::json;
using analysis::encoding_name;
using analysis::format_number;

std::string status_name(RunStatus s) {
  switch (s) {
    case RunStatus::kOk:
      return "ok";
    case RunStatus::kFailed:
      return "failed";
    case RunStatus::kPending:
      break;
  }
  return "pending";
}

RunStatus parse_status(const std::string& s) {
  if (s == "ok") return RunStatus::kOk;
  if (s == "failed") return RunStatus::kFailed;
  return RunStatus::kPending;
}

swarm::scenario::MapEncoding parse_encoding(const std::string& name, const std::string& where) {
  swarm::scenario::MapEncoding e{};
  if (!swarm::scenario::MapEncoding_Parse(name, &e)) {
    throw cfg::ConfigError(where + ": unknown map encoding '" + name +
                           "' (expected RAW_CELLS, RUN_LENGTH or ZSTD_RUN_LENGTH)");
  }
  return e;
}

json setting_json(const RunSetting& s) {
  json j = json::object();
  if (s.leader_gcs_delay_ticks) j["leader_gcs_delay_ticks"] = *s.leader_gcs_delay_ticks;
  if (s.member_leader_delay_ticks) j["member_leader_delay_ticks"] = *s.member_leader_delay_ticks;
  if (s.map_encoding) j["map_encoding"] = encoding_name(*s.map_encoding);
  if (s.leader_gcs_bandwidth_bytes_per_s) {
    j["leader_gcs_bandwidth_bytes_per_s"] = *s.leader_gcs_bandwidth_bytes_per_s;
  }
  if (s.member_leader_bandwidth_bytes_per_s) {
    j["member_leader_bandwidth_bytes_per_s"] = *s.member_leader_bandwidth_bytes_per_s;
  }
  if (s.demand) j["demand"] = {{"link", s.demand->link}, {"basis", s.demand->basis}, {"fraction", s.demand->fraction}};
  if (s.loss) j["loss"] = *s.loss;
  return j;
}

RunSetting setting_from_json(const json& j, const std::string& where) {
  RunSetting s;
  if (j.contains("leader_gcs_delay_ticks")) s.leader_gcs_delay_ticks = j["leader_gcs_delay_ticks"];
  if (j.contains("member_leader_delay_ticks")) {
    s.member_leader_delay_ticks = j["member_leader_delay_ticks"];
  }
  if (j.contains("map_encoding")) s.map_encoding = parse_encoding(j["map_encoding"], where);
  if (j.contains("leader_gcs_bandwidth_bytes_per_s")) {
    s.leader_gcs_bandwidth_bytes_per_s = j["leader_gcs_bandwidth_bytes_per_s"];
  }
  if (j.contains("member_leader_bandwidth_bytes_per_s")) {
    s.member_leader_bandwidth_bytes_per_s = j["member_leader_bandwidth_bytes_per_s"];
  }
  if (j.contains("demand")) {
    const json& d = j["demand"];
    s.demand = DemandCap{d.at("link").get<std::string>(), d.at("basis").get<std::string>(), d.at("fraction").get<double>()};
    const auto known = [](const auto& names, const std::string& v) {
      return std::find(std::begin(names), std::end(names), v) != std::end(names);
    };
    if (!known(kCappedLinks, s.demand->link) || !known(kDemandBases, s.demand->basis) || !(s.demand->fraction > 0)) {
      throw cfg::ConfigError(where + ": a demand cap needs link leader_gcs or member_leader, basis mean or peak "
                             "and a fraction above 0");
    }
  }
  if (j.contains("loss")) s.loss = j["loss"];
  return s;
}

// The plan without its runs: results.json's "parameters" and the head of experiment.json.
json parameters_json(const ExperimentPlan& p) {
  json j = {{"kind", kind_name(p.kind)},
            {"scenario", p.scenario},
            {"maps", p.maps},
            {"methods", p.methods},
            {"seeds", p.seeds}};
  if (!p.mission.empty()) j["mission"] = p.mission;
  switch (p.kind) {
    case ExperimentKind::kLatency:
      j["planning_interval_ticks"] = p.planning_interval_ticks;
      j["leader_gcs_delays_ticks"] = p.leader_gcs_delays_ticks;
      j["member_leader_delays_ticks"] = p.member_leader_delays_ticks;
      break;
    case ExperimentKind::kBandwidth: {
      json names = json::array();
      for (auto e : p.encodings) names.push_back(encoding_name(e));
      j["encodings"] = names;
      j["leader_gcs_caps_bytes_per_s"] = p.leader_gcs_caps_bytes_per_s;
      j["cap_fractions"] = p.cap_fractions;
      j["cap_links"] = p.cap_links;
      j["cap_bases"] = p.cap_bases;
      j["cap_encoding"] = encoding_name(p.cap_encoding);
      json demand = json::object();
      for (const auto& [map, links] : p.demand) {
        for (const auto& [link, d] : links) {
          demand[map][link] = {{"mean_bytes_per_s", d.mean_bytes_per_s},
                               {"peak_bytes_per_s", d.peak_bytes_per_s},
                               {"runs", d.runs},
                               {"busiest_sender_mean_bytes_per_s", d.busiest_mean_bytes_per_s},
                               {"busiest_sender", d.busiest_sender},
                               {"busiest_sender_runs", d.busiest_sender_runs}};
        }
      }
      j["demand_per_sender"] = demand;
      break;
    }
    case ExperimentKind::kLoss:
      j["losses"] = p.losses;
      break;
    case ExperimentKind::kExplore:
      break;
  }
  if (!p.from_manifest) j["from"] = "run directories";
  return j;
}

std::string run_dir_of(const std::string& experiment_dir, const ExperimentRun& r) {
  if (experiment_dir.empty() || fs::path(r.dir).is_absolute()) return r.dir;
  return (fs::path(experiment_dir) / r.dir).string();
}

// A short tag for a run directory name.
std::string setting_tag(const RunSetting& s) {
  std::string tag;
  auto add = [&](const std::string& part) { tag += (tag.empty() ? "" : "-") + part; };
  if (s.leader_gcs_delay_ticks) add("lg" + std::to_string(*s.leader_gcs_delay_ticks));
  if (s.member_leader_delay_ticks) add("ml" + std::to_string(*s.member_leader_delay_ticks));
  if (s.map_encoding) {
    std::string e = encoding_name(*s.map_encoding);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) {
      return c == '_' ? '-' : static_cast<char>(std::tolower(c));
    });
    add(e);
  }
  if (s.demand) {
    char percent[32];
    std::snprintf(percent, sizeof percent, "%g", 100 * s.demand->fraction);
    add((s.demand->link == "leader_gcs" ? "lg-" : "ml-") + s.demand->basis + percent);
  } else if (s.leader_gcs_bandwidth_bytes_per_s) {
    add(*s.leader_gcs_bandwidth_bytes_per_s > 0
            ? "cap" + format_number(*s.leader_gcs_bandwidth_bytes_per_s, 0)
            : "nocap");
  }
  if (s.loss) add("loss" + format_number(*s.loss * 100.0, 0));
  return tag;
}


std::vector<std::string> setting_columns(ExperimentKind kind) {
  switch (kind) {
    case ExperimentKind::kLatency:
      return {"leader_gcs_delay_ticks", "member_leader_delay_ticks"};
    case ExperimentKind::kBandwidth:
      return {"map_encoding", "leader_gcs_bandwidth_bytes_per_s", "member_leader_bandwidth_bytes_per_s",
              "cap_link", "cap_basis", "cap_fraction"};
    case ExperimentKind::kLoss:
      return {"loss"};
    case ExperimentKind::kExplore:
      break;
  }
  return {};
}

std::vector<std::string> setting_values(ExperimentKind kind, const RunSetting& s) {
  auto opt = [](const auto& v, auto&& f) { return v ? f(*v) : std::string(); };
  switch (kind) {
    case ExperimentKind::kLatency:
      return {opt(s.leader_gcs_delay_ticks, [](auto v) { return std::to_string(v); }),
              opt(s.member_leader_delay_ticks, [](auto v) { return std::to_string(v); })};
    case ExperimentKind::kBandwidth:
      return {opt(s.map_encoding, [](auto v) { return encoding_name(v); }),
              opt(s.leader_gcs_bandwidth_bytes_per_s, [](double v) { return format_number(v, 1); }),
              opt(s.member_leader_bandwidth_bytes_per_s, [](double v) { return format_number(v, 1); }),
              opt(s.demand, [](const DemandCap& d) { return d.link; }),
              opt(s.demand, [](const DemandCap& d) { return d.basis; }),
              opt(s.demand, [](const DemandCap& d) { return format_number(d.fraction, 3); })};
    case ExperimentKind::kLoss:
      return {opt(s.loss, [](double v) { return format_number(v, 2); })};
    case ExperimentKind::kExplore:
      break;
  }
  return {};
}

std::string make_csv(const ExperimentPlan& plan, const std::vector<RunRow>& rows) {
  std::ostringstream o;
  const auto header = csv_header(plan.kind);
  for (std::size_t i = 0; i < header.size(); ++i) o << (i ? "," : "") << header[i];
  o << "\n";
  for (const RunRow& r : rows) {
    std::vector<std::string> cells = {r.run.dir, map_label(r.run.map), r.run.method,
                                      std::to_string(r.run.seed)};
    for (auto& v : setting_values(plan.kind, r.run.setting)) cells.push_back(v);
    if (r.numbers) {
      const RunNumbers& n = *r.numbers;
      cells.push_back(n.ended_early() ? "ended_early" : "ok");
      cells.push_back(n.complete ? "true" : "false");
      cells.push_back(format_number(n.steps, 0));
      cells.push_back(n.steps_to_99 ? format_number(*n.steps_to_99, 0) : "");
      cells.push_back(format_number(n.planning_rounds, 0));
      cells.push_back(format_number(100.0 * n.explored_fraction, 2));
      cells.push_back(format_number(n.ticks_run, 0));
      cells.push_back(format_number(n.wall_seconds, 2));
      cells.push_back(format_number(n.traffic_bytes, 0));
      cells.push_back(format_number(n.map_bytes, 0));
      cells.push_back(format_number(n.map_bytes_per_robot_second(), 1));
      cells.push_back(format_number(n.radio_bytes(), 0));
      cells.push_back(format_number(n.on_robot_bytes(), 0));
      for (const char* link : kCappedLinks) {
        const auto l = n.links.find(link);
        const auto opt = [](const std::optional<double>& v, int decimals) { return v ? format_number(*v, decimals) : ""; };
        cells.push_back(l == n.links.end() ? "" : format_number(l->second.bytes, 0));
        cells.push_back(l == n.links.end() ? "" : opt(l->second.peak_bytes_per_s, 1));
        cells.push_back(l == n.links.end() ? "" : opt(l->second.queue_median_ticks, 0));
        cells.push_back(l == n.links.end() ? "" : opt(l->second.queue_p95_ticks, 0));
      }
      cells.push_back("");
      cells.push_back("");
    } else {
      cells.push_back("failed");
      // Every number empty, up to the last two columns (log, failure).
      while (cells.size() + 2 < header.size()) cells.push_back("");
      cells.push_back(r.run.log);
      cells.push_back(r.run.failure);
    }
    for (std::size_t i = 0; i < cells.size(); ++i) o << (i ? "," : "") << csv_escape(cells[i]);
    o << "\n";
  }
  return o.str();
}

json runs_json(const ExperimentPlan& plan, const std::vector<RunRow>& rows) {
  json runs = json::array();
  for (const RunRow& r : rows) {
    json j = {{"dir", r.run.dir},
              {"map", map_label(r.run.map)},
              {"method", r.run.method},
              {"seed", r.run.seed},
              {"setting", setting_json(r.run.setting)},
              {"status", !r.numbers ? "failed" : r.numbers->ended_early() ? "ended_early" : "ok"}};
    if (r.numbers) {
      const RunNumbers& n = *r.numbers;
      j["complete"] = n.complete;
      j["steps"] = n.steps;
      j["steps_to_99"] = analysis::optional_json(n.steps_to_99);
      j["planning_rounds"] = n.planning_rounds;
      j["explored_fraction"] = n.explored_fraction;
      j["ticks_run"] = n.ticks_run;
      j["wall_seconds"] = n.wall_seconds;
      j["robots"] = n.robots;
      j["tick_seconds"] = n.tick_seconds;
      j["traffic_bytes"] = n.traffic_bytes;
      j["map_bytes"] = n.map_bytes;
      j["map_bytes_per_robot_second"] = n.map_bytes_per_robot_second();
      j["conflicts"] = n.conflicts;
      j["delivered"] = analysis::optional_json(n.delivered);
      j["radio_bytes"] = n.radio_bytes();
      j["sim_robot_on_robot_bytes"] = n.on_robot_bytes();
      for (const auto& [link, l] : n.links) {
        j["links"][link] = {{"bytes", l.bytes},
                            {"peak_bytes_per_s", analysis::optional_json(l.peak_bytes_per_s)},
                            {"queue_median_ticks", analysis::optional_json(l.queue_median_ticks)},
                            {"queue_p95_ticks", analysis::optional_json(l.queue_p95_ticks)},
                            {"dropped_messages", l.dropped_messages}};
      }
    } else {
      j["failure"] = r.run.failure;
      j["log"] = r.run.log;
    }
    runs.push_back(j);
  }
  return runs;
}


}  // namespace

std::string csv_escape(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) {
    throw std::runtime_error("cannot write " + path.string() + " (" + std::strerror(errno) + ")");
  }
}

// ---- kinds, settings, defaults --------------------------------------------------------------

std::string kind_name(ExperimentKind kind) {
  switch (kind) {
    case ExperimentKind::kExplore:
      return "explore";
    case ExperimentKind::kLatency:
      return "latency";
    case ExperimentKind::kBandwidth:
      return "bandwidth";
    case ExperimentKind::kLoss:
      return "loss";
  }
  return "explore";
}

std::optional<ExperimentKind> parse_kind(const std::string& name) {
  for (auto k : {ExperimentKind::kExplore, ExperimentKind::kLatency, ExperimentKind::kBandwidth,
                 ExperimentKind::kLoss}) {
    if (kind_name(k) == name) return k;
  }
  return std::nullopt;
}

RunSetting RunSetting::delays(std::uint32_t leader_gcs, std::uint32_t member_leader) {
  RunSetting s;
  s.leader_gcs_delay_ticks = leader_gcs;
  s.member_leader_delay_ticks = member_leader;
  return s;
}

RunSetting RunSetting::encoding_and_cap(swarm::scenario::MapEncoding e, double bytes_per_s) {
  RunSetting s;
  s.map_encoding = e;
  s.leader_gcs_bandwidth_bytes_per_s = bytes_per_s;
  return s;
}

RunSetting RunSetting::demand_cap(swarm::scenario::MapEncoding e, DemandCap cap) {
  RunSetting s;
  s.map_encoding = e;
  s.demand = std::move(cap);
  return s;
}

bool RunSetting::waits_for_demand() const {
  if (!demand) return false;
  return demand->link == "leader_gcs" ? !leader_gcs_bandwidth_bytes_per_s : !member_leader_bandwidth_bytes_per_s;
}

RunSetting RunSetting::every_link_loss(double loss) {
  RunSetting s;
  s.loss = loss;
  return s;
}

void RunSetting::apply(swarm::scenario::Scenario& s) const {
  auto* links = s.mutable_links();
  if (leader_gcs_delay_ticks) links->mutable_leader_gcs()->set_delay_ticks(*leader_gcs_delay_ticks);
  if (member_leader_delay_ticks) {
    links->mutable_member_leader()->set_delay_ticks(*member_leader_delay_ticks);
  }
  if (map_encoding) s.set_map_encoding(*map_encoding);
  if (leader_gcs_bandwidth_bytes_per_s) {
    links->mutable_leader_gcs()->set_bandwidth_bytes_per_s(*leader_gcs_bandwidth_bytes_per_s);
  }
  if (member_leader_bandwidth_bytes_per_s) {
    links->mutable_member_leader()->set_bandwidth_bytes_per_s(*member_leader_bandwidth_bytes_per_s);
  }
  if (loss) {
    links->mutable_sim_robot()->set_loss(*loss);
    links->mutable_member_leader()->set_loss(*loss);
    links->mutable_leader_gcs()->set_loss(*loss);
  }
}

std::vector<std::string> known_methods() { return {"group-frontier", "baseline", "ideal"}; }

std::vector<std::string> default_maps(ExperimentKind kind) {
  if (kind == ExperimentKind::kExplore) return {"open", "maze1", "maze2"};
  return {"maze1"};
}

std::vector<std::string> default_methods(ExperimentKind kind) {
  switch (kind) {
    case ExperimentKind::kExplore:
      return known_methods();
    case ExperimentKind::kBandwidth:
      return {"group-frontier"};
    case ExperimentKind::kLatency:
    case ExperimentKind::kLoss:
      break;
  }
  return {"group-frontier", "baseline"};
}

std::uint32_t default_seeds(ExperimentKind kind) {
  // Table 2's differences (group-frontier and ideal against the baseline, on each of the three
  // maps) are all significant from 7 seeds on (the paired 95 % intervals, measured on seeds
  // 1..N for N = 2..8); 8 keeps a margin and takes 3 min 37 s on 2 cores (README, Experiments).
  return kind == ExperimentKind::kExplore ? 8 : 3;
}

ExperimentPlan make_plan(ExperimentKind kind, std::vector<std::string> maps,
                         std::vector<std::string> methods, std::uint32_t seeds,
                         const swarm::scenario::Scenario& base, const std::string& scenario_path,
                         const SweepChoices& choices) {
  ExperimentPlan p;
  p.kind = kind;
  p.scenario = scenario_path;
  p.maps = std::move(maps);
  p.methods = std::move(methods);
  p.seeds = seeds;
  switch (kind) {
    case ExperimentKind::kLatency: {
      // 0, 1/2, 1, 2 and 4 planning intervals.
      const std::uint32_t interval = base.explore().replan_threshold_steps();
      p.planning_interval_ticks = interval;
      p.leader_gcs_delays_ticks = {0, (interval + 1) / 2, interval, 2 * interval, 4 * interval};
      p.member_leader_delays_ticks = {0, 1, 5, 10};
      break;
    }
    case ExperimentKind::kBandwidth:
      p.encodings = {swarm::scenario::RAW_CELLS, swarm::scenario::RUN_LENGTH,
                     swarm::scenario::ZSTD_RUN_LENGTH};
      if (!choices.encodings.empty()) p.encodings = choices.encodings;
      // Caps from the measured demand (the uncapped runs first): twice it down to an eighth, on
      // both radio link classes, of the mean and of the peak.
      p.cap_fractions = choices.cap_fractions.empty() ? std::vector<double>{2.0, 1.0, 0.5, 0.25, 0.125} : choices.cap_fractions;
      p.cap_links = choices.cap_links.empty() ? std::vector<std::string>(std::begin(kCappedLinks), std::end(kCappedLinks))
                                              : choices.cap_links;
      p.cap_bases = choices.cap_bases.empty() ? std::vector<std::string>(std::begin(kDemandBases), std::end(kDemandBases))
                                              : choices.cap_bases;
      p.leader_gcs_caps_bytes_per_s = choices.leader_gcs_caps_bytes_per_s;
      p.cap_encoding = base.map_encoding();
      break;
    case ExperimentKind::kLoss:
      p.losses = {0.0, 0.05, 0.20};
      break;
    case ExperimentKind::kExplore:
      break;
  }
  const auto settings = analysis::settings_of(p);
  for (const std::string& map : p.maps) {
    for (const std::string& method : p.methods) {
      for (const RunSetting& setting : settings) {
        for (std::uint32_t seed = 1; seed <= seeds; ++seed) {
          ExperimentRun r;
          const std::string tag = setting_tag(setting);
          r.dir = "runs/" + map_label(map) + "-" + method + (tag.empty() ? "" : "-" + tag) + "-s" +
                  std::to_string(seed);
          r.map = map;
          r.method = method;
          r.seed = seed;
          r.setting = setting;
          r.pictures = kind == ExperimentKind::kExplore && seed == 1;
          p.runs.push_back(r);
        }
      }
    }
  }
  return p;
}

// ---- the manifest ----------------------------------------------------------------------------

void write_manifest(const std::string& dir, const ExperimentPlan& plan) {
  json j = parameters_json(plan);
  j["swarm_experiment"] = 1;
  json runs = json::array();
  for (const ExperimentRun& r : plan.runs) {
    runs.push_back({{"dir", r.dir},
                    {"map", r.map},
                    {"method", r.method},
                    {"seed", r.seed},
                    {"setting", setting_json(r.setting)},
                    {"pictures", r.pictures},
                    {"status", status_name(r.status)},
                    {"failure", r.failure},
                    {"log", r.log}});
  }
  j["runs"] = runs;
  // Written whole, then renamed: a reader never sees half a file.
  const fs::path path = fs::path(dir) / kManifestFile;
  const fs::path tmp = fs::path(dir) / (std::string(kManifestFile) + ".tmp");
  write_file(tmp, j.dump(2) + "\n");
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot write " + path.string() + " (" + ec.message() + ")");
}

ExperimentPlan read_manifest(const std::string& dir) {
  const std::string path = (fs::path(dir) / kManifestFile).string();
  std::ifstream in(path);
  if (!in) {
    throw cfg::ConfigError("cannot read " + path + "; is " + dir + " an experiment directory?");
  }
  json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw cfg::ConfigError(path + " is not valid JSON (" + e.what() +
                           "); it is written by `swarm experiment`");
  }
  try {
    ExperimentPlan p;
    const auto kind = parse_kind(j.at("kind").get<std::string>());
    if (!kind) {
      throw cfg::ConfigError(path + ": unknown experiment kind '" +
                             j.at("kind").get<std::string>() +
                             "' (expected explore, latency, bandwidth or loss)");
    }
    p.kind = *kind;
    p.scenario = j.value("scenario", "");
    p.maps = j.at("maps").get<std::vector<std::string>>();
    p.methods = j.at("methods").get<std::vector<std::string>>();
    p.seeds = j.at("seeds").get<std::uint32_t>();
    p.mission = j.value("mission", std::vector<std::string>{});
    p.planning_interval_ticks = j.value("planning_interval_ticks", 0u);
    p.leader_gcs_delays_ticks =
        j.value("leader_gcs_delays_ticks", std::vector<std::uint32_t>{});
    p.member_leader_delays_ticks =
        j.value("member_leader_delays_ticks", std::vector<std::uint32_t>{});
    for (const auto& e : j.value("encodings", std::vector<std::string>{})) {
      p.encodings.push_back(parse_encoding(e, path));
    }
    p.leader_gcs_caps_bytes_per_s = j.value("leader_gcs_caps_bytes_per_s", std::vector<double>{});
    p.cap_fractions = j.value("cap_fractions", std::vector<double>{});
    p.cap_links = j.value("cap_links", std::vector<std::string>{});
    p.cap_bases = j.value("cap_bases", std::vector<std::string>{});
    const json demand = j.value("demand_per_sender", json::object());
    for (const auto& [map, links] : demand.items()) {
      for (const auto& [link, d] : links.items()) {
        p.demand[map][link] = {d.at("mean_bytes_per_s").get<double>(), d.at("peak_bytes_per_s").get<double>(),
                               d.value("runs", std::size_t{0}), d.value("busiest_sender_mean_bytes_per_s", 0.0),
                               d.value("busiest_sender", std::string{}), d.value("busiest_sender_runs", std::size_t{0})};
      }
    }
    if (j.contains("cap_encoding")) p.cap_encoding = parse_encoding(j["cap_encoding"], path);
    p.losses = j.value("losses", std::vector<double>{});
    for (const json& r : j.at("runs")) {
      ExperimentRun run;
      run.dir = r.at("dir");
      run.map = r.at("map");
      run.method = r.at("method");
      run.seed = r.at("seed");
      run.setting = setting_from_json(r.value("setting", json::object()), path);
      run.pictures = r.value("pictures", false);
      run.status = parse_status(r.value("status", "pending"));
      run.failure = r.value("failure", "");
      run.log = r.value("log", "");
      p.runs.push_back(run);
    }
    return p;
  } catch (const json::exception& e) {
    throw cfg::ConfigError(path + " is damaged (" + e.what() +
                           "); it is written by `swarm experiment`");
  }
}

// ---- run numbers ------------------------------------------------------------------------------

double RunNumbers::map_bytes_per_robot_second() const {
  const double robot_seconds = robots * ticks_run * tick_seconds;
  return robot_seconds > 0 ? map_bytes / robot_seconds : 0.0;
}

double RunNumbers::on_robot_bytes() const {
  const auto l = links.find("sim_robot");
  return l == links.end() ? 0.0 : l->second.bytes;
}

double RunNumbers::radio_bytes() const { return traffic_bytes - on_robot_bytes(); }

double RunNumbers::senders(const std::string& link) const {
  if (link == "leader_gcs") return groups + 1.0;
  if (link == "member_leader") return robots;
  return 0;
}

double RunNumbers::mean_bytes_per_s_per_sender(const std::string& link) const {
  const auto l = links.find(link);
  const double seconds = ticks_run * tick_seconds;
  return l == links.end() || seconds <= 0 || senders(link) <= 0 ? 0.0 : l->second.bytes / seconds / senders(link);
}

std::optional<double> RunNumbers::peak_bytes_per_s_per_sender(const std::string& link) const {
  const auto l = links.find(link);
  if (l == links.end() || !l->second.peak_bytes_per_s || senders(link) <= 0) return std::nullopt;
  return *l->second.peak_bytes_per_s / senders(link);
}

std::string ExperimentPlan::Demand::busiest_sender_text() const {
  if (busiest_sender_runs == 0) return busiest_sender;
  return busiest_sender + " in " + std::to_string(busiest_sender_runs) + " of " + std::to_string(runs) + " runs";
}

std::optional<double> RunNumbers::busiest_sender_bytes_per_s(const std::string& link) const {
  const auto l = links.find(link);
  const double seconds = ticks_run * tick_seconds;
  if (l == links.end() || l->second.busiest_sender.empty() || seconds <= 0) return std::nullopt;
  return l->second.busiest_sender_bytes / seconds;
}

bool RunNumbers::ended_early() const {
  return explores && complete && explored_fraction < kCompleteExploredFraction;
}

const std::vector<std::string>& map_topics() {
  static const std::vector<std::string> topics = {"patch_up", "patch_down", "patch_gcs", "round"};
  return topics;
}

namespace {
// Each link's busiest whole second in RUN_DIR/traffic.csv (tools/cli/traffic_over_time.hpp: columns
// "second", "<link>_bytes_per_s", the on-robot link "..._on_robot_bytes_per_s"); nothing when the
// run has no such file. The last bin, often shorter than a second, is left out.
std::map<std::string, double> peak_rates(const std::string& run_dir) {
  std::map<std::string, double> peak;
  std::ifstream in(fs::path(run_dir) / "traffic.csv");
  std::string line;
  if (!in || !std::getline(in, line)) return peak;
  std::vector<std::string> links;
  std::stringstream head(line);
  for (std::string c; std::getline(head, c, ',');) {
    const std::string suffix = "_bytes_per_s";
    links.push_back(c.size() > suffix.size() && c.ends_with(suffix) ? c.substr(0, c.size() - suffix.size()) : "");
  }
  double last_second = 0;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::vector<double> v;
    for (std::string c; std::getline(row, c, ',');) v.push_back(std::strtod(c.c_str(), nullptr));
    if (v.empty()) continue;
    const bool whole = v[0] - last_second > 0.999;
    last_second = v[0];
    if (!whole) continue;
    for (std::size_t k = 1; k < v.size() && k < links.size(); ++k) {
      if (!links[k].empty()) peak[links[k]] = std::max(peak[links[k]], v[k]);
    }
  }
  return peak;
}
}  // namespace

std::optional<RunNumbers> load_run_numbers(const std::string& run_dir, std::string& why) {
  swarm::record::RunMetrics m;
  try {
    m = swarm::record::read_metrics((fs::path(run_dir) / "metrics.json").string());
  } catch (const swarm::record::MetricsError& e) {
    why = e.what();
    return std::nullopt;
  }
  RunNumbers n;
  n.complete = m.complete;
  n.steps = m.steps;
  if (m.steps_to_99) n.steps_to_99 = *m.steps_to_99;
  n.planning_rounds = m.planning_rounds;
  n.explored_fraction = m.explored_fraction;
  n.ticks_run = m.ticks_run;
  n.wall_seconds = m.wall_seconds;
  n.groups = m.groups;
  n.robots_per_group = m.robots_per_group;
  n.robots = m.robots;
  n.traffic_bytes = static_cast<double>(m.traffic.total_bytes);
  n.explores = m.phases.empty() || m.phases.front().name == "explore";
  n.conflicts = static_cast<double>(m.motion.vertex_conflict_events + m.motion.edge_conflict_events);
  for (const auto& p : m.phases) {
    // A phase that never ended (the run stopped in it) ran to the run's last tick: a lower bound,
    // which the table marks as it marks the run incomplete.
    const double end = p.end_tick ? static_cast<double>(*p.end_tick) : m.ticks_run;
    n.phase_ticks.push_back(end - static_cast<double>(p.start_tick));
    if (p.name == "collect" && p.task.contains("delivered")) n.delivered = n.delivered.value_or(0) + p.task["delivered"].get<double>();
  }
  for (const std::string& topic : map_topics()) {
    if (auto it = m.traffic.by_topic.find(topic); it != m.traffic.by_topic.end()) n.map_bytes += it->second.bytes;
  }
  for (const auto& [link, l] : m.traffic.by_link) {
    RunNumbers::Link& out = n.links[link];
    out.bytes = static_cast<double>(l.bytes);
    out.dropped_messages = static_cast<double>(l.dropped_messages);
    if (const auto q = swarm::record::queue_quantile(l.queued_ticks, 0.5)) out.queue_median_ticks = *q;
    if (const auto q = swarm::record::queue_quantile(l.queued_ticks, 0.95)) out.queue_p95_ticks = *q;
    out.busiest_sender = l.busiest_sender;
    out.busiest_sender_bytes = static_cast<double>(l.busiest_sender_bytes);
  }
  for (const auto& [link, peak] : peak_rates(run_dir)) n.links[link].peak_bytes_per_s = peak;
  // tick_seconds is a scenario field, not a metric.
  const std::string scenario_path = (fs::path(run_dir) / "scenario.pbtxt").string();
  std::ifstream sin(scenario_path, std::ios::binary);
  if (!sin) {
    why = "no scenario.pbtxt in " + run_dir;
    return std::nullopt;
  }
  try {
    std::stringstream text;
    text << sin.rdbuf();
    n.tick_seconds = cfg::parse_scenario_text(text.str(), scenario_path).tick_seconds();
  } catch (const cfg::ConfigError& e) {
    why = e.what();
    return std::nullopt;
  }
  return n;
}

std::vector<std::string> resolve_demand(ExperimentPlan& plan, const std::vector<RunRow>& rows) {
  std::vector<std::string> missing;
  const auto uncapped = [&](const RunSetting& s) {
    return !s.demand && !s.member_leader_bandwidth_bytes_per_s && s.leader_gcs_bandwidth_bytes_per_s.value_or(0) <= 0 &&
           s.map_encoding == plan.cap_encoding;
  };
  for (const std::string& map : plan.maps) {
    const std::string label = map_label(map);
    for (const std::string& link : plan.cap_links) {
      std::vector<double> mean, peak, busiest;
      std::map<std::string, int> busiest_names;
      for (const RunRow& r : rows) {
        if (r.run.map != map || !r.numbers || r.numbers->ended_early() || !uncapped(r.run.setting)) continue;
        const auto p = r.numbers->peak_bytes_per_s_per_sender(link);
        if (!p) continue;
        mean.push_back(r.numbers->mean_bytes_per_s_per_sender(link));
        peak.push_back(*p);
        if (const auto b = r.numbers->busiest_sender_bytes_per_s(link)) {
          busiest.push_back(*b);
          ++busiest_names[r.numbers->links.at(link).busiest_sender];
        }
      }
      ExperimentPlan::Demand d{summarize(mean).mean, summarize(peak).mean, mean.size(), 0.0, {}, 0};
      if (!busiest.empty()) {
        d.busiest_mean_bytes_per_s = summarize(busiest).mean;
        const auto most = std::max_element(busiest_names.begin(), busiest_names.end(),
                                           [](const auto& a, const auto& b) { return a.second < b.second; });
        d.busiest_sender = most->first;
        d.busiest_sender_runs = static_cast<std::size_t>(most->second);
      }
      if (mean.empty() || !(d.mean_bytes_per_s > 0) || !(d.peak_bytes_per_s > 0)) {
        if (std::find(missing.begin(), missing.end(), label) == missing.end()) missing.push_back(label);
        continue;
      }
      plan.demand[label][link] = d;
    }
  }
  for (ExperimentRun& run : plan.runs) {
    if (!run.setting.waits_for_demand()) continue;
    const auto m = plan.demand.find(map_label(run.map));
    if (m == plan.demand.end() || !m->second.count(run.setting.demand->link)) continue;
    const ExperimentPlan::Demand& d = m->second.at(run.setting.demand->link);
    const double rate = run.setting.demand->fraction * (run.setting.demand->basis == "peak" ? d.peak_bytes_per_s : d.mean_bytes_per_s);
    (run.setting.demand->link == "leader_gcs" ? run.setting.leader_gcs_bandwidth_bytes_per_s
                                              : run.setting.member_leader_bandwidth_bytes_per_s) = rate;
  }
  return missing;
}

std::vector<RunRow> load_rows(const std::string& experiment_dir, const ExperimentPlan& plan) {
  std::vector<RunRow> rows;
  for (const ExperimentRun& run : plan.runs) {
    RunRow row{run, std::nullopt};
    if (run.status != RunStatus::kFailed) {
      std::string why;
      row.numbers = load_run_numbers(run_dir_of(experiment_dir, run), why);
      if (!row.numbers) {
        row.run.status = RunStatus::kFailed;
        row.run.failure = run.status == RunStatus::kPending
                              ? "did not run (the experiment was interrupted)"
                              : why;
      } else {
        row.run.status = RunStatus::kOk;
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

ExperimentPlan plan_from_run_dirs(const std::vector<std::string>& run_dirs) {
  ExperimentPlan p;
  p.kind = ExperimentKind::kExplore;
  p.from_manifest = false;
  std::set<std::uint64_t> seeds;
  std::vector<std::string> maps, methods;
  for (const std::string& dir : run_dirs) {
    swarm::record::RunMetrics m;
    try {
      m = swarm::record::read_metrics((fs::path(dir) / "metrics.json").string());
    } catch (const swarm::record::MetricsError& e) {
      throw cfg::ConfigError(dir + " is not a usable run directory: " + e.what());
    }
    ExperimentRun r;
    r.dir = dir;
    r.map = m.map;
    r.method = m.mode;
    r.seed = m.seed;
    r.status = RunStatus::kOk;
    seeds.insert(r.seed);
    if (std::find(maps.begin(), maps.end(), r.map) == maps.end()) maps.push_back(r.map);
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) {
      methods.push_back(r.method);
    }
    p.runs.push_back(r);
  }
  const auto builtin = cfg::builtin_map_names();
  auto rank = [&](const std::string& m) {
    const auto it = std::find(builtin.begin(), builtin.end(), m);
    return std::make_pair(static_cast<int>(it - builtin.begin()), map_label(m));
  };
  std::sort(maps.begin(), maps.end(),
            [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
  const auto known = known_methods();
  auto method_rank = [&](const std::string& m) {
    const auto it = std::find(known.begin(), known.end(), m);
    return std::make_pair(static_cast<int>(it - known.begin()), m);
  };
  std::sort(methods.begin(), methods.end(),
            [&](const auto& a, const auto& b) { return method_rank(a) < method_rank(b); });
  p.maps = maps;
  p.methods = methods;
  p.seeds = static_cast<std::uint32_t>(seeds.size());
  return p;
}

// ---- outputs ----------------------------------------------------------------------------------

std::vector<std::string> csv_header(ExperimentKind kind) {
  std::vector<std::string> h = {"run", "map", "method", "seed"};
  for (auto& c : setting_columns(kind)) h.push_back(c);
  for (const char* c : {"status", "complete", "steps", "steps_to_99", "planning_rounds",
                        "explored_percent", "ticks_run", "wall_seconds", "traffic_bytes",
                        "map_bytes", "map_bytes_per_robot_second", "radio_bytes", "sim_robot_on_robot_bytes"}) {
    h.push_back(c);
  }
  for (const std::string link : kCappedLinks) {
    for (const char* c : {"_bytes", "_peak_bytes_per_s", "_queue_median_ticks", "_queue_p95_ticks"}) h.push_back(link + c);
  }
  h.push_back("log");
  h.push_back("failure");
  return h;
}

ExperimentOutputs analyze_experiment(const ExperimentPlan& plan, const std::vector<RunRow>& rows) {
  analysis::KindOutputs k;
  switch (plan.kind) {
    case ExperimentKind::kExplore:
      analysis::analyze_explore(plan, rows, k);
      break;
    case ExperimentKind::kLatency:
      analysis::analyze_latency(plan, rows, k);
      break;
    case ExperimentKind::kBandwidth:
      analysis::analyze_bandwidth(plan, rows, k);
      break;
    case ExperimentKind::kLoss:
      analysis::analyze_loss(plan, rows, k);
      break;
  }
  ExperimentOutputs o;
  o.table = k.table;
  o.csv = make_csv(plan, rows);
  const json results = {{"experiment", kind_name(plan.kind)},
                        {"parameters", parameters_json(plan)},
                        {"runs", runs_json(plan, rows)},
                        {"aggregates", k.aggregates},
                        {"findings", k.findings}};
  o.json = results.dump(2) + "\n";
  o.figures = std::move(k.figures);
  return o;
}

std::vector<std::string> write_outputs(const std::string& dir, const ExperimentOutputs& o) {
  std::vector<std::string> written;
  auto text = [&](const char* name, const std::string& content) {
    const fs::path p = fs::path(dir) / name;
    write_file(p, content);
    written.push_back(p.string());
  };
  text("table.txt", o.table);
  text("results.csv", o.csv);
  text("results.json", o.json);
  for (const auto& [name, figure] : o.figures) {
    const fs::path p = fs::path(dir) / name;
    write_figure_png(figure, p.string());
    written.push_back(p.string());
  }
  return written;
}

}  // namespace swarm::tools
