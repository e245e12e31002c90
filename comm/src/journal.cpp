#include "swarm/comm/journal.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace swarm::comm {

namespace {

enum Kind : std::uint8_t { kClock = 1, kMessage = 2, kTickEnd = 3, kRestart = 4 };

constexpr std::uint32_t kMaxRecordBytes = 64u << 20;  // a clock or message is far smaller

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

std::uint32_t get_u32(const char* p) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(p[i])) << (8 * i);
  return v;
}

}  // namespace

JournalContents read_journal(const std::string& path) {
  JournalContents out;
  std::ifstream in(path, std::ios::binary);
  if (!in) return out;
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t at = 0;
  JournalTick open;
  bool in_tick = false;
  constexpr std::size_t kHeader = 13;
  while (at + kHeader <= data.size()) {
    const auto kind = static_cast<std::uint8_t>(data[at]);
    const std::uint32_t tick = get_u32(&data[at + 1]);
    const std::uint32_t order = get_u32(&data[at + 5]);
    const std::uint32_t length = get_u32(&data[at + 9]);
    if (length > kMaxRecordBytes || at + kHeader + length > data.size()) break;  // cut off
    std::string bytes = data.substr(at + kHeader, length);
    at += kHeader + length;
    if (kind == kClock && !in_tick) {
      open = JournalTick{tick, std::move(bytes), {}};
      in_tick = true;
    } else if (kind == kMessage && in_tick && tick == open.tick) {
      open.messages.push_back({static_cast<int>(order), std::move(bytes)});
    } else if (kind == kTickEnd && in_tick && tick == open.tick) {
      out.ticks.push_back(std::move(open));
      in_tick = false;
      out.complete_bytes = at;
    } else if (kind == kRestart && !in_tick) {
      std::istringstream text(bytes);
      JournalRestart r;
      text >> r.replayed_ticks >> r.seconds;
      out.restarts.push_back(r);
      out.complete_bytes = at;
    } else {
      break;  // not a record of this format, or out of place: the tail is not trusted
    }
  }
  return out;
}

JournalWriter::JournalWriter(const std::string& path, std::uint64_t keep_bytes) : path_(path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    std::filesystem::resize_file(path, keep_bytes, ec);
    if (ec) throw std::runtime_error(path + ": cannot cut the journal to its last complete tick: " + ec.message());
  }
  file_ = std::fopen(path.c_str(), "ab");
  if (file_ == nullptr) throw std::runtime_error(path + ": cannot open the journal: " + std::strerror(errno));
}

JournalWriter::~JournalWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void JournalWriter::record(std::uint8_t kind, std::uint32_t tick, std::uint32_t order, const std::string& bytes) {
  std::string head(1, static_cast<char>(kind));
  put_u32(head, tick);
  put_u32(head, order);
  put_u32(head, static_cast<std::uint32_t>(bytes.size()));
  if (std::fwrite(head.data(), 1, head.size(), file_) != head.size() ||
      std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) {
    throw std::runtime_error(path_ + ": cannot write the journal: " + std::strerror(errno));
  }
}

void JournalWriter::clock(std::uint32_t tick, const std::string& cdr) { record(kClock, tick, 0, cdr); }

void JournalWriter::message(std::uint32_t tick, int order, const std::string& cdr) {
  record(kMessage, tick, static_cast<std::uint32_t>(order), cdr);
}

void JournalWriter::tick_end(std::uint32_t tick) {
  record(kTickEnd, tick, 0, {});
  // To the kernel: a process that is killed loses nothing written before.
  if (std::fflush(file_) != 0) throw std::runtime_error(path_ + ": cannot write the journal: " + std::strerror(errno));
}

void JournalWriter::restart(std::uint32_t tick, const JournalRestart& r) {
  std::ostringstream text;
  text.precision(9);
  text << r.replayed_ticks << ' ' << r.seconds;
  record(kRestart, tick, 0, text.str());
  std::fflush(file_);
}

}  // namespace swarm::comm
