// Run records: RUN_DIR/run.pb, a sequence of swarm::record::Frame messages (idl/run_record.proto),
// each written as a varint byte count followed by the message (protobuf's "delimited" format, the
// same as Java's writeDelimitedTo), so a record can be appended frame by frame while a run goes on
// and read back without an index.
//
// The first frame is a Header, the last a Summary; Poses, Plan and MapVersion frames come between,
// in tick order. The record holds no wall-clock values, so two lockstep runs with one seed write
// byte-identical files (compare them with file_hash.hpp).
//
//   swarm::record::RecordWriter out(run_dir);        // opens RUN_DIR/run.pb (truncates)
//   swarm::record::Frame f;
//   f.mutable_poses()->set_tick(7);
//   out.append(f);
//   out.close();                                      // or let the destructor flush and close
//
//   std::vector<swarm::record::Frame> frames = swarm::record::read_record(run_dir + "/run.pb");
//
// Not thread-safe: one writer per file, used from one thread.
#pragma once

#include <cstdint>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/proto/run_record.pb.h"

namespace swarm::record {

// The record's file name inside a run directory.
inline constexpr const char* kRunRecordFile = "run.pb";

// RUN_DIR/run.pb for a run directory.
std::string run_record_path(const std::string& run_dir);

// Appends frames to a run record. Throws std::runtime_error when the file cannot be created or a
// write fails (disk full, ...), naming the file.
class RecordWriter {
 public:
  // `path` is the record file, or an existing directory, in which case the record is
  // path/run.pb. An existing file is truncated.
  explicit RecordWriter(const std::string& path);
  ~RecordWriter();  // flushes and closes; never throws (call close() to see write errors)

  RecordWriter(const RecordWriter&) = delete;
  RecordWriter& operator=(const RecordWriter&) = delete;
  RecordWriter(RecordWriter&&) noexcept;
  RecordWriter& operator=(RecordWriter&&) noexcept;

  void append(const Frame& frame);
  // Called with every frame appended from now on, after it is written (the GCS shows its route
  // plans to watchers).
  void on_append(std::function<void(const Frame&)> observer) { observer_ = std::move(observer); }
  void flush();
  void close();  // idempotent; append after close throws

  const std::string& path() const { return path_; }
  std::size_t frames_written() const { return frames_; }
  std::uint64_t bytes_written() const { return bytes_; }

 private:
  std::string path_;
  std::ofstream out_;
  std::size_t frames_ = 0;
  std::uint64_t bytes_ = 0;
  std::function<void(const Frame&)> observer_;
};

// Reads every frame of a record file (or of DIR/run.pb when `path` is a directory). Throws
// std::runtime_error naming the file, the frame number and the byte offset when the file is
// missing, truncated (ends inside a frame, e.g. the run was killed) or corrupt.
std::vector<Frame> read_record(const std::string& path);

// The frames of a record up to its last whole one: a run stopped by a signal or a failed process
// leaves a record that ends inside a frame. `cut` says where and why ("" when the record is
// whole); a corrupt frame or a missing file still throws, as read_record does.
struct RecordPrefix {
  std::vector<Frame> frames;
  std::string cut;
};
RecordPrefix read_record_prefix(const std::string& path);

// The last tick the frames' poses reach; none without a Poses frame.
std::optional<std::uint32_t> last_tick(const std::vector<Frame>& frames);

// The map a MapVersion holds, on the Header's frame (nullptr: all unknown). Throws
// std::runtime_error naming the tick when it does not decode to the Header's size.
planner::OccupancyGrid map_of(const Header& header, const MapVersion* version);

// The robots' names by id (group * robots_per_group + index): "leader-G", "member-G-I".
std::vector<std::string> robot_names(const Header& header);

}  // namespace swarm::record
