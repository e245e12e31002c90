// An MCAP reader for tests, written from the specification (mcap.dev/spec) apart from the writer
// (record/mcap_writer.hpp), so that a misreading of the spec in one is not repeated in the other.
// It reads the whole file front to back and checks everything a seeking reader relies on:
//   - the magic at both ends, the Header first, the Footer last;
//   - every chunk: its compression (zstd or none), uncompressed size and CRC; the records in it;
//   - every Message Index after a chunk: one per channel in it, each entry pointing at a Message
//     of that channel and log time, every message of the chunk indexed once;
//   - Data End's CRC of the data section (from the leading magic), the Footer's CRC of the summary;
//   - the summary: Summary Offsets that cover groups of one opcode each, a Chunk Index per chunk
//     that matches it, Statistics that match what was read, Metadata Indexes that point at the
//     Metadata records, a copy of every Schema and Channel.
//
//   const McapFile f = read_mcap(bytes);
//   for (const std::string& p : f.problems) ADD_FAILURE() << p;
//   f.messages;   // every message, in file order
#pragma once

#include <zstd.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace swarm::test {

struct McapMessage {
  std::uint16_t channel = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;
  std::string data;
};

struct McapChannel {
  std::uint16_t schema = 0;
  std::string topic, encoding;
  std::map<std::string, std::string> metadata;
};

struct McapFile {
  std::string profile, library;
  std::map<std::uint16_t, std::string> schema_names;  // id -> name
  std::map<std::uint16_t, std::string> schema_data;
  std::map<std::uint16_t, McapChannel> channels;
  std::vector<McapMessage> messages;
  std::map<std::string, std::map<std::string, std::string>> metadata;
  std::size_t chunks = 0;
  std::vector<std::string> problems;  // empty: the file is sound
};

namespace mcap_check_detail {

inline std::uint32_t crc(const std::string& s, std::size_t from, std::size_t to) {
  std::uint32_t c = 0xFFFFFFFFU;
  for (std::size_t i = from; i < to; ++i) {
    c ^= static_cast<std::uint8_t>(s[i]);
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320U & (0U - (c & 1U)));
  }
  return ~c;
}

// Reads little-endian fields from a byte string; `ok` turns false on reading past the end.
struct Cursor {
  const std::string& s;
  std::size_t at;
  std::size_t end;
  bool ok = true;
  std::uint64_t le(int bytes) {
    if (at + static_cast<std::size_t>(bytes) > end) {
      ok = false;
      at = end;
      return 0;
    }
    std::uint64_t v = 0;
    for (int b = 0; b < bytes; ++b) v |= std::uint64_t{static_cast<std::uint8_t>(s[at + static_cast<std::size_t>(b)])} << (8 * b);
    at += static_cast<std::size_t>(bytes);
    return v;
  }
  std::string bytes(std::uint64_t n) {
    if (at + n > end) {
      ok = false;
      at = end;
      return {};
    }
    std::string out = s.substr(at, n);
    at += n;
    return out;
  }
  std::string str() { return bytes(le(4)); }
  std::map<std::string, std::string> string_map() {
    const std::uint64_t n = le(4);
    const std::size_t stop = at + n;
    std::map<std::string, std::string> m;
    while (ok && at < stop) {
      std::string k = str();
      m[k] = str();
    }
    return m;
  }
};

struct Record {
  std::uint8_t op = 0;
  std::size_t start = 0, content = 0, end = 0;  // the record, its content, the byte after it
};

// The records in s[from, to); a record running past `to` is a problem.
inline std::vector<Record> records(const std::string& s, std::size_t from, std::size_t to, std::vector<std::string>& problems,
                                   const std::string& where) {
  std::vector<Record> out;
  std::size_t at = from;
  while (at < to) {
    if (at + 9 > to) {
      problems.push_back(where + ": a record header cut at byte " + std::to_string(at));
      break;
    }
    Cursor c{s, at + 1, to};
    const std::uint64_t length = c.le(8);
    if (at + 9 + length > to) {
      problems.push_back(where + ": a record of opcode " + std::to_string(static_cast<int>(static_cast<std::uint8_t>(s[at]))) +
                         " runs past its end at byte " + std::to_string(at));
      break;
    }
    out.push_back({static_cast<std::uint8_t>(s[at]), at, at + 9, at + 9 + length});
    at += 9 + length;
  }
  return out;
}

}  // namespace mcap_check_detail

inline McapFile read_mcap(const std::string& s) {
  using namespace mcap_check_detail;
  McapFile f;
  auto& P = f.problems;
  const std::string magic("\x89MCAP0\r\n", 8);
  if (s.size() < 8 + 9 + 8 + 29 || s.compare(0, 8, magic) != 0 || s.compare(s.size() - 8, 8, magic) != 0) {
    P.push_back("no MCAP magic at both ends, or too short");
    return f;
  }
  // The footer, at a fixed place before the trailing magic.
  const std::size_t footer = s.size() - 8 - 29;
  Cursor fc{s, footer, s.size() - 8};
  if (fc.le(1) != 0x02 || fc.le(8) != 20) P.push_back("no Footer of 20 bytes before the trailing magic");
  const std::uint64_t summary_start = fc.le(8), offsets_start = fc.le(8);
  const auto summary_crc = static_cast<std::uint32_t>(fc.le(4));

  const std::vector<Record> data = records(s, 8, summary_start ? summary_start : footer, P, "data section");
  if (data.empty() || data.front().op != 0x01) P.push_back("the first record is not a Header");
  if (data.empty() || data.back().op != 0x0F) {
    P.push_back("the data section does not end with Data End");
    return f;
  }
  struct ChunkSeen {
    std::uint64_t start_time, end_time, offset, length, compressed, uncompressed, index_length = 0;
    std::string compression;
    std::map<std::uint16_t, std::uint64_t> index_offsets;
  };
  std::vector<ChunkSeen> chunks;
  std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> metadata_at;
  std::set<std::uint16_t> schemas_seen, channels_seen;
  // Messages of the last chunk not yet matched by a Message Index entry: offset in chunk -> (channel, time).
  std::map<std::uint64_t, std::pair<std::uint16_t, std::uint64_t>> unindexed;
  const auto take = [&](std::uint8_t op, Cursor& c, std::uint64_t offset_in_chunk) {
    if (op == 0x03) {
      const auto id = static_cast<std::uint16_t>(c.le(2));
      f.schema_names[id] = c.str();
      c.str();
      f.schema_data[id] = c.str();
      schemas_seen.insert(id);
    } else if (op == 0x04) {
      const auto id = static_cast<std::uint16_t>(c.le(2));
      McapChannel ch;
      ch.schema = static_cast<std::uint16_t>(c.le(2));
      ch.topic = c.str();
      ch.encoding = c.str();
      ch.metadata = c.string_map();
      if (ch.schema != 0 && !schemas_seen.count(ch.schema)) P.push_back("channel " + ch.topic + " before its schema");
      f.channels[id] = ch;
      channels_seen.insert(id);
    } else if (op == 0x05) {
      McapMessage m;
      m.channel = static_cast<std::uint16_t>(c.le(2));
      m.sequence = static_cast<std::uint32_t>(c.le(4));
      m.log_time = c.le(8);
      if (c.le(8) != m.log_time) P.push_back("a message's publish time differs from its log time");
      m.data = c.bytes(c.end - c.at);
      if (!channels_seen.count(m.channel)) P.push_back("a message on channel " + std::to_string(m.channel) + " before the channel");
      unindexed[offset_in_chunk] = {m.channel, m.log_time};
      f.messages.push_back(std::move(m));
    }
  };
  for (std::size_t i = 0; i < data.size(); ++i) {
    const Record& r = data[i];
    Cursor c{s, r.content, r.end};
    if (r.op == 0x01) {
      f.profile = c.str();
      f.library = c.str();
    } else if (r.op == 0x03 || r.op == 0x04) {
      take(r.op, c, 0);
    } else if (r.op == 0x05) {
      P.push_back("a message outside any chunk (not indexed)");
    } else if (r.op == 0x0C) {
      const std::string name = c.str();
      f.metadata[name] = c.string_map();
      metadata_at[name] = {r.start, r.end - r.start};
    } else if (r.op == 0x06) {
      if (!unindexed.empty()) P.push_back("a chunk's messages were not all indexed");
      unindexed.clear();
      ChunkSeen k{};
      k.start_time = c.le(8);
      k.end_time = c.le(8);
      k.uncompressed = c.le(8);
      const auto want_crc = static_cast<std::uint32_t>(c.le(4));
      k.compression = c.str();
      k.compressed = c.le(8);
      const std::string packed = c.bytes(k.compressed);
      k.offset = r.start;
      k.length = r.end - r.start;
      std::string plain;
      if (k.compression == "zstd") {
        plain.resize(k.uncompressed);
        const std::size_t n = ZSTD_decompress(plain.data(), plain.size(), packed.data(), packed.size());
        if (ZSTD_isError(n) != 0U || n != k.uncompressed) P.push_back("chunk " + std::to_string(chunks.size()) + ": zstd data does not decompress to its size");
      } else if (k.compression.empty()) {
        plain = packed;
      } else {
        P.push_back("chunk compression '" + k.compression + "'");
      }
      if (crc(plain, 0, plain.size()) != want_crc) P.push_back("chunk " + std::to_string(chunks.size()) + ": CRC mismatch");
      std::uint64_t first = ~std::uint64_t{0}, last = 0;
      for (const Record& in : records(plain, 0, plain.size(), P, "chunk " + std::to_string(chunks.size()))) {
        Cursor ic{plain, in.content, in.end};
        take(in.op, ic, in.start);
        if (in.op == 0x05) first = std::min(first, f.messages.back().log_time), last = std::max(last, f.messages.back().log_time);
        if (!ic.ok) P.push_back("a record inside a chunk is short");
      }
      if (!unindexed.empty() && (first != k.start_time || last != k.end_time)) P.push_back("chunk times are not its messages'");
      const std::uint64_t index_from = r.end;
      for (std::size_t j = i + 1; j < data.size() && data[j].op == 0x07; ++j) {
        Cursor m{s, data[j].content, data[j].end};
        const auto channel = static_cast<std::uint16_t>(m.le(2));
        k.index_offsets[channel] = data[j].start;
        const std::uint64_t n = m.le(4) / 16;
        for (std::uint64_t e = 0; e < n; ++e) {
          const std::uint64_t time = m.le(8), offset = m.le(8);
          const auto it = unindexed.find(offset);
          if (it == unindexed.end() || it->second != std::make_pair(channel, time)) {
            P.push_back("a Message Index entry that points at no message of its channel and time");
          } else {
            unindexed.erase(it);
          }
        }
        k.index_length = data[j].end - index_from;
      }
      chunks.push_back(k);
    } else if (r.op == 0x0F) {
      if (static_cast<std::uint32_t>(c.le(4)) != crc(s, 0, r.start)) P.push_back("Data End: data section CRC mismatch");
    }
    if (!c.ok) P.push_back("record of opcode " + std::to_string(r.op) + " is short");
  }
  if (!unindexed.empty()) P.push_back("the last chunk's messages were not all indexed");
  f.chunks = chunks.size();

  // The summary.
  if (summary_start == 0) {
    P.push_back("no summary section");
    return f;
  }
  if (summary_start != data.back().end) P.push_back("the summary does not start right after Data End");
  if (crc(s, summary_start, footer + 1 + 8 + 16) != summary_crc) P.push_back("Footer: summary CRC mismatch");
  const std::vector<Record> summary = records(s, summary_start, offsets_start ? offsets_start : footer, P, "summary");
  const std::vector<Record> offsets = records(s, offsets_start, footer, P, "summary offsets");
  std::set<std::uint8_t> grouped;
  std::size_t covered = 0;
  for (const Record& o : offsets) {
    Cursor c{s, o.content, o.end};
    const auto op = static_cast<std::uint8_t>(c.le(1));
    const std::uint64_t start = c.le(8), length = c.le(8);
    if (o.op != 0x0E) P.push_back("a record that is not a Summary Offset after the summary");
    std::size_t in_group = 0;
    for (const Record& r : summary) {
      if (r.start >= start && r.end <= start + length) {
        ++in_group;
        if (r.op != op) P.push_back("a Summary Offset group holds another opcode");
      }
    }
    if (in_group == 0) P.push_back("a Summary Offset points at no record");
    grouped.insert(op);
    covered += in_group;
  }
  if (covered != summary.size()) P.push_back("summary records outside every Summary Offset group");
  std::size_t chunk_indexes = 0, schema_copies = 0, channel_copies = 0;
  for (const Record& r : summary) {
    Cursor c{s, r.content, r.end};
    if (r.op == 0x03) ++schema_copies;
    if (r.op == 0x04) ++channel_copies;
    if (r.op == 0x08) {
      ChunkSeen k{};
      k.start_time = c.le(8);
      k.end_time = c.le(8);
      k.offset = c.le(8);
      k.length = c.le(8);
      const std::uint64_t n = c.le(4);
      const std::size_t stop = c.at + n;
      while (c.ok && c.at < stop) {
        const auto channel = static_cast<std::uint16_t>(c.le(2));
        k.index_offsets[channel] = c.le(8);
      }
      k.index_length = c.le(8);
      k.compression = c.str();
      k.compressed = c.le(8);
      k.uncompressed = c.le(8);
      const bool match = chunk_indexes < chunks.size() && [&] {
        const ChunkSeen& a = chunks[chunk_indexes];
        return a.start_time == k.start_time && a.end_time == k.end_time && a.offset == k.offset && a.length == k.length &&
               a.index_offsets == k.index_offsets && a.index_length == k.index_length && a.compression == k.compression &&
               a.compressed == k.compressed && a.uncompressed == k.uncompressed;
      }();
      if (!match) P.push_back("Chunk Index " + std::to_string(chunk_indexes) + " does not match its chunk");
      ++chunk_indexes;
    } else if (r.op == 0x0B) {
      std::map<std::uint16_t, std::uint64_t> per_channel, counted;
      const std::uint64_t messages = c.le(8), schema_count = c.le(2), channel_count = c.le(4);
      c.le(4);
      const std::uint64_t metadata_count = c.le(4), chunk_count = c.le(4), start = c.le(8), end = c.le(8);
      const std::uint64_t n = c.le(4);
      const std::size_t stop = c.at + n;
      while (c.ok && c.at < stop) {
        const auto channel = static_cast<std::uint16_t>(c.le(2));
        per_channel[channel] = c.le(8);
      }
      std::uint64_t first = ~std::uint64_t{0}, last = 0;
      for (const McapMessage& m : f.messages) ++counted[m.channel], first = std::min(first, m.log_time), last = std::max(last, m.log_time);
      if (messages != f.messages.size() || schema_count != f.schema_names.size() || channel_count != f.channels.size() ||
          metadata_count != f.metadata.size() || chunk_count != chunks.size() || per_channel != counted ||
          (!f.messages.empty() && (start != first || end != last))) {
        P.push_back("Statistics do not match the file");
      }
    } else if (r.op == 0x0D) {
      const std::uint64_t at = c.le(8), length = c.le(8);
      const std::string name = c.str();
      if (metadata_at.count(name) == 0 || metadata_at[name] != std::make_pair(at, length)) {
        P.push_back("Metadata Index '" + name + "' points elsewhere");
      }
    }
    if (!c.ok) P.push_back("summary record of opcode " + std::to_string(r.op) + " is short");
  }
  if (chunk_indexes != chunks.size()) P.push_back("not one Chunk Index per chunk");
  if (schema_copies != f.schema_names.size() || channel_copies != f.channels.size()) {
    P.push_back("the summary lacks a copy of a Schema or Channel");
  }
  return f;
}

}  // namespace swarm::test
