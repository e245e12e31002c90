#include "swarm/record/grid_canvas.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace swarm::record {
namespace {

// Okabe-Ito first (colour-blind safe), then further well-separated hues for larger teams.
constexpr Rgb kColours[] = {
    {0, 114, 178},   {230, 159, 0},   {0, 158, 115},   {204, 121, 167}, {86, 180, 233},
    {213, 94, 0},    {240, 228, 66},  {120, 60, 160},  {150, 110, 60},  {40, 160, 160},
    {230, 80, 120},  {100, 150, 30},  {60, 80, 200},   {255, 140, 100}, {140, 200, 120},
    {180, 180, 40},  {200, 40, 40},   {90, 200, 220},  {170, 120, 220}, {110, 110, 110},
};
constexpr int kColourCount = static_cast<int>(sizeof(kColours) / sizeof(kColours[0]));

cv::Scalar bgr(Rgb c) { return cv::Scalar(c.b, c.g, c.r); }
const cv::Scalar kBandColour(245, 245, 245);

}  // namespace

Rgb palette_colour(int i) { return kColours[((i % kColourCount) + kColourCount) % kColourCount]; }

struct GridCanvas::Impl {
  cv::Mat image;
  std::string title;
  std::vector<std::pair<std::string, Rgb>> legend;
};

GridCanvas::GridCanvas(const planner::OccupancyGrid& map, int scale)
    : impl_(std::make_unique<Impl>()), scale_(std::max(1, scale)) {
  geo_.width_cells = map.width();
  geo_.height_cells = map.height();
  geo_.scale = scale_;
  impl_->image = cv::Mat(geo_.image_height(), geo_.image_width(), CV_8UC3, kBandColour);
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const planner::CellState s = map.at(planner::Cell{x, y});
      const Rgb c = s == planner::CellState::Free       ? kFreeColour
                    : s == planner::CellState::Occupied ? kOccupiedColour
                                                        : kUnknownColour;
      cv::rectangle(impl_->image, cv::Rect(geo_.left(x), geo_.top(y), scale_, scale_), bgr(c), cv::FILLED);
    }
  }
}

GridCanvas::~GridCanvas() = default;

void GridCanvas::fill_cell(planner::Cell c, Rgb colour, double alpha) {
  if (c.x < 0 || c.y < 0 || c.x >= geo_.width_cells || c.y >= geo_.height_cells) return;
  cv::Mat roi = impl_->image(cv::Rect(geo_.left(c.x), geo_.top(c.y), scale_, scale_));
  if (alpha >= 1.0) {
    roi.setTo(bgr(colour));
    return;
  }
  cv::Mat solid(roi.size(), roi.type(), bgr(colour));
  cv::addWeighted(solid, alpha, roi, 1.0 - alpha, 0.0, roi);
}

void GridCanvas::polyline(const std::vector<planner::Cell>& cells, Rgb colour, int thickness) {
  if (cells.empty()) return;
  std::vector<cv::Point> pts;
  pts.reserve(cells.size());
  for (const auto& c : cells) pts.emplace_back(geo_.centre_col(c.x), geo_.centre_row(c.y));
  if (pts.size() == 1) {
    cv::circle(impl_->image, pts[0], std::max(1, thickness), bgr(colour), cv::FILLED, cv::LINE_AA);
    return;
  }
  cv::polylines(impl_->image, pts, false, bgr(colour), std::max(1, thickness), cv::LINE_AA);
}

void GridCanvas::arrow(planner::Cell from, planner::Cell to, Rgb colour, int thickness) {
  cv::arrowedLine(impl_->image, {geo_.centre_col(from.x), geo_.centre_row(from.y)},
                  {geo_.centre_col(to.x), geo_.centre_row(to.y)}, bgr(colour), std::max(1, thickness),
                  cv::LINE_AA, 0, 0.25);
}

void GridCanvas::marker(planner::Cell c, Rgb colour, Marker kind, double size_cells) {
  const cv::Point p(geo_.centre_col(c.x), geo_.centre_row(c.y));
  const int r = std::max(2, static_cast<int>(size_cells * scale_ / 2.0));
  const cv::Scalar col = bgr(colour);
  switch (kind) {
    case Marker::Disc:
      cv::circle(impl_->image, p, r, col, cv::FILLED, cv::LINE_AA);
      cv::circle(impl_->image, p, r, bgr(kInk), 1, cv::LINE_AA);
      break;
    case Marker::Ring:
      cv::circle(impl_->image, p, r, col, std::max(1, r / 3), cv::LINE_AA);
      break;
    case Marker::Square:
      cv::rectangle(impl_->image, {p.x - r, p.y - r}, {p.x + r, p.y + r}, col, cv::FILLED);
      cv::rectangle(impl_->image, {p.x - r, p.y - r}, {p.x + r, p.y + r}, bgr(kInk), 1);
      break;
    case Marker::Cross:
      cv::line(impl_->image, {p.x - r, p.y - r}, {p.x + r, p.y + r}, col, std::max(1, r / 3), cv::LINE_AA);
      cv::line(impl_->image, {p.x - r, p.y + r}, {p.x + r, p.y - r}, col, std::max(1, r / 3), cv::LINE_AA);
      break;
    case Marker::Triangle: {
      const std::vector<cv::Point> tri = {{p.x, p.y - r}, {p.x - r, p.y + r}, {p.x + r, p.y + r}};
      cv::fillConvexPoly(impl_->image, tri, col, cv::LINE_AA);
      cv::polylines(impl_->image, tri, true, bgr(kInk), 1, cv::LINE_AA);
      break;
    }
  }
}

void GridCanvas::label(planner::Cell c, const std::string& text, Rgb colour) {
  const double fs = std::clamp(scale_ / 16.0, 0.3, 0.6);
  cv::putText(impl_->image, text, {geo_.left(c.x) + scale_, geo_.top(c.y)}, cv::FONT_HERSHEY_SIMPLEX, fs,
              bgr(colour), 1, cv::LINE_AA);
}

void GridCanvas::outline(planner::Cell lo, planner::Cell hi, Rgb colour, int thickness) {
  const int x0 = geo_.left(std::min(lo.x, hi.x));
  const int x1 = geo_.left(std::max(lo.x, hi.x)) + scale_ - 1;
  const int y0 = geo_.top(std::max(lo.y, hi.y));
  const int y1 = geo_.top(std::min(lo.y, hi.y)) + scale_ - 1;
  cv::rectangle(impl_->image, {x0, y0}, {x1, y1}, bgr(colour), std::max(1, thickness));
}

void GridCanvas::set_title(const std::string& title) { impl_->title = title; }

void GridCanvas::add_legend(const std::string& text, Rgb colour) { impl_->legend.emplace_back(text, colour); }

void GridCanvas::write_png(const std::string& path) const {
  cv::Mat out = impl_->image.clone();
  cv::rectangle(out, cv::Rect(0, 0, out.cols, kBandPx), kBandColour, cv::FILLED);
  cv::putText(out, impl_->title, {4, 15}, cv::FONT_HERSHEY_SIMPLEX, 0.45, bgr(kInk), 1, cv::LINE_AA);
  // Legend entries flow left to right over two rows; what does not fit is left out with "...".
  int x = 4, row = 0;
  for (std::size_t i = 0; i < impl_->legend.size(); ++i) {
    const auto& [text, colour] = impl_->legend[i];
    int baseline = 0;
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, &baseline);
    const int w = 14 + size.width + 12;
    if (x + w > out.cols && x > 4) {
      if (++row >= 2) {
        cv::putText(out, "...", {x, 31 + 16}, cv::FONT_HERSHEY_SIMPLEX, 0.4, bgr(kInk), 1, cv::LINE_AA);
        break;
      }
      x = 4;
    }
    const int y = 31 + 16 * row;
    cv::rectangle(out, cv::Rect(x, y - 9, 10, 10), bgr(colour), cv::FILLED);
    cv::putText(out, text, {x + 14, y}, cv::FONT_HERSHEY_SIMPLEX, 0.4, bgr(kInk), 1, cv::LINE_AA);
    x += w;
  }
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (!cv::imwrite(path, out)) throw std::runtime_error("cannot write the picture " + path);
}

}  // namespace swarm::record
