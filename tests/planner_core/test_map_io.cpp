#include "swarm_test/data.hpp"
#include "swarm/planner/grid/map_io.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

namespace swarm::planner {
namespace {

namespace fs = std::filesystem;

std::string benchmark_dir() { return swarm::test::benchmarks_dir(); }

// A fresh folder per test, removed afterwards.
class MapIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("swarm_map_io_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& content) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // The message load_map_yaml throws for this YAML text (with a valid 2x1 image beside it).
  std::string yaml_error(const std::string& yaml) const {
    write("ok.pgm", std::string("P5 2 1 255\n") + '\xfe' + '\x00');
    const std::string y = write("m.yaml", yaml);
    try {
      (void)load_map_yaml(y);
    } catch (const MapFileError& e) {
      return e.what();
    }
    return "(no error)";
  }

  std::string pgm_error(const std::string& pgm) const {
    write("p.pgm", pgm);
    const std::string y = write("m.yaml", "image: p.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n");
    try {
      (void)load_map_yaml(y);
    } catch (const MapFileError& e) {
      return e.what();
    }
    return "(no error)";
  }

  std::string movingai_error(const std::string& text) const {
    const std::string p = write("m.map", text);
    try {
      (void)load_movingai_map(p);
    } catch (const MapFileError& e) {
      return e.what();
    }
    return "(no error)";
  }

  fs::path dir_;
};

TEST_F(MapIo, SaveThenLoadIsExact) {
  OccupancyGrid g(37, 23, 0.05, -12.3, 4.56);
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> state(0, 2);
  for (std::size_t i = 0; i < g.size(); ++i) {
    g.set(static_cast<int>(i), static_cast<CellState>(state(rng)));
  }
  save_map_yaml(path("saved.yaml"), g);
  ASSERT_TRUE(fs::exists(path("saved.pgm")));
  const OccupancyGrid back = load_map_yaml(path("saved.yaml"));
  EXPECT_EQ(back, g);
  EXPECT_EQ(back.resolution(), 0.05);
  EXPECT_EQ(back.origin_x(), -12.3);
  EXPECT_EQ(back.origin_y(), 4.56);
}

TEST_F(MapIo, SavedPgmHasTheTopRowFirstAndMapSaverValues) {
  OccupancyGrid g(3, 2, 0.2);
  g.set(Cell{0, 1}, CellState::Free);      // top-left
  g.set(Cell{2, 0}, CellState::Occupied);  // bottom-right
  save_map_yaml(path("m.yaml"), g);
  std::ifstream in(path("m.pgm"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GE(bytes.size(), 6u);
  const std::string pixels = bytes.substr(bytes.size() - 6);
  EXPECT_EQ(pixels, std::string("\xfe\xcd\xcd\xcd\xcd\x00", 6));
  EXPECT_EQ(bytes.substr(0, 3), "P5\n");
}

TEST_F(MapIo, LoadsAsciiPgmWithCommentsSmallMaxvalThresholdsAndNegate) {
  // maxval 10: p = (10 - v) / 10, so 0 -> 1.0 Occupied, 10 -> 0 Free, 5 -> 0.5 Unknown with the
  // default thresholds; first row is y = 1.
  write("a.pgm", "P2\n# made by hand\n3 2 # width height\n10\n0 5 10\n10 10 #c\n 7\n");
  write("a.yaml",
        "image: a.pgm\nresolution: 0.5\norigin: [1.5, -2, 0.0]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n");
  const OccupancyGrid g = load_map_yaml(path("a.yaml"));
  ASSERT_EQ(g.width(), 3);
  ASSERT_EQ(g.height(), 2);
  EXPECT_EQ(g.resolution(), 0.5);
  EXPECT_EQ(g.origin_x(), 1.5);
  EXPECT_EQ(g.origin_y(), -2.0);
  EXPECT_EQ(g.at(Cell{0, 1}), CellState::Occupied);
  EXPECT_EQ(g.at(Cell{1, 1}), CellState::Unknown);
  EXPECT_EQ(g.at(Cell{2, 1}), CellState::Free);
  EXPECT_EQ(g.at(Cell{0, 0}), CellState::Free);
  EXPECT_EQ(g.at(Cell{2, 0}), CellState::Unknown);  // p = 0.3

  // negate: p = v / maxval; a lower occupied threshold turns 0.5 into Occupied.
  write("b.yaml",
        "image: a.pgm\nresolution: 0.5\norigin: [0, 0, 0]\nnegate: 1\noccupied_thresh: 0.4\n");
  const OccupancyGrid n = load_map_yaml(path("b.yaml"));
  EXPECT_EQ(n.at(Cell{0, 1}), CellState::Free);
  EXPECT_EQ(n.at(Cell{1, 1}), CellState::Occupied);
  EXPECT_EQ(n.at(Cell{2, 1}), CellState::Occupied);
  EXPECT_EQ(n.at(Cell{2, 0}), CellState::Occupied);  // p = 0.7
}

TEST_F(MapIo, ImagePathIsRelativeToTheYamlFolder) {
  fs::create_directories(dir_ / "sub");
  write("sub/img.pgm", std::string("P5 1 1 255\n") + '\x00');
  write("sub/m.yaml", "image: img.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(load_map_yaml(path("sub/m.yaml")).at(Cell{0, 0}), CellState::Occupied);
}

TEST_F(MapIo, YamlErrorsNameFileLineAndExpectation) {
  const std::string f = path("m.yaml");
  EXPECT_EQ(yaml_error("image: ok.pgm\norigin: [0, 0, 0]\nresolution: abc\n"),
            f + ":3: resolution must be a positive number (got \"abc\")");
  EXPECT_EQ(yaml_error("image: ok.pgm\nresolution: -0.5\norigin: [0, 0, 0]\n"),
            f + ":2: resolution must be a number of metres per cell in [0.001, 1000] (got \"-0.5\")");
  EXPECT_EQ(yaml_error("image: ok.pgm\norigin: [0, 0, 0]\n"),
            f + ":1: missing key 'resolution' (expected a positive number, metres per cell)");
  EXPECT_EQ(yaml_error("resolution: 1\norigin: [0, 0, 0]\n"),
            f + ":1: missing key 'image' (expected the image file name, relative to this file)");
  EXPECT_EQ(yaml_error("image: ok.pgm\nresolution: 1\n\norigin: [1, 2]\n"),
            f + ":4: origin must be a list of three numbers [x, y, yaw] (got \"[1, 2]\")");
  EXPECT_EQ(yaml_error("image: ok.pgm\nresolution: 1\norigin:\n  - 1\n  - north\n  - 0\n"),
            f + ":5: origin y must be a number (got \"north\")");
  EXPECT_EQ(yaml_error("image: ok.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 2\n"),
            f + ":4: negate must be 0 or 1 (got \"2\")");
  EXPECT_EQ(yaml_error("image: ok.pgm\nresolution: 1\norigin: [0, 0, 0]\noccupied_thresh: 1.5\n"),
            f + ":4: occupied_thresh must be a number between 0 and 1 (got \"1.5\")");
  EXPECT_EQ(yaml_error("image: ok.pgm\nresolution: 1\norigin: [0, 0, 0]\nfree_thresh: 0.8\n"),
            f + ":4: free_thresh (0.8) must not exceed occupied_thresh (0.65)");
  EXPECT_EQ(yaml_error("image: ok.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: scale\n"),
            f + ":4: mode \"scale\" is not supported (expected trinary, the default; re-save "
                "scale/raw maps as trinary)");
  EXPECT_EQ(yaml_error("image: nope.pgm\nresolution: 1\norigin: [0, 0, 0]\n"),
            f + ":1: image \"nope.pgm\" not found (looked for " + path("nope.pgm") +
                "; relative image paths are resolved from the YAML file's folder)");
  EXPECT_EQ(yaml_error("- just\n- a list\n"),
            f + ":1: expected a YAML mapping with keys image, resolution and origin (map_server "
                "format)");
  const std::string syntax = yaml_error("image: ok.pgm\nresolution: [1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(syntax.rfind(f + ":", 0), 0u) << syntax;
  EXPECT_NE(syntax.find("invalid YAML"), std::string::npos) << syntax;
  try {
    (void)load_map_yaml(path("missing.yaml"));
    ADD_FAILURE() << "no error";
  } catch (const MapFileError& e) {
    EXPECT_EQ(std::string(e.what()),
              path("missing.yaml") + ": cannot open the map file (check the path)");
  }
}

TEST_F(MapIo, UnreadableNonPgmImageIsReported) {
  write("bad.png", "not a png");
  const std::string y = write("m.yaml", "image: bad.png\nresolution: 1\norigin: [0, 0, 0]\n");
  try {
    (void)load_map_yaml(y);
    ADD_FAILURE() << "no error";
  } catch (const MapFileError& e) {
    EXPECT_EQ(std::string(e.what()),
              path("bad.png") +
                  ": cannot read the image (expected a PGM, or an 8-bit image OpenCV can decode)");
  }
}

TEST_F(MapIo, PgmErrorsNameTheHeaderField) {
  const std::string p = path("p.pgm");
  EXPECT_EQ(pgm_error("P6 1 1 255\n\x01\x02\x03"),
            p + ": PGM header field 'magic number': expected P5 (binary) or P2 (ASCII) "
                "(got \"P6\")");
  EXPECT_EQ(pgm_error("P5 abc 1 255\n\x01"),
            p + ": PGM header field 'width': expected a positive integer (got \"abc\")");
  EXPECT_EQ(pgm_error("P5 2 0 255\n"),
            p + ": PGM header field 'height': expected a positive integer (got \"0\")");
  EXPECT_EQ(pgm_error("P5 1 1 65535\n\x01\x02"),
            p + ": PGM header field 'maxval': expected an integer 1..255 (16-bit PGMs are not "
                "supported) (got \"65535\")");
  EXPECT_EQ(pgm_error("P5 # no maxval"),
            p + ": PGM header field 'width': expected a positive integer (got end of file)");
  EXPECT_EQ(pgm_error("P5 4 2 255\n\x01\x02\x03"),
            p + ": PGM pixel data: expected 8 bytes (4 x 2) after the header, found 3");
  EXPECT_EQ(pgm_error("P5 2 1 100\n\x01\xc8"),
            p + ": PGM pixel 1 (row 0, column 1): expected an integer 0..100 (got 200)");
  EXPECT_EQ(pgm_error("P2 2 2 255\n1 2\n3 x\n"),
            p + ": PGM pixel 3 (row 1, column 1): expected an integer 0..255 (got \"x\")");
  EXPECT_EQ(pgm_error("P2 2 2 255\n1 2\n3\n"),
            p + ": PGM pixel 3 (row 1, column 1): expected an integer 0..255 (got end of file)");
}

TEST_F(MapIo, LoadsTheMovingAiMaze) {
  const OccupancyGrid g = load_movingai_map(benchmark_dir() + "/movingai/maze-32-32-2.map");
  ASSERT_EQ(g.width(), 32);
  ASSERT_EQ(g.height(), 32);
  EXPECT_EQ(g.resolution(), 0.2);
  int free_cells = 0;
  for (const CellState s : g.data()) free_cells += s == CellState::Free;
  EXPECT_EQ(free_cells, 666);
  for (int x = 0; x < 32; ++x) EXPECT_TRUE(g.is_occupied({x, 31})) << x;  // top row: all '@'
  // Row 1 "@..@..@....": y = 30.
  EXPECT_TRUE(g.is_occupied({0, 30}));
  EXPECT_TRUE(g.is_free({1, 30}));
  EXPECT_TRUE(g.is_occupied({3, 30}));
  EXPECT_TRUE(g.is_free({31, 30}));
  // Row 3 "@..@..@..@@@@@@@@@@@@@..@@@@..@.": y = 28.
  EXPECT_TRUE(g.is_occupied({9, 28}));
  EXPECT_TRUE(g.is_free({22, 28}));
  // Last row "@.....@.....@...........@.......": y = 0.
  EXPECT_TRUE(g.is_occupied({0, 0}));
  EXPECT_TRUE(g.is_free({1, 0}));
  EXPECT_TRUE(g.is_occupied({6, 0}));
  EXPECT_TRUE(g.is_free({31, 0}));
  EXPECT_EQ(from_movingai_xy(g, 15, 2), (Cell{15, 29}));
  const std::string maze = benchmark_dir() + "/movingai/maze-32-32-2.map";
  EXPECT_EQ(load_movingai_map(maze, 0.5).resolution(), 0.5);
}

TEST_F(MapIo, MovingAiParsesLettersAndCrLf) {
  const OccupancyGrid g = load_movingai_map(
      write("t.map", "type octile\r\nheight 2\r\nwidth 3\r\nmap\r\nG@T\r\nS.W\r\n"));
  EXPECT_TRUE(g.is_free({0, 1}));
  EXPECT_TRUE(g.is_occupied({1, 1}));
  EXPECT_TRUE(g.is_occupied({2, 1}));
  EXPECT_TRUE(g.is_free({0, 0}));
  EXPECT_TRUE(g.is_free({1, 0}));
  EXPECT_TRUE(g.is_occupied({2, 0}));
}

TEST_F(MapIo, MovingAiErrorsNameTheLine) {
  const std::string f = path("m.map");
  EXPECT_EQ(movingai_error("type octile\nheight x\nwidth 3\nmap\n...\n"),
            f + ":2: height must be a positive integer (got \"x\")");
  EXPECT_EQ(movingai_error("type octile\nwidth 3\nheight 1\nmap\n...\n"),
            f + ":2: expected \"height <rows>\" (got \"width 3\")");
  EXPECT_EQ(movingai_error("type octile\nheight 2\nwidth 3\nmap\n...\n..\n"),
            f + ":6: map row 1 has 2 characters, expected 3 (width)");
  EXPECT_EQ(movingai_error("type octile\nheight 3\nwidth 3\nmap\n...\n...\n"),
            f + ":7: expected 3 map rows (height), found 2");
  EXPECT_EQ(movingai_error("type octile\nheight 1\nwidth 3\nrows\n...\n"),
            f + ":4: expected \"map\" before the rows (got \"rows\")");
  EXPECT_EQ(movingai_error(""), f + ":1: expected \"type octile\", found end of file");
}

}  // namespace
}  // namespace swarm::planner
