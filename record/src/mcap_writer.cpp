#include "swarm/record/mcap_writer.hpp"

#include <zstd.h>

#include <array>
#include <tuple>
#include <stdexcept>

namespace swarm::record {
namespace {

constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

enum Op : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

// Little-endian fields, MCAP's strings (uint32 length, bytes) and maps (uint32 byte length, entries).
void u8(std::string& s, std::uint8_t v) { s.push_back(static_cast<char>(v)); }
void u16(std::string& s, std::uint16_t v) {
  for (int b = 0; b < 2; ++b) s.push_back(static_cast<char>((v >> (8 * b)) & 0xFF));
}
void u32(std::string& s, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) s.push_back(static_cast<char>((v >> (8 * b)) & 0xFF));
}
void u64(std::string& s, std::uint64_t v) {
  for (int b = 0; b < 8; ++b) s.push_back(static_cast<char>((v >> (8 * b)) & 0xFF));
}
void str(std::string& s, std::string_view v) {
  u32(s, static_cast<std::uint32_t>(v.size()));
  s.append(v);
}
void string_map(std::string& s, const std::map<std::string, std::string>& m) {
  std::string body;
  for (const auto& [k, v] : m) str(body, k), str(body, v);
  str(s, body);
}
std::string record(std::uint8_t op, const std::string& content) {
  std::string r;
  u8(r, op);
  u64(r, content.size());
  r += content;
  return r;
}

const std::array<std::uint32_t, 256>& crc_table() {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320U ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  return table;
}

}  // namespace

std::uint32_t crc32(std::string_view data, std::uint32_t crc) {
  const auto& t = crc_table();
  crc = ~crc;
  for (const char ch : data) crc = t[(crc ^ static_cast<std::uint8_t>(ch)) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

McapWriter::McapWriter(const std::string& path) : McapWriter(path, Options{}) {}

McapWriter::McapWriter(const std::string& path, Options options)
    : path_(path), options_(std::move(options)), out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot create " + path);
  open_ = true;
  put(kMagic);
  std::string header;
  str(header, options_.profile);
  str(header, options_.library);
  put_record(kHeader, header);
}

McapWriter::~McapWriter() {
  try {
    close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; close() reports
  }
}

void McapWriter::put(std::string_view bytes) {
  out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out_) throw std::runtime_error("writing " + path_ + " failed");
  crc_ = crc32(bytes, crc_);
  pos_ += bytes.size();
}

void McapWriter::put_record(std::uint8_t op, const std::string& content) { put(record(op, content)); }

std::string McapWriter::schema_record(const Schema& s) {
  std::string c;
  u16(c, s.id);
  str(c, s.name);
  str(c, s.encoding);
  str(c, s.data);
  return c;
}

std::string McapWriter::channel_record(const Channel& ch) {
  std::string c;
  u16(c, ch.id);
  u16(c, ch.schema);
  str(c, ch.topic);
  str(c, ch.encoding);
  string_map(c, ch.metadata);
  return c;
}

std::uint16_t McapWriter::add_schema(const std::string& name, const std::string& encoding, const std::string& data) {
  schemas_.push_back({static_cast<std::uint16_t>(schemas_.size() + 1), name, encoding, data});  // 0 is "no schema"
  put_record(kSchema, schema_record(schemas_.back()));
  return schemas_.back().id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema, const std::string& topic, const std::string& message_encoding,
                                      const std::map<std::string, std::string>& metadata) {
  channels_.push_back({static_cast<std::uint16_t>(channels_.size() + 1), schema, topic, message_encoding, metadata});
  put_record(kChannel, channel_record(channels_.back()));
  return channels_.back().id;
}

void McapWriter::add_metadata(const std::string& name, const std::map<std::string, std::string>& values) {
  std::string c;
  str(c, name);
  string_map(c, values);
  const std::uint64_t at = pos_;
  put_record(kMetadata, c);
  metadata_.push_back({name, {at, pos_ - at}});
}

void McapWriter::write(std::uint16_t channel, std::uint64_t log_time_ns, std::string_view data) {
  if (!open_) throw std::logic_error("McapWriter::write after close");
  if (channel == 0 || channel > channels_.size()) throw std::invalid_argument("McapWriter::write: unknown channel");
  std::string c;
  u16(c, channel);
  u32(c, sequence_[channel]++);
  u64(c, log_time_ns);
  u64(c, log_time_ns);  // publish time: the same, the run's clock
  c.append(data);
  if (chunk_.empty()) chunk_start_ = log_time_ns;
  chunk_end_ = log_time_ns;
  chunk_index_[channel].push_back({log_time_ns, chunk_.size()});
  chunk_ += record(kMessage, c);
  if (message_count_ == 0) first_time_ = log_time_ns;
  last_time_ = log_time_ns;
  ++message_count_;
  ++channel_counts_[channel];
  if (chunk_.size() >= options_.chunk_bytes) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.empty()) return;
  std::string compressed;
  if (options_.compress) {
    compressed.resize(ZSTD_compressBound(chunk_.size()));
    const std::size_t n = ZSTD_compress(compressed.data(), compressed.size(), chunk_.data(), chunk_.size(), 3);
    if (ZSTD_isError(n) != 0U) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
    compressed.resize(n);
  } else {
    compressed = chunk_;
  }
  std::string c;
  u64(c, chunk_start_);
  u64(c, chunk_end_);
  u64(c, chunk_.size());
  u32(c, crc32(chunk_));
  str(c, options_.compress ? "zstd" : "");
  u64(c, compressed.size());
  c += compressed;
  ChunkIndex index{chunk_start_, chunk_end_, pos_, 0, {}, 0, compressed.size(), chunk_.size()};
  put_record(kChunk, c);
  index.length = pos_ - index.offset;
  const std::uint64_t indexes_at = pos_;
  for (const auto& [channel, entries] : chunk_index_) {
    std::string m;
    u16(m, channel);
    u32(m, static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [time, offset] : entries) u64(m, time), u64(m, offset);
    index.index_offsets[channel] = pos_;
    put_record(kMessageIndex, m);
  }
  index.index_length = pos_ - indexes_at;
  chunks_.push_back(std::move(index));
  chunk_.clear();
  chunk_index_.clear();
}

void McapWriter::close() {
  if (!open_) return;
  open_ = false;
  flush_chunk();
  std::string end;
  u32(end, crc_);  // every byte from the leading magic up to here
  put_record(kDataEnd, end);

  // The summary, grouped by opcode, each group's place kept for its Summary Offset.
  const std::uint64_t summary_start = pos_;
  crc_ = 0;
  std::vector<std::tuple<std::uint8_t, std::uint64_t, std::uint64_t>> groups;
  const auto group = [&](std::uint8_t op, const std::vector<std::string>& contents) {
    if (contents.empty()) return;
    const std::uint64_t at = pos_;
    for (const std::string& c : contents) put_record(op, c);
    groups.emplace_back(op, at, pos_ - at);
  };
  std::vector<std::string> contents;
  for (const Schema& s : schemas_) contents.push_back(schema_record(s));
  group(kSchema, contents);
  contents.clear();
  for (const Channel& ch : channels_) contents.push_back(channel_record(ch));
  group(kChannel, contents);
  std::string stats;
  u64(stats, message_count_);
  u16(stats, static_cast<std::uint16_t>(schemas_.size()));
  u32(stats, static_cast<std::uint32_t>(channels_.size()));
  u32(stats, 0);  // attachments
  u32(stats, static_cast<std::uint32_t>(metadata_.size()));
  u32(stats, static_cast<std::uint32_t>(chunks_.size()));
  u64(stats, first_time_);
  u64(stats, last_time_);
  std::string counts;
  for (const auto& [channel, n] : channel_counts_) u16(counts, channel), u64(counts, n);
  str(stats, counts);
  group(kStatistics, {stats});
  contents.clear();
  for (const ChunkIndex& ci : chunks_) {
    std::string c;
    u64(c, ci.start_time);
    u64(c, ci.end_time);
    u64(c, ci.offset);
    u64(c, ci.length);
    std::string offsets;
    for (const auto& [channel, at] : ci.index_offsets) u16(offsets, channel), u64(offsets, at);
    str(c, offsets);
    u64(c, ci.index_length);
    str(c, options_.compress ? "zstd" : "");
    u64(c, ci.compressed);
    u64(c, ci.uncompressed);
    contents.push_back(std::move(c));
  }
  group(kChunkIndex, contents);
  contents.clear();
  for (const auto& [name, place] : metadata_) {
    std::string c;
    u64(c, place.first);
    u64(c, place.second);
    str(c, name);
    contents.push_back(std::move(c));
  }
  group(kMetadataIndex, contents);
  const std::uint64_t offsets_start = pos_;
  for (const auto& [op, at, length] : groups) {
    std::string c;
    u8(c, op);
    u64(c, at);
    u64(c, length);
    put_record(kSummaryOffset, c);
  }
  // The footer: its CRC covers the summary up to and including its own two offsets.
  std::string footer;
  u8(footer, kFooter);
  u64(footer, 8 + 8 + 4);
  u64(footer, summary_start);
  u64(footer, offsets_start);
  put(footer);
  std::string crc;
  u32(crc, crc_);
  put(crc);
  put(kMagic);
  out_.close();
  if (!out_) throw std::runtime_error("closing " + path_ + " failed");
}

}  // namespace swarm::record
