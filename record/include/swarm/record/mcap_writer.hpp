// An MCAP writer (mcap.dev/spec, major version 0), written from the specification: the file
// format Foxglove, Lichtblick and the ROS 2 tools open and seek in.
//
// Layout written:
//   magic, Header, Schema and Channel records (as they are added), Metadata records, Chunks of
//   Message records (zstd, or none) each followed by one Message Index per channel in it,
//   Data End (with the data section's CRC), then the summary: Schemas, Channels, Statistics,
//   Chunk Indexes, Metadata Indexes, one Summary Offset per group, the Footer (with the summary's
//   CRC) and the magic again. Every CRC is filled in, so a reader can check all of it.
//
//   McapWriter out("run.mcap");                                   // throws if it cannot open
//   const auto s = out.add_schema("foxglove.Log", "jsonschema", schema_json);
//   const auto c = out.add_channel(s, "/log", "json");
//   out.add_metadata("scenario", {{"seed", "1"}});
//   out.write(c, 1'000'000, R"({"message":"hello"})");             // log time in ns
//   out.close();                                                   // throws on a failed write
//
// Messages must be written in log-time order per file (a chunk's times are its first and last
// message's). Not thread-safe: one writer per file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace swarm::record {

// CRC-32 (IEEE 802.3, as zlib's crc32) of `data`, continuing `crc` (0 to start).
std::uint32_t crc32(std::string_view data, std::uint32_t crc = 0);

class McapWriter {
 public:
  struct Options {
    std::string profile;                  // "" : no well-known profile (JSON messages)
    std::string library = "swarm";
    std::size_t chunk_bytes = 1 << 20;    // a chunk is closed once its records reach this size
    bool compress = true;                 // zstd; false: chunks uncompressed
  };

  explicit McapWriter(const std::string& path);
  McapWriter(const std::string& path, Options options);
  ~McapWriter();  // closes if still open; never throws
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  std::uint16_t add_schema(const std::string& name, const std::string& encoding, const std::string& data);
  std::uint16_t add_channel(std::uint16_t schema, const std::string& topic, const std::string& message_encoding,
                            const std::map<std::string, std::string>& metadata = {});
  void add_metadata(const std::string& name, const std::map<std::string, std::string>& values);
  void write(std::uint16_t channel, std::uint64_t log_time_ns, std::string_view data);
  void close();

  [[nodiscard]] std::uint64_t messages() const { return message_count_; }
  [[nodiscard]] std::uint64_t bytes() const { return pos_; }

 private:
  struct Schema {
    std::uint16_t id;
    std::string name, encoding, data;
  };
  struct Channel {
    std::uint16_t id, schema;
    std::string topic, encoding;
    std::map<std::string, std::string> metadata;
  };
  struct ChunkIndex {
    std::uint64_t start_time, end_time, offset, length;
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    std::uint64_t index_length, compressed, uncompressed;
  };

  void put(std::string_view bytes);                              // to the file, counted and CRC'd
  void put_record(std::uint8_t op, const std::string& content);  // opcode, length, content
  void flush_chunk();
  [[nodiscard]] static std::string schema_record(const Schema& s);
  [[nodiscard]] static std::string channel_record(const Channel& c);

  std::string path_;
  Options options_;
  std::ofstream out_;
  bool open_ = false;
  std::uint64_t pos_ = 0;
  std::uint32_t crc_ = 0;  // of everything written so far (the data section's, until Data End)
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<std::pair<std::string, std::pair<std::uint64_t, std::uint64_t>>> metadata_;  // name, (offset, length)
  // The open chunk: its records, and per channel (log time, offset in the records) of each message.
  std::string chunk_;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::vector<ChunkIndex> chunks_;
  std::map<std::uint16_t, std::uint32_t> sequence_;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;
  std::uint64_t message_count_ = 0, first_time_ = 0, last_time_ = 0;
};

}  // namespace swarm::record
