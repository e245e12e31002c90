// `swarm export RUN_DIR --mcap FILE`: a run record as an MCAP file (mcap_export.hpp).
#include <chrono>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "mcap_export.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/record/record.hpp"

namespace swarm::tools {

namespace fs = std::filesystem;

int export_command(const ExportOptions& o, std::ostream& out, std::ostream& err) {
  const std::string me = "swarm export";
  std::error_code ec;
  if (!fs::is_directory(o.run_dir, ec)) {
    err << me << ": " << o.run_dir << " is not a directory; give a run directory written by `swarm run`\n";
    return 2;
  }
  const std::string record = swarm::record::run_record_path(o.run_dir);
  if (!fs::exists(record, ec)) {
    err << me << ": " << o.run_dir << " is not a run directory: it has no " << swarm::record::kRunRecordFile << "\n";
    return 2;
  }
  if (o.mcap_path.empty()) {
    err << me << ": say what to write: --mcap FILE\n";
    return 2;
  }
  std::vector<swarm::record::Frame> frames;
  try {
    frames = swarm::record::read_record(record);
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }
  if (frames.empty() || !frames.front().has_header()) {
    err << me << ": " << record << " does not start with a Header frame; is it a run record?\n";
    return 2;
  }
  // The map file, for the ground-truth map and the LiDAR: from the run directory (a relative map
  // path in the scenario), or from here.
  std::optional<config::World> world;
  std::string why;
  for (const std::string& dir : {o.run_dir, std::string(".")}) {
    try {
      world = config::resolve_world(frames.front().header().scenario(), dir);
      break;
    } catch (const std::exception& e) {
      why = e.what();
    }
  }
  if (!world) err << me << ": no /map/truth or /scan channels: " << why << "\n";
  const auto t0 = std::chrono::steady_clock::now();
  McapExport done;
  try {
    done = export_mcap(frames, world ? &*world : nullptr, o.mcap_path);
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return 2;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out << o.mcap_path << ": " << done.messages << " messages, " << done.bytes << " bytes, in " << seconds << " s\n";
  for (const auto& [topic, n] : done.per_topic) out << "  " << topic << "  " << n << "\n";
  return 0;
}

}  // namespace swarm::tools
