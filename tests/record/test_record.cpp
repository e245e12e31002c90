// Run records: write -> read round trip, damaged files, SHA-256, and the pictures.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "swarm_test/files.hpp"
#include "swarm/record/file_hash.hpp"
#include "swarm/record/record.hpp"
#include "swarm/record/render.hpp"

namespace fs = std::filesystem;
using namespace swarm::record;

namespace {

using swarm::test::TempDir;

// The MapVersion encoding of run_record.proto, written here from the spec so the test checks the
// format rather than the decoder against itself: (count varint, value byte) pairs, row-major
// from y = 0; 0 unknown, 1 free, 2 occupied.
std::string encode_rle(const std::vector<std::uint8_t>& cells) {
  std::string out;
  std::size_t i = 0;
  while (i < cells.size()) {
    std::size_t j = i;
    while (j < cells.size() && cells[j] == cells[i]) ++j;
    std::uint64_t count = j - i;
    while (count >= 0x80) {
      out.push_back(static_cast<char>((count & 0x7f) | 0x80));
      count >>= 7;
    }
    out.push_back(static_cast<char>(count));
    out.push_back(static_cast<char>(cells[i]));
    i = j;
  }
  return out;
}

constexpr int kW = 12;
constexpr int kH = 9;
constexpr std::uint8_t U = 0, F = 1, O = 2;

// A 12 x 9 world: walls round the edge, free inside, the top inner row still unknown, and one
// inner wall cell at (8, 2) so "y is up" shows.
std::vector<std::uint8_t> world_cells() {
  std::vector<std::uint8_t> cells(kW * kH, F);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      std::uint8_t v = F;
      if (x == 0 || y == 0 || x == kW - 1 || y == kH - 1) v = O;
      else if (y == kH - 2) v = U;
      cells[y * kW + x] = v;
    }
  }
  cells[2 * kW + 8] = O;
  return cells;
}

// Two groups of two robots; group 0's leader walks (2,2) -> (6,2) along y = 2, its member stays
// at (2,3); group 1's leader steps (2,5) -> (2,6), its member stays at (9,5).
std::vector<Frame> sample_frames() {
  std::vector<Frame> frames;
  Frame f;
  Header* h = f.mutable_header();
  h->mutable_scenario()->set_name("unit");
  h->mutable_scenario()->set_map("maze1");
  h->mutable_scenario()->mutable_explore()->set_mode(swarm::scenario::BASELINE);
  h->set_width(kW);
  h->set_height(kH);
  h->set_resolution(0.2);
  h->set_start_x(2);
  h->set_start_y(4);
  h->set_groups(2);
  h->set_robots_per_group(2);
  frames.push_back(f);

  for (int t = 0; t <= 4; ++t) {
    Frame p;
    Poses* poses = p.mutable_poses();
    poses->set_tick(t);
    const int leader1_y = t > 0 ? 6 : 5;
    for (int v : {2 + t, 2, /*member 0*/ 2, 3, /*leader 1*/ 2, leader1_y, /*member 1*/ 9, 5}) {
      poses->add_xy(v);
    }
    frames.push_back(p);
    if (t == 1) {
      Frame m;
      m.mutable_map()->set_tick(1);
      m.mutable_map()->set_round(0);
      m.mutable_map()->set_rle(encode_rle(world_cells()));
      frames.push_back(m);

      Frame pl;
      Plan* plan = pl.mutable_plan();
      plan->set_tick(1);
      plan->set_round(1);
      plan->set_group(1);
      plan->set_plan_case(GROUP_FRONTIER);
      for (int v : {5, 6, 6, 6}) plan->add_group_frontiers_xy(v);  // cells (5,6), (6,6)
      for (int v : {5, 6, -1, -1}) plan->add_waypoints_xy(v);
      Segment* s = plan->add_global_segments();
      for (int v : {9, 6, 10, 6}) s->add_xy(v);  // cells (9,6), (10,6)
      frames.push_back(pl);
    }
  }
  Frame s;
  s.mutable_summary()->set_steps(4);
  s.mutable_summary()->set_planning_rounds(1);
  s.mutable_summary()->set_complete(true);
  s.mutable_summary()->set_explored_fraction(0.9);
  frames.push_back(s);
  return frames;
}

void write_all(const std::string& path, const std::vector<Frame>& frames) {
  RecordWriter w(path);
  for (const Frame& f : frames) w.append(f);
  w.close();
}

using swarm::test::slurp;

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

cv::Vec3b bgr(Rgb c) { return {c.b, c.g, c.r}; }

std::string throw_message(const std::string& path) {
  try {
    read_record(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RecordIo, WriteThenReadGivesTheSameFrames) {
  TempDir dir;
  const auto frames = sample_frames();
  {
    RecordWriter w(dir.str());  // a directory: writes DIR/run.pb
    for (const Frame& f : frames) w.append(f);
    EXPECT_EQ(w.frames_written(), frames.size());
    EXPECT_EQ(w.path(), run_record_path(dir.str()));
    // destructor flushes
  }
  const auto back = read_record(run_record_path(dir.str()));
  ASSERT_EQ(back.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(back[i].SerializeAsString(), frames[i].SerializeAsString()) << "frame " << i;
  }
  EXPECT_EQ(read_record(dir.str()).size(), frames.size());  // a run directory works too
}

TEST(RecordIo, BytesWrittenIsTheFileSize) {
  TempDir dir;
  RecordWriter w(dir.file("r.pb"));
  for (const Frame& f : sample_frames()) w.append(f);
  w.close();
  EXPECT_EQ(w.bytes_written(), fs::file_size(dir.file("r.pb")));
  EXPECT_THROW(w.append(Frame()), std::runtime_error);
}

TEST(RecordIo, EmptyFileHasNoFrames) {
  TempDir dir;
  spit(dir.file("empty.pb"), "");
  EXPECT_TRUE(read_record(dir.file("empty.pb")).empty());
}

TEST(RecordIo, TruncatedFileThrowsNamingTheFrame) {
  TempDir dir;
  const std::string path = dir.file("run.pb");
  write_all(path, sample_frames());
  const std::string bytes = slurp(path);
  spit(path, bytes.substr(0, bytes.size() - 3));  // inside the Summary frame
  const std::string msg = throw_message(path);
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("frame " + std::to_string(sample_frames().size() - 1)), std::string::npos)
      << msg;
}

TEST(RecordIo, GarbageThrowsCorrupt) {
  TempDir dir;
  const std::string path = dir.file("run.pb");
  write_all(path, sample_frames());
  spit(path, slurp(path) + std::string("\x05\xff\xff\xff\xff\xff", 6));  // 5 bytes of nonsense
  const std::string msg = throw_message(path);
  EXPECT_NE(msg.find("corrupt"), std::string::npos) << msg;

  spit(path, std::string(16, '\0'));  // zeros parse as empty frames: still damage
  EXPECT_NE(throw_message(path).find("empty frame"), std::string::npos);

  spit(path, std::string(8, '\xff'));  // a size prefix that never ends
  EXPECT_NE(throw_message(path).find("corrupt size prefix"), std::string::npos);
}

TEST(RecordIo, MissingFileThrows) {
  TempDir dir;
  const std::string msg = throw_message(dir.file("nope.pb"));
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
}

TEST(RecordIo, UnwritablePathThrows) {
  TempDir dir;
  EXPECT_THROW(RecordWriter(dir.file("no/such/dir/run.pb")), std::runtime_error);
}

TEST(FileHash, KnownSha256Vectors) {
  // FIPS 180-4 examples and the empty string.
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(FileHash, FileHashEqualsStringHashAndTellsRecordsApart) {
  TempDir dir;
  const std::string a = dir.file("a.pb"), b = dir.file("b.pb");
  write_all(a, sample_frames());
  write_all(b, sample_frames());
  EXPECT_EQ(sha256_file_hex(a), sha256_hex(slurp(a)));
  EXPECT_EQ(sha256_file_hex(a), sha256_file_hex(b));  // same frames, same bytes
  auto other = sample_frames();
  other.back().mutable_summary()->set_steps(5);
  write_all(b, other);
  EXPECT_NE(sha256_file_hex(a), sha256_file_hex(b));
  EXPECT_THROW(sha256_file_hex(dir.file("missing")), std::runtime_error);
}

TEST(Render, MapPngHasTheExpectedSizeAndColours) {
  TempDir dir;
  const auto frames = sample_frames();
  const std::string png = dir.file("map.png");
  render_map_png(frames, png, 6);
  const cv::Mat img = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(img.empty());
  const RenderGeometry geo = render_geometry(frames, 6);
  EXPECT_EQ(geo.image_width(), kMinImageWidthPx);  // 12 cells * 6 px is narrower
  EXPECT_EQ(render_geometry(frames, 50).image_width(), kW * 50);
  EXPECT_EQ(geo.image_height(), kBandPx + kH * 6);
  EXPECT_EQ(img.cols, geo.image_width());
  EXPECT_EQ(img.rows, geo.image_height());

  auto px = [&](int x, int y) { return img.at<cv::Vec3b>(geo.centre_row(y), geo.centre_col(x)); };
  EXPECT_EQ(px(9, 2), bgr(kFreeColour));      // free, off every path
  EXPECT_EQ(px(8, 2), bgr(kOccupiedColour));  // the inner wall cell
  EXPECT_EQ(px(0, 4), bgr(kOccupiedColour));  // the outer wall
  EXPECT_EQ(px(4, kH - 2), bgr(kUnknownColour));
  EXPECT_EQ(px(4, 2), bgr(group_colour(0)));  // group 0's leader walked y = 2
  EXPECT_EQ(px(2, 6), bgr(group_colour(1)));  // group 1's leader
  EXPECT_EQ(px(9, 5), bgr(group_colour(1)));  // group 1's member, standing still
  EXPECT_NE(group_colour(0), group_colour(1));
  // y is up: the wall row y = 0 is the bottom row of the image, the map's top row is wall too,
  // and the unknown row y = H-2 sits just below it.
  EXPECT_EQ(img.at<cv::Vec3b>(img.rows - 1, geo.centre_col(kW / 2)), bgr(kOccupiedColour));
  EXPECT_EQ(geo.top(kH - 2), kBandPx + 6);
  // The start X is red at the start cell's centre.
  EXPECT_EQ(px(2, 4), bgr(kStartColour));
}

// The frontier snapshot of `frames` at `tick`, rendered at 8 px a cell into `png` and read back.
cv::Mat frontier_image(const std::vector<Frame>& frames, std::uint32_t tick, const std::string& png) {
  render_frontier_png(frames, tick, png, 8);
  return cv::imread(png, cv::IMREAD_COLOR);
}

TEST(Render, FrontierPngShowsGroupFrontiersAndHatchedSegments) {
  TempDir dir;
  const auto frames = sample_frames();
  const std::string png = dir.file("frontiers.png");
  const cv::Mat img = frontier_image(frames, 2, png);
  ASSERT_FALSE(img.empty());
  const RenderGeometry geo = render_geometry(frames, 8);
  EXPECT_EQ(img.cols, geo.image_width());
  EXPECT_EQ(img.rows, geo.image_height());
  // Group 1's frontier cell (6, 6) filled in its colour (at a pixel off the waypoint ring).
  EXPECT_EQ(img.at<cv::Vec3b>(geo.top(6) + 1, geo.left(6) + 6), bgr(group_colour(1)));
  // The global segment cell (10, 6): some hatch ink, some free white.
  int ink = 0, white = 0;
  for (int r = geo.top(6) + 1; r < geo.top(6) + 7; ++r) {
    for (int c = geo.left(10) + 1; c < geo.left(10) + 7; ++c) {
      const cv::Vec3b v = img.at<cv::Vec3b>(r, c);
      if (v == cv::Vec3b(60, 60, 60)) ++ink;
      if (v == bgr(kFreeColour)) ++white;
    }
  }
  EXPECT_GT(ink, 3);
  EXPECT_GT(white, 10);
  // Before the first map version, the map is all unknown.
  const cv::Mat early = frontier_image(frames, 0, png);
  EXPECT_EQ(early.at<cv::Vec3b>(geo.centre_row(2), geo.centre_col(9)), bgr(kUnknownColour));
}

// Two planning rounds under the paper's delay: round 1 (tick 1) is planned on the map fused at
// tick 1; round 2 (tick 3) on that same map again, while the GCS has meanwhile fused the top
// inner row's cells x = 1..5 (free) and x = 6 (wall). A final map version at tick 4 names no
// planning map, as the GCS writes it.
std::vector<std::uint8_t> round2_cells() {
  std::vector<std::uint8_t> cells = world_cells();
  for (int x = 1; x <= 5; ++x) cells[(kH - 2) * kW + x] = F;
  cells[(kH - 2) * kW + 6] = O;
  return cells;
}

std::vector<Frame> two_round_frames() {
  std::vector<Frame> frames = sample_frames();
  frames.pop_back();  // the Summary goes last again below
  for (Frame& f : frames) {
    if (!f.has_map()) continue;
    f.mutable_map()->set_round(1);
    f.mutable_map()->set_planning_map_tick(1);
  }
  Frame m;
  m.mutable_map()->set_tick(3);
  m.mutable_map()->set_round(2);
  m.mutable_map()->set_rle(encode_rle(round2_cells()));
  m.mutable_map()->set_planning_map_tick(1);
  frames.push_back(m);
  Frame pl;
  Plan* plan = pl.mutable_plan();
  plan->set_tick(3);
  plan->set_round(2);
  plan->set_group(0);
  plan->set_plan_case(GLOBAL_ASSIGNMENT);
  for (int v : {8, 6, -1, -1}) plan->add_waypoints_xy(v);
  Segment* seg = plan->add_global_segments();
  for (int v : {7, 6, 8, 6}) seg->add_xy(v);  // frontiers of the tick-1 map, not of tick 3's
  plan->set_chosen_segment(0);
  frames.push_back(pl);
  Frame last;
  last.mutable_map()->set_tick(4);
  last.mutable_map()->set_round(2);
  last.mutable_map()->set_rle(encode_rle(round2_cells()));
  frames.push_back(last);
  Frame s;
  s.mutable_summary()->set_steps(4);
  s.mutable_summary()->set_planning_rounds(2);
  frames.push_back(s);
  return frames;
}

int known_cells(const swarm::planner::OccupancyGrid& g) {
  int n = 0;
  for (auto c : g.data()) n += c != swarm::planner::CellState::Unknown;
  return n;
}

TEST(Render, SnapshotMapsArePlannedWithAndNewestFused) {
  const auto frames = two_round_frames();
  // 12 x 9 = 108 cells; the tick-1 map leaves the 10 inner cells of row y = 7 unknown (98
  // known); the tick-3 map knows 6 of them more (104).
  const SnapshotMaps at3 = snapshot_maps(frames, 3);
  ASSERT_TRUE(at3.round);
  EXPECT_EQ(*at3.round, 2u);
  EXPECT_TRUE(at3.planned_recorded);
  EXPECT_EQ(at3.planned_tick, 1u);
  EXPECT_EQ(at3.fused_tick, 3u);
  EXPECT_EQ(known_cells(at3.planned), 98);
  EXPECT_EQ(known_cells(at3.fused), 104);
  // Tick 4: the end-of-run version is the newest fused map; round 2's planning map stays.
  const SnapshotMaps at4 = snapshot_maps(frames, 4);
  EXPECT_EQ(at4.planned_tick, 1u);
  EXPECT_EQ(at4.fused_tick, 4u);
  // Tick 2: round 1, planned on the map fused at its own start (the first round has no older).
  const SnapshotMaps at2 = snapshot_maps(frames, 2);
  EXPECT_EQ(at2.round, 1u);
  EXPECT_EQ(at2.planned_tick, 1u);
  EXPECT_EQ(at2.fused_tick, 1u);
  // Before any plan: no round, the map fused by then, not called a planning map.
  const SnapshotMaps at0 = snapshot_maps(frames, 0);
  EXPECT_FALSE(at0.round);
  EXPECT_FALSE(at0.planned_recorded);
  EXPECT_FALSE(at0.planned_tick);
}

TEST(Render, FrontierPngDrawsThePlanningMapAndGreysWhatWasFusedSince) {
  TempDir dir;
  const auto frames = two_round_frames();
  const std::string png = dir.file("frontiers.png");
  const cv::Mat img = frontier_image(frames, 3, png);
  ASSERT_FALSE(img.empty());
  const RenderGeometry geo = render_geometry(frames, 8);
  auto px = [&](const cv::Mat& m, int x, int y) {
    return m.at<cv::Vec3b>(geo.top(y) + 1, geo.left(x) + 1);  // a corner pixel: no ring or hatch
  };
  EXPECT_EQ(px(img, 3, 7), bgr(kSeenFreeColour));      // unknown when planned, free by tick 3
  EXPECT_EQ(px(img, 6, 7), bgr(kSeenOccupiedColour));  // unknown when planned, wall by tick 3
  EXPECT_EQ(px(img, 9, 7), bgr(kUnknownColour));       // unknown in both
  EXPECT_EQ(px(img, 4, 4), bgr(kFreeColour));          // free in both
  EXPECT_EQ(px(img, 8, 2), bgr(kOccupiedColour));

  // A record from before planning_map_tick: the newest fused map, as pictures always drew it.
  auto old = frames;
  for (Frame& f : old) {
    if (f.has_map()) f.mutable_map()->clear_planning_map_tick();
  }
  const SnapshotMaps maps = snapshot_maps(old, 3);
  EXPECT_FALSE(maps.planned_recorded);
  EXPECT_EQ(maps.planned_tick, 3u);
  EXPECT_EQ(known_cells(maps.planned), 104);
  const cv::Mat old_img = frontier_image(old, 3, png);
  EXPECT_EQ(px(old_img, 3, 7), bgr(kFreeColour));
  EXPECT_EQ(px(old_img, 6, 7), bgr(kOccupiedColour));
}

TEST(Render, PlanningMapTickWithoutThatMapVersionIsADamagedRecord) {
  auto frames = two_round_frames();
  for (Frame& f : frames) {
    if (f.has_map() && f.map().round() == 2 && f.map().has_planning_map_tick()) {
      f.mutable_map()->set_planning_map_tick(2);
    }
  }
  try {
    (void)snapshot_maps(frames, 3);
    FAIL() << "expected a damaged-record error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("map version of tick 2"), std::string::npos) << e.what();
  }
}

TEST(Render, RecordWithoutHeaderIsRefused) {
  TempDir dir;
  std::vector<Frame> frames(1);
  frames[0].mutable_summary()->set_steps(1);
  EXPECT_THROW(render_map_png(frames, dir.file("x.png")), std::runtime_error);
}

TEST(Render, UnwritablePngThrows) {
  TempDir dir;
  EXPECT_THROW(render_map_png(sample_frames(), dir.file("no/such/dir/map.png")),
               std::runtime_error);
}
