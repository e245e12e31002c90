#include "swarm/planner/grid/map_patch.hpp"

#include <zstd.h>

#include <algorithm>
#include <cassert>
#include <limits>

namespace swarm::planner {
namespace {

constexpr std::uint64_t kIndexLimit = std::uint64_t{1} << 31;  // indices are int32 >= 0

bool valid_state(std::uint8_t s) { return s <= static_cast<std::uint8_t>(CellState::Occupied); }

void put_varint(std::vector<std::uint8_t>& out, std::uint32_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(v));
}

// Bounds-checked reader; every get_* returns false instead of reading past the end.
class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}
  bool done() const { return p_ == end_; }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

  bool get_byte(std::uint8_t& b) {
    if (p_ == end_) return false;
    b = *p_++;
    return true;
  }

  bool get_varint(std::uint32_t& v) {
    std::uint64_t acc = 0;
    for (int i = 0; i < 5; ++i) {
      std::uint8_t b = 0;
      if (!get_byte(b)) return false;
      acc |= static_cast<std::uint64_t>(b & 0x7F) << (7 * i);
      if (!(b & 0x80)) {
        if (acc > std::numeric_limits<std::uint32_t>::max()) return false;
        v = static_cast<std::uint32_t>(acc);
        return true;
      }
    }
    return false;  // more than 5 bytes: not a 32-bit varint
  }

 private:
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

std::optional<std::vector<CellChange>> decode_raw(const std::uint8_t* p, std::size_t size) {
  if (size % 5 != 0 || size / 5 > kMaxPatchChanges) return std::nullopt;
  std::vector<CellChange> out(size / 5);
  for (CellChange& ch : out) {
    const std::uint32_t idx = std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) |
                              (std::uint32_t{p[2]} << 16) | (std::uint32_t{p[3]} << 24);
    if (idx >= kIndexLimit || !valid_state(p[4])) return std::nullopt;
    ch.index = static_cast<std::int32_t>(idx);
    ch.state = static_cast<CellState>(p[4]);
    p += 5;
  }
  return out;
}

std::optional<std::vector<CellChange>> decode_rle(const std::uint8_t* p, std::size_t size) {
  Reader in(p, size);
  std::vector<CellChange> out;
  std::uint64_t next = 0;  // one past the end of the previous run
  while (!in.done()) {
    std::uint32_t gap = 0;
    std::uint32_t len = 0;
    std::uint8_t state = 0;
    if (!in.get_varint(gap) || !in.get_varint(len) || !in.get_byte(state)) return std::nullopt;
    if (len == 0 || !valid_state(state)) return std::nullopt;
    const std::uint64_t start = next + gap;
    next = start + len;
    if (next > kIndexLimit || out.size() + len > kMaxPatchChanges) return std::nullopt;
    for (std::uint64_t i = start; i < next; ++i) {
      out.push_back({static_cast<std::int32_t>(i), static_cast<CellState>(state)});
    }
  }
  return out;
}

}  // namespace

std::vector<std::uint8_t> zstd_pack(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> out;
  put_varint(out, static_cast<std::uint32_t>(size));
  const std::size_t header = out.size();
  out.resize(header + ZSTD_compressBound(size));
  // Level 3 (zstd's default): map patches are small; higher levels buy little here.
  const std::size_t n = ZSTD_compress(out.data() + header, out.size() - header, data, size, 3);
  assert(!ZSTD_isError(n) && "compressing into a buffer of compressBound bytes cannot fail");
  out.resize(header + n);
  return out;
}

std::optional<std::vector<std::uint8_t>> zstd_unpack(const std::uint8_t* data, std::size_t size,
                                                     std::size_t max_size) {
  if (data == nullptr) return std::nullopt;
  Reader in(data, size);
  std::uint32_t raw_size = 0;
  if (!in.get_varint(raw_size) || raw_size > max_size) return std::nullopt;
  const std::size_t header = size - in.remaining();
  std::vector<std::uint8_t> out(raw_size);
  const std::size_t n = ZSTD_decompress(out.data(), out.size(), data + header, size - header);
  if (ZSTD_isError(n) || n != raw_size) return std::nullopt;
  return out;
}

std::vector<std::uint8_t> encode_changes(std::vector<CellChange> changes, PatchEncoding encoding) {
  if (encoding == PatchEncoding::ZstdRunLength) {
    const std::vector<std::uint8_t> rle = encode_changes(std::move(changes), PatchEncoding::RunLength);
    std::vector<std::uint8_t> out{static_cast<std::uint8_t>(PatchEncoding::ZstdRunLength)};
    const std::vector<std::uint8_t> packed = zstd_pack(rle.data() + 1, rle.size() - 1);
    out.insert(out.end(), packed.begin(), packed.end());
    return out;
  }
  std::vector<std::uint8_t> out;
  out.push_back(static_cast<std::uint8_t>(encoding));
  for ([[maybe_unused]] const CellChange& ch : changes) {
    assert(ch.index >= 0 && "cell indices are never negative");
  }
  if (encoding == PatchEncoding::Raw) {
    out.reserve(1 + 5 * changes.size());
    for (const CellChange& ch : changes) {
      const auto idx = static_cast<std::uint32_t>(ch.index);
      out.push_back(static_cast<std::uint8_t>(idx));
      out.push_back(static_cast<std::uint8_t>(idx >> 8));
      out.push_back(static_cast<std::uint8_t>(idx >> 16));
      out.push_back(static_cast<std::uint8_t>(idx >> 24));
      out.push_back(static_cast<std::uint8_t>(ch.state));
    }
    return out;
  }

  // Stable sort keeps the original order among equal indices; the last of each group wins.
  std::stable_sort(changes.begin(), changes.end(),
                   [](const CellChange& a, const CellChange& b) { return a.index < b.index; });
  std::uint32_t prev_end = 0;
  std::size_t i = 0;
  while (i < changes.size()) {
    // Collapse duplicates of changes[i].index to the last one, then extend the run.
    auto last_of = [&](std::size_t j) {
      while (j + 1 < changes.size() && changes[j + 1].index == changes[j].index) ++j;
      return j;
    };
    std::size_t j = last_of(i);
    const std::uint32_t start = static_cast<std::uint32_t>(changes[i].index);
    const CellState state = changes[j].state;
    std::uint32_t len = 1;
    for (;;) {
      const std::size_t k = j + 1;
      if (k >= changes.size() || static_cast<std::uint32_t>(changes[k].index) != start + len) break;
      const std::size_t kl = last_of(k);
      if (changes[kl].state != state) break;
      j = kl;
      ++len;
    }
    put_varint(out, start - prev_end);
    put_varint(out, len);
    out.push_back(static_cast<std::uint8_t>(state));
    prev_end = start + len;
    i = j + 1;
  }
  return out;
}

std::optional<std::vector<CellChange>> decode_changes(const std::uint8_t* data, std::size_t size) {
  if (data == nullptr || size == 0) return std::nullopt;
  switch (data[0]) {
    case static_cast<std::uint8_t>(PatchEncoding::Raw): return decode_raw(data + 1, size - 1);
    case static_cast<std::uint8_t>(PatchEncoding::RunLength): return decode_rle(data + 1, size - 1);
    case static_cast<std::uint8_t>(PatchEncoding::ZstdRunLength): {
      // A run costs at least 3 bytes and yields at most kMaxPatchChanges changes in all.
      const auto body = zstd_unpack(data + 1, size - 1, 3 * kMaxPatchChanges);
      if (!body) return std::nullopt;
      return decode_rle(body->data(), body->size());
    }
    default: return std::nullopt;
  }
}

std::vector<std::uint8_t> encode_grid_rle(const OccupancyGrid& grid) {
  std::vector<std::uint8_t> out;
  const std::vector<CellState>& cells = grid.data();
  std::size_t i = 0;
  while (i < cells.size()) {
    std::size_t j = i + 1;
    constexpr std::size_t kMaxRun = std::numeric_limits<std::uint32_t>::max();
    while (j < cells.size() && cells[j] == cells[i] && j - i < kMaxRun) ++j;
    put_varint(out, static_cast<std::uint32_t>(j - i));
    out.push_back(static_cast<std::uint8_t>(cells[i]));
    i = j;
  }
  return out;
}

bool decode_grid_rle(const std::uint8_t* data, std::size_t size, OccupancyGrid& into) {
  if (data == nullptr && size != 0) return false;
  // Validate first so that a bad message leaves the receiver's grid untouched.
  const std::size_t n = into.size();
  {
    Reader in(data, size);
    std::size_t total = 0;
    while (!in.done()) {
      std::uint32_t count = 0;
      std::uint8_t state = 0;
      if (!in.get_varint(count) || !in.get_byte(state)) return false;
      if (count == 0 || !valid_state(state) || count > n - total) return false;
      total += count;
    }
    if (total != n) return false;
  }
  Reader in(data, size);
  std::vector<CellState>& cells = into.data();
  std::size_t pos = 0;
  while (!in.done()) {
    std::uint32_t count = 0;
    std::uint8_t state = 0;
    (void)in.get_varint(count);
    (void)in.get_byte(state);
    std::fill_n(cells.begin() + static_cast<std::ptrdiff_t>(pos), count,
                static_cast<CellState>(state));
    pos += count;
  }
  return true;
}

std::optional<std::vector<CellChange>> decode_changes(const std::uint8_t* data, std::size_t size,
                                                      std::size_t map_cells) {
  auto changes = decode_changes(data, size);
  if (!changes) return std::nullopt;
  for (const CellChange& c : *changes) {
    if (c.index < 0 || static_cast<std::size_t>(c.index) >= map_cells) return std::nullopt;
  }
  return changes;
}

std::vector<std::uint8_t> encode_grid(const OccupancyGrid& grid, PatchEncoding encoding) {
  std::vector<std::uint8_t> rle = encode_grid_rle(grid);
  return encoding == PatchEncoding::ZstdRunLength ? zstd_pack(rle.data(), rle.size()) : rle;
}

bool decode_grid(const std::uint8_t* data, std::size_t size, PatchEncoding encoding, OccupancyGrid& into) {
  if (encoding != PatchEncoding::ZstdRunLength) return decode_grid_rle(data, size, into);
  // A (count, state) pair is at most 6 bytes per cell.
  const auto rle = zstd_unpack(data, size, 6 * into.size() + 16);
  return rle && decode_grid_rle(rle->data(), rle->size(), into);
}

std::vector<std::int16_t> cells_to_xy(const std::vector<Cell>& cells) {
  std::vector<std::int16_t> xy;
  xy.reserve(cells.size() * 2);
  for (const Cell& c : cells) {
    xy.push_back(static_cast<std::int16_t>(c.x));
    xy.push_back(static_cast<std::int16_t>(c.y));
  }
  return xy;
}

std::optional<std::vector<Cell>> cells_from_xy(const std::int16_t* xy, std::size_t n) {
  if (n % 2 != 0) return std::nullopt;
  std::vector<Cell> cells;
  cells.reserve(n / 2);
  for (std::size_t i = 0; i + 1 < n; i += 2) cells.push_back({xy[i], xy[i + 1]});
  return cells;
}

}  // namespace swarm::planner
