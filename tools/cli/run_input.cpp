#include "run_input.hpp"

#include <filesystem>

#include "swarm/record/record.hpp"

namespace swarm::tools {

std::optional<std::vector<record::Frame>> read_run(const std::string& run_dir, const std::string& me, std::ostream& err) {
  std::error_code ec;
  const std::string path = record::run_record_path(run_dir);
  if (!std::filesystem::is_directory(run_dir, ec) || !std::filesystem::exists(path, ec)) {
    err << me << ": " << run_dir << " is not a run directory (it has no " << record::kRunRecordFile
        << "); give one written by `swarm run`\n";
    return std::nullopt;
  }
  std::vector<record::Frame> frames;
  try {
    frames = record::read_record(path);
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return std::nullopt;
  }
  if (frames.empty() || !frames.front().has_header()) {
    err << me << ": " << path << " does not start with a Header frame; is it a run record?\n";
    return std::nullopt;
  }
  return frames;
}

std::optional<config::World> world_of_record(const record::Header& header, const std::string& run_dir, std::string& why) {
  for (const std::string& dir : {run_dir, std::string(".")}) {
    try {
      return config::resolve_world(header.scenario(), dir);
    } catch (const std::exception& e) {
      why = e.what();
    }
  }
  return std::nullopt;
}

}  // namespace swarm::tools
