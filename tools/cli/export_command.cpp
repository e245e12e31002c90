// `swarm export RUN_DIR --mcap FILE`: a run record as an MCAP file (mcap_export.hpp).
#include <chrono>
#include <optional>

#include "commands.hpp"
#include "mcap_export.hpp"
#include "run_input.hpp"
#include "swarm/record/record.hpp"

namespace swarm::tools {

int export_command(const ExportOptions& o, std::ostream& out, std::ostream& err) {
  const std::string me = "swarm export";
  if (o.mcap_path.empty()) {
    err << me << ": say what to write: --mcap FILE\n";
    return 2;
  }
  const std::optional<std::vector<swarm::record::Frame>> read = read_run(o.run_dir, me, err);
  if (!read) return 2;
  const std::vector<swarm::record::Frame>& frames = *read;
  std::string why;
  const std::optional<config::World> world = world_of_record(frames.front().header(), o.run_dir, why);
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
