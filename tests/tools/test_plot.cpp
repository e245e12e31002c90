// The OpenCV charts: a PNG of the promised size, drawn pixels where the bars are, nice ticks.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "plot.hpp"

using namespace swarm::tools;
namespace fs = std::filesystem;

namespace {

std::string temp_png(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("swarm-plot-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

Figure two_panel_figure() {
  BarPanel steps;
  steps.title = "Steps until the map is complete";
  steps.y_label = "steps";
  steps.x_label = "map";
  steps.groups = {"open", "maze1", "maze2"};
  steps.series.push_back({"group-frontier", {0, 114, 178}, {173, 368, 609}, {10, 25, 40}});
  steps.series.push_back({"baseline", {213, 94, 0}, {208, 626, 711}, {12, 30, NAN}});
  LinePanel delay;
  delay.title = "Steps vs delay";
  delay.y_label = "steps";
  delay.x_label = "delay (planning intervals)";
  delay.x_ticks = {"0", "0.5", "1", "2", "4"};
  delay.series.push_back({"group-frontier", {0, 114, 178}, {368, 370, NAN, 420, 500}, {5, 6, 0, 8, 9}});
  delay.series.push_back({"baseline", {213, 94, 0}, {626, 640, 650, 700, 800}, {}});
  Figure f;
  f.title = "Exploration: mean +/- std over seeds 1-5";
  f.panels = {steps, delay};
  f.note = "error bars: standard deviation over seeds";
  return f;
}

}  // namespace

TEST(Plot, WritesAPngOfTheExpectedSize) {
  const Figure f = two_panel_figure();
  EXPECT_EQ(f.width(), 2 * 640);
  EXPECT_EQ(f.height(), kFigureBandPx + 480);
  const std::string png = temp_png("two-panels.png");
  write_figure_png(f, png);
  const cv::Mat img = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(img.empty());
  EXPECT_EQ(img.cols, 1280);
  EXPECT_EQ(img.rows, kFigureBandPx + 480);
  // Something is drawn in the group-frontier blue (bars, lines, legend) and the baseline colour.
  int blue = 0, vermillion = 0;
  for (int y = 0; y < img.rows; ++y) {
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      if (p == cv::Vec3b(178, 114, 0)) ++blue;
      if (p == cv::Vec3b(0, 94, 213)) ++vermillion;
    }
  }
  EXPECT_GT(blue, 1000);
  EXPECT_GT(vermillion, 1000);
  fs::remove_all(fs::path(png).parent_path());
}

TEST(Plot, PanelSizeIsConfigurable) {
  Figure f = two_panel_figure();
  f.panels.resize(1);
  f.panel_width = 400;
  f.panel_height = 300;
  const std::string png = temp_png("one-panel.png");
  write_figure_png(f, png);
  const cv::Mat img = cv::imread(png, cv::IMREAD_COLOR);
  EXPECT_EQ(img.cols, 400);
  EXPECT_EQ(img.rows, kFigureBandPx + 300);
  fs::remove_all(fs::path(png).parent_path());
}

TEST(Plot, UnwritablePathThrowsNamingIt) {
  try {
    write_figure_png(two_panel_figure(), "/nonexistent-dir/x.png");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.png"), std::string::npos) << e.what();
  }
}

TEST(Plot, NiceTicksCoverTheValues) {
  const AxisTicks a = nice_ticks(711);
  EXPECT_DOUBLE_EQ(a.step, 200);
  EXPECT_DOUBLE_EQ(a.top, 800);
  const AxisTicks b = nice_ticks(5);
  EXPECT_DOUBLE_EQ(b.step, 1);
  EXPECT_DOUBLE_EQ(b.top, 6);
  const AxisTicks c = nice_ticks(0);
  EXPECT_GT(c.top, 0);
  for (double v : {0.37, 3.0, 42.0, 99.0, 100.0, 1234.0, 98765.0}) {
    const AxisTicks t = nice_ticks(v);
    EXPECT_GE(t.top, v) << v;
    EXPECT_LE(t.top / t.step, 9.01) << v;
  }
}

// Tukey boxes: quartiles by linear interpolation between order statistics (type 7).
TEST(Plot, BoxStatsOfTenSamples) {
  const BoxStats b = box_stats({9, 1, 2, 3, 4, 5, 6, 7, 8, 100, NAN});
  EXPECT_EQ(b.n, 10u);                // the NaN is ignored
  EXPECT_DOUBLE_EQ(b.q1, 3.25);       // x[2] + 0.25 (x[3] - x[2]), (10 - 1) * 0.25 = 2.25
  EXPECT_DOUBLE_EQ(b.median, 5.5);
  EXPECT_DOUBLE_EQ(b.q3, 7.75);
  EXPECT_DOUBLE_EQ(b.low, 1);         // fences at 3.25 - 6.75 and 7.75 + 6.75 = 14.5
  EXPECT_DOUBLE_EQ(b.high, 9);
  EXPECT_EQ(b.outliers, (std::vector<double>{100}));
  EXPECT_EQ(box_stats({}).n, 0u);
  EXPECT_TRUE(std::isnan(box_stats({}).median));
}

TEST(Plot, DrawsBoxPanels) {
  BoxPanel p;
  p.title = "iterations";
  p.y_label = "iterations";
  p.groups = {"far", "near"};
  p.series.push_back({"standalone", {213, 94, 0}, {{100, 120, 130, 900}, {2000, 2500, 10000}}});
  p.series.push_back({"bfs-kmeans", {0, 114, 178}, {{3000, 4000, 5000, 6000}, {}}});
  Figure f;
  f.title = "boxes";
  f.panels = {p};
  const std::string png = temp_png("boxes.png");
  write_figure_png(f, png);
  const cv::Mat img = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(img.empty());
  EXPECT_EQ(img.cols, 640);
  int blue = 0;
  for (int y = kFigureBandPx; y < img.rows; ++y) {
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b c = img.at<cv::Vec3b>(y, x);
      blue += c[0] == 178 && c[1] == 114 && c[2] == 0;
    }
  }
  EXPECT_GT(blue, 20) << "the bfs-kmeans box is drawn";
}
