#include "run_end.hpp"

#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "swarm/record/metrics.hpp"
#include "swarm/record/record.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// What the record says up to its last whole frame: ticks, and the phases begun and ended.
json from_record(const std::string& run_dir) {
  json out;
  try {
    const record::RecordPrefix r = record::read_record_prefix(record::run_record_path(run_dir));
    const std::optional<std::uint32_t> last = record::last_tick(r.frames);
    json phases = json::array();
    for (const record::Frame& f : r.frames) {
      if (!f.has_phase()) continue;
      const auto& p = f.phase();
      if (!p.ended()) {
        phases.push_back({{"name", p.task()}, {"start_tick", p.tick()}, {"end_tick", nullptr}, {"complete", false}});
      } else if (!phases.empty()) {
        phases.back()["end_tick"] = p.tick();
        phases.back()["complete"] = p.complete();
      }
    }
    out["ticks_run"] = last ? json(*last + 1) : json(nullptr);
    out["phases"] = phases;
    out["record"] = r.cut.empty() ? "whole" : r.cut;
  } catch (const std::exception& e) {
    out["ticks_run"] = nullptr;
    out["phases"] = json::array();
    out["record"] = e.what();
  }
  return out;
}

}  // namespace

std::string early_end_reason(const SupervisorResult& r) {
  if (r.ok) return "";
  if (r.interrupted) return "interrupted: SIGINT or SIGTERM reached the launcher";
  if (r.timed_out) return r.message;
  return r.message.empty() ? "a process failed" : r.message;
}

std::string record_early_end(const std::string& run_dir, const swarm::scenario::Scenario& s,
                             const std::string& reason) {
  const fs::path path = fs::path(run_dir) / "metrics.json";
  try {
    std::error_code ec;
    if (fs::exists(path, ec)) {
      // The GCS wrote it while the run ended itself: it holds everything up to the last tick.
      record::RunMetrics m = record::read_metrics(path.string());
      m.complete = false;
      m.ended = reason + " (the GCS: " + m.ended + ")";
      record::write_metrics(path.string(), m);
      return "";
    }
    json j = from_record(run_dir);
    j["schema_version"] = record::kMetricsSchemaVersion;
    j["partial"] = true;
    j["complete"] = false;
    j["ended"] = reason;
    j["missing"] = "the GCS wrote no metrics.json (it, or the simulator whose report it needs, had stopped): "
                   "only ticks_run and the phases begun are known, from the run record";
    j["scenario"] = s.name();
    j["map"] = s.map();
    j["seed"] = s.seed();
    j["groups"] = s.groups();
    j["robots_per_group"] = s.robots_per_group();
    j["robots"] = s.groups() * s.robots_per_group();
    std::ofstream out(path);
    out << j.dump(2) << "\n";
    if (!out.flush()) return "cannot write " + path.string();
    return "";
  } catch (const std::exception& e) {
    return path.string() + ": " + e.what();
  }
}

}  // namespace swarm::tools
