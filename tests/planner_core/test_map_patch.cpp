#include "swarm/planner/grid/map_patch.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <vector>

namespace swarm::planner {
namespace {

using Bytes = std::vector<std::uint8_t>;
constexpr CellState F = CellState::Free;
constexpr CellState O = CellState::Occupied;
constexpr CellState U = CellState::Unknown;

std::optional<std::vector<CellChange>> decode(const Bytes& b) {
  return decode_changes(b.data(), b.size());
}

TEST(MapPatch, RawIsFiveBytesPerChangeLittleEndian) {
  const std::vector<CellChange> changes = {{1, F}, {0x102, O}, {0x01020304, U}};
  const Bytes bytes = encode_changes(changes, PatchEncoding::Raw);
  const Bytes expected = {0x00,                          // tag
                          0x01, 0x00, 0x00, 0x00, 0x01,  // 1 Free
                          0x02, 0x01, 0x00, 0x00, 0x02,  // 258 Occupied
                          0x04, 0x03, 0x02, 0x01, 0x00};  // 0x01020304 Unknown
  EXPECT_EQ(bytes, expected);
  EXPECT_EQ(decode(bytes), changes);
}

TEST(MapPatch, RunLengthSortsDeduplicatesAndEncodesRuns) {
  // 6 is written twice; the later Free wins, joining 5..7 into one run.
  const std::vector<CellChange> changes = {{7, F}, {5, F}, {6, O}, {8, O}, {200, F}, {6, F}};
  const Bytes bytes = encode_changes(changes, PatchEncoding::RunLength);
  const Bytes expected = {0x01,              // tag
                          0x05, 0x03, 0x01,  // gap 5, 3 cells, Free: 5, 6, 7
                          0x00, 0x01, 0x02,  // gap 0, 1 cell, Occupied: 8
                          0xBF, 0x01, 0x01, 0x01};  // gap 191 (two-byte varint), 1 cell, Free: 200
  EXPECT_EQ(bytes, expected);
  const std::vector<CellChange> decoded = {{5, F}, {6, F}, {7, F}, {8, O}, {200, F}};
  EXPECT_EQ(decode(bytes), decoded);
}

TEST(MapPatch, EmptyPatchesAreJustTheTag) {
  EXPECT_EQ(encode_changes({}, PatchEncoding::Raw), Bytes{0x00});
  EXPECT_EQ(encode_changes({}, PatchEncoding::RunLength), Bytes{0x01});
  EXPECT_EQ(decode(Bytes{0x00}), std::vector<CellChange>{});
  EXPECT_EQ(decode(Bytes{0x01}), std::vector<CellChange>{});
}

TEST(MapPatch, MalformedInputIsRejected) {
  EXPECT_FALSE(decode_changes(nullptr, 0));
  EXPECT_FALSE(decode(Bytes{}));
  EXPECT_FALSE(decode(Bytes{0x02}));                                  // unknown tag
  EXPECT_FALSE(decode(Bytes{0x00, 0x01, 0x00, 0x00, 0x00}));          // Raw truncated
  EXPECT_FALSE(decode(Bytes{0x00, 0x01, 0x00, 0x00, 0x00, 0x03}));    // state 3
  EXPECT_FALSE(decode(Bytes{0x00, 0x00, 0x00, 0x00, 0x80, 0x01}));    // index >= 2^31
  EXPECT_FALSE(decode(Bytes{0x01, 0x05, 0x00, 0x01}));                // zero-length run
  EXPECT_FALSE(decode(Bytes{0x01, 0x05, 0x01, 0x07}));                // state 7
  // A 6-byte varint.
  EXPECT_FALSE(decode(Bytes{0x01, 0x80, 0x80, 0x80, 0x80, 0x80, 0x01, 0x01, 0x01}));
  EXPECT_FALSE(decode(Bytes{0x01, 0xFF, 0xFF, 0xFF, 0xFF, 0x1F, 0x01, 0x01}));  // varint > 2^32
  EXPECT_FALSE(decode(Bytes{0x01, 0xFF, 0xFF, 0xFF, 0xFF, 0x0F, 0x01, 0x01}));  // index >= 2^31
  EXPECT_FALSE(decode(Bytes{0x01, 0xFF, 0xFF, 0xFF, 0xFF, 0x07, 0x02, 0x01}));  // run past 2^31 - 1
  const auto last = decode(Bytes{0x01, 0xFF, 0xFF, 0xFF, 0xFF, 0x07, 0x01, 0x01});
  ASSERT_TRUE(last);  // the largest int32 index is fine
  EXPECT_EQ(last->front().index, 0x7FFFFFFF);
  // A run of 2^28 cells: over kMaxPatchChanges, refused before allocating.
  EXPECT_FALSE(decode(Bytes{0x01, 0x00, 0xFF, 0xFF, 0xFF, 0x7F, 0x01}));
  // Every truncation of a valid RunLength patch either fails or ends on a run boundary.
  const Bytes full = {0x01, 0x05, 0x03, 0x01, 0x00, 0x01, 0x02, 0xBF, 0x01, 0x01, 0x01};
  for (std::size_t n = 2; n < full.size(); ++n) {
    const auto got = decode_changes(full.data(), n);
    if (n == 4) {
      ASSERT_TRUE(got);
      EXPECT_EQ(got->size(), 3u);
    } else if (n == 7) {
      ASSERT_TRUE(got);
      EXPECT_EQ(got->size(), 4u);
    } else {
      EXPECT_FALSE(got) << n;
    }
  }
}

TEST(MapPatch, RandomRoundTrips) {
  std::mt19937 rng(5);
  for (int round = 0; round < 200; ++round) {
    std::uniform_int_distribution<int> count(0, 300);
    std::uniform_int_distribution<int> index(0, round % 2 ? 400 : 1000000);
    std::uniform_int_distribution<int> state(0, 2);
    std::vector<CellChange> changes(static_cast<std::size_t>(count(rng)));
    std::map<std::int32_t, CellState> last;
    for (CellChange& c : changes) {
      c = {index(rng), static_cast<CellState>(state(rng))};
      last[c.index] = c.state;
    }
    EXPECT_EQ(decode(encode_changes(changes, PatchEncoding::Raw)), changes);
    std::vector<CellChange> expected;
    for (const auto& [i, s] : last) expected.push_back({i, s});
    const Bytes rle = encode_changes(changes, PatchEncoding::RunLength);
    EXPECT_EQ(decode(rle), expected);
    if (round % 2) {  // dense indices: runs pay off
      EXPECT_LT(rle.size(), 1 + 5 * expected.size());
    }
  }
}

TEST(MapPatch, RandomBytesNeverCrash) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<int> len(0, 40);
  int accepted = 0;
  for (int i = 0; i < 20000; ++i) {
    Bytes b(static_cast<std::size_t>(len(rng)));
    for (auto& x : b) x = static_cast<std::uint8_t>(byte(rng));
    if (!b.empty()) b[0] &= 1;  // valid tag, so the payload parser is exercised
    accepted += decode(b).has_value();
  }
  EXPECT_GT(accepted, 0);
}

TEST(GridRle, CountValuePairsRowMajorFromYZero) {
  OccupancyGrid g(3, 2);
  g.set(Cell{0, 0}, F);
  g.set(Cell{1, 0}, F);
  g.set(Cell{2, 0}, O);
  g.set(Cell{0, 1}, O);
  g.set(Cell{1, 1}, O);  // (2, 1) stays Unknown
  const Bytes bytes = encode_grid_rle(g);
  const Bytes expected = {0x02, 0x01, 0x03, 0x02, 0x01, 0x00};
  EXPECT_EQ(bytes, expected);
  OccupancyGrid back(3, 2);
  ASSERT_TRUE(decode_grid_rle(bytes.data(), bytes.size(), back));
  EXPECT_EQ(back, g);

  const OccupancyGrid wide(200, 1, 0.2, 0.0, 0.0, F);
  EXPECT_EQ(encode_grid_rle(wide), (Bytes{0xC8, 0x01, 0x01}));  // 200 as a two-byte varint
}

TEST(GridRle, RejectsWrongSizesAndMalformedBytesLeavingTheGridAlone) {
  const OccupancyGrid g(4, 4, 0.2, 0.0, 0.0, F);
  const Bytes bytes = encode_grid_rle(g);  // {16, Free}
  OccupancyGrid small(3, 3);
  EXPECT_FALSE(decode_grid_rle(bytes.data(), bytes.size(), small));
  OccupancyGrid big(5, 5);
  EXPECT_FALSE(decode_grid_rle(bytes.data(), bytes.size(), big));
  OccupancyGrid into(4, 4);
  const OccupancyGrid before = into;
  for (const Bytes& bad : {Bytes{0x10}, Bytes{0x10, 0x03}, Bytes{0x00, 0x01, 0x10, 0x01},
                           Bytes{0x08, 0x01, 0x08}, Bytes{0x80}, Bytes{}}) {
    EXPECT_FALSE(decode_grid_rle(bad.data(), bad.size(), into));
    EXPECT_EQ(into, before);
  }
  OccupancyGrid empty;
  EXPECT_TRUE(decode_grid_rle(nullptr, 0, empty));
}

TEST(GridRle, RandomRoundTrips) {
  std::mt19937 rng(3);
  for (int round = 0; round < 50; ++round) {
    std::uniform_int_distribution<int> dim(1, 80);
    OccupancyGrid g(dim(rng), dim(rng));
    std::uniform_int_distribution<int> state(0, 2);
    std::uniform_int_distribution<int> run(1, 30);
    for (std::size_t i = 0; i < g.size();) {
      const auto s = static_cast<CellState>(state(rng));
      for (int k = run(rng); k > 0 && i < g.size(); --k, ++i) g.set(static_cast<int>(i), s);
    }
    const Bytes bytes = encode_grid_rle(g);
    OccupancyGrid back(g.width(), g.height());
    ASSERT_TRUE(decode_grid_rle(bytes.data(), bytes.size(), back));
    EXPECT_EQ(back, g);
  }
}

}  // namespace
}  // namespace swarm::planner
