#include "swarm/record/record.hpp"

#include "swarm/planner/grid/map_patch.hpp"

#include <algorithm>

#include <google/protobuf/util/delimited_message_util.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace swarm::record {
namespace {

namespace fs = std::filesystem;

std::string resolve_record_path(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return run_record_path(path);
  return path;
}

}  // namespace

std::string run_record_path(const std::string& run_dir) {
  return (fs::path(run_dir) / kRunRecordFile).string();
}

RecordWriter::RecordWriter(const std::string& path) : path_(resolve_record_path(path)) {
  out_.open(path_, std::ios::binary | std::ios::out | std::ios::trunc);
  if (!out_) {
    throw std::runtime_error("run record " + path_ + ": cannot create the file (" +
                             std::strerror(errno) + "); does its folder exist and is it writable?");
  }
}

RecordWriter::~RecordWriter() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; call close() explicitly to see write errors.
  }
}

RecordWriter::RecordWriter(RecordWriter&& other) noexcept
    : path_(std::move(other.path_)),
      out_(std::move(other.out_)),
      frames_(other.frames_),
      bytes_(other.bytes_),
      observer_(std::move(other.observer_)) {}

RecordWriter& RecordWriter::operator=(RecordWriter&& other) noexcept {
  if (this != &other) {
    try {
      close();
    } catch (...) {
    }
    path_ = std::move(other.path_);
    out_ = std::move(other.out_);
    frames_ = other.frames_;
    bytes_ = other.bytes_;
    observer_ = std::move(other.observer_);
  }
  return *this;
}

void RecordWriter::append(const Frame& frame) {
  if (!out_.is_open()) throw std::runtime_error("run record " + path_ + ": append after close");
  const std::size_t size = frame.ByteSizeLong();
  if (!google::protobuf::util::SerializeDelimitedToOstream(frame, &out_) || !out_) {
    throw std::runtime_error("run record " + path_ + ": write of frame " + std::to_string(frames_) +
                             " failed (disk full?)");
  }
  ++frames_;
  // Varint length prefix: 7 bits per byte.
  std::size_t prefix = 1;
  for (std::size_t v = size; v >= 0x80; v >>= 7) ++prefix;
  bytes_ += prefix + size;
  if (observer_) observer_(frame);
}

void RecordWriter::flush() {
  if (!out_.is_open()) return;
  out_.flush();
  if (!out_) throw std::runtime_error("run record " + path_ + ": flush failed (disk full?)");
}

void RecordWriter::close() {
  if (!out_.is_open()) return;
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || !out_) {
    throw std::runtime_error("run record " + path_ + ": closing failed (disk full?)");
  }
}

std::optional<std::uint32_t> last_tick(const std::vector<Frame>& frames) {
  std::optional<std::uint32_t> last;
  for (const Frame& f : frames) {
    if (f.has_poses()) last = std::max(last.value_or(0), f.poses().tick());
  }
  return last;
}

planner::OccupancyGrid map_of(const Header& h, const MapVersion* version) {
  planner::OccupancyGrid grid(static_cast<int>(h.width()), static_cast<int>(h.height()),
                              h.resolution() > 0 ? h.resolution() : 0.2, h.origin_x(), h.origin_y());
  if (version == nullptr) return grid;  // nothing known yet: all unknown
  const std::string& rle = version->rle();
  if (!planner::decode_grid_rle(reinterpret_cast<const std::uint8_t*>(rle.data()), rle.size(), grid)) {
    throw std::runtime_error("run record: the map version of tick " + std::to_string(version->tick()) +
                             " does not decode to " + std::to_string(h.width()) + " x " + std::to_string(h.height()) +
                             " cells (damaged record?)");
  }
  return grid;
}

std::vector<std::string> robot_names(const Header& h) {
  std::vector<std::string> names;
  for (std::uint32_t g = 0; g < h.groups(); ++g) {
    for (std::uint32_t i = 0; i < h.robots_per_group(); ++i) {
      names.push_back(i == 0 ? "leader-" + std::to_string(g) : "member-" + std::to_string(g) + "-" + std::to_string(i));
    }
  }
  return names;
}

std::vector<Frame> read_record(const std::string& path_in) {
  RecordPrefix r = read_record_prefix(path_in);
  if (!r.cut.empty()) throw std::runtime_error(r.cut);
  return std::move(r.frames);
}

RecordPrefix read_record_prefix(const std::string& path_in) {
  const std::string path = resolve_record_path(path_in);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::runtime_error("run record " + path + ": cannot open (" + std::strerror(errno) +
                             "); is this a run directory written by `swarm run`?");
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("run record " + path + ": read error");

  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  const std::size_t total = bytes.size();
  auto fail = [&](std::size_t frame, std::size_t offset, const std::string& what) {
    return std::runtime_error("run record " + path + ": frame " + std::to_string(frame) +
                              " at byte " + std::to_string(offset) + " of " +
                              std::to_string(total) + ": " + what);
  };

  std::vector<Frame> frames;
  std::size_t pos = 0;
  while (pos < total) {
    // Varint length prefix, at most 5 bytes for a 32-bit size.
    std::uint64_t size = 0;
    std::size_t p = pos;
    int shift = 0;
    bool done = false;
    while (p < total && shift < 35) {
      const std::uint8_t b = data[p++];
      size |= static_cast<std::uint64_t>(b & 0x7f) << shift;
      shift += 7;
      if ((b & 0x80) == 0) {
        done = true;
        break;
      }
    }
    if (!done) {
      if (p >= total && shift < 35) {
        std::string cut = fail(frames.size(), pos, "truncated inside the size prefix (was the run interrupted?)").what();
        return {std::move(frames), std::move(cut)};
      }
      throw fail(frames.size(), pos, "corrupt size prefix (not a swarm run record, or damaged)");
    }
    if (size > static_cast<std::uint64_t>(INT32_MAX)) {
      throw fail(frames.size(), pos, "corrupt size prefix (not a swarm run record, or damaged)");
    }
    if (size > total - p) {
      std::string cut = fail(frames.size(), pos,
                             "truncated: the frame declares " + std::to_string(size) + " bytes but only " +
                                 std::to_string(total - p) + " remain (was the run interrupted, or is the file damaged?)")
                            .what();
      return {std::move(frames), std::move(cut)};
    }
    Frame frame;
    if (!frame.ParseFromArray(data + p, static_cast<int>(size))) {
      throw fail(frames.size(), pos, "corrupt frame (not a swarm run record, or damaged)");
    }
    if (frame.kind_case() == Frame::KIND_NOT_SET && frame.GetReflection()
                                                         ->GetUnknownFields(frame)
                                                         .empty()) {
      // Writers never write empty frames; a run of zero bytes is damage, not data.
      throw fail(frames.size(), pos, "empty frame (not a swarm run record, or damaged)");
    }
    frames.push_back(std::move(frame));
    pos = p + static_cast<std::size_t>(size);
  }
  return {std::move(frames), ""};
}

}  // namespace swarm::record
