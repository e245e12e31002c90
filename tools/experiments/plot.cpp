#include "plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace swarm::tools {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTitleScale = 0.75;
constexpr double kPanelTitleScale = 0.62;
constexpr double kLabelScale = 0.55;
constexpr double kTickScale = 0.5;
constexpr double kValueScale = 0.45;
// Plot area margins inside a panel.
constexpr int kLeft = 86, kRight = 24, kTop = 44, kBottom = 70;

const cv::Scalar kText(30, 30, 30);
const cv::Scalar kAxis(60, 60, 60);
const cv::Scalar kGrid(225, 225, 225);
const cv::Scalar kErrorBar(40, 40, 40);

cv::Scalar bgr(const Colour& c) { return cv::Scalar(c.b, c.g, c.r); }

// Hershey fonts have no '±' (nor any non-ASCII glyph).
std::string ascii(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "\xC2\xB1") == 0) {
      out += "+/-";
      ++i;
    } else if (text.compare(i, 3, "\xE2\x86\x94") == 0) {  // '↔'
      out += "<->";
      i += 2;
    } else if (static_cast<unsigned char>(text[i]) < 0x80) {
      out += text[i];
    }
  }
  return out;
}

cv::Size text_size(const std::string& text, double scale, int thickness = 1) {
  int baseline = 0;
  return cv::getTextSize(ascii(text), kFont, scale, thickness, &baseline);
}

// Text whose left end is at x and baseline at y.
void put(cv::Mat& img, const std::string& text, int x, int y, double scale, int thickness = 1,
         const cv::Scalar& colour = kText) {
  cv::putText(img, ascii(text), {x, y}, kFont, scale, colour, thickness, cv::LINE_AA);
}

// Text centred on x, baseline at y; shrunk until it fits in max_width (if > 0).
void put_centred(cv::Mat& img, const std::string& text, int x, int y, double scale,
                 int max_width = 0, int thickness = 1) {
  while (max_width > 0 && scale > 0.36 && text_size(text, scale, thickness).width > max_width) {
    scale -= 0.04;
  }
  put(img, text, x - text_size(text, scale, thickness).width / 2, y, scale, thickness);
}

// Text turned 90 degrees counter-clockwise (reads bottom to top), centred on (cx, cy).
void put_vertical(cv::Mat& img, const std::string& text, int cx, int cy, double scale) {
  int baseline = 0;
  const cv::Size s = cv::getTextSize(ascii(text), kFont, scale, 1, &baseline);
  cv::Mat strip(s.height + baseline + 4, s.width + 4, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(strip, ascii(text), {2, s.height + 2}, kFont, scale, kText, 1, cv::LINE_AA);
  cv::Mat turned;
  cv::rotate(strip, turned, cv::ROTATE_90_COUNTERCLOCKWISE);
  int x = cx - turned.cols / 2, y = cy - turned.rows / 2;
  x = std::clamp(x, 0, std::max(0, img.cols - turned.cols));
  y = std::clamp(y, 0, std::max(0, img.rows - turned.rows));
  const int w = std::min(turned.cols, img.cols - x), h = std::min(turned.rows, img.rows - y);
  if (w <= 0 || h <= 0) return;
  turned(cv::Rect(0, 0, w, h)).copyTo(img(cv::Rect(x, y, w, h)));
}

// "1200", "12k", "2.5", "0.25": short labels for tick values.
std::string tick_label(double v, double step) {
  char buf[32];
  if (std::fabs(v) >= 10000) {
    if (std::fabs(v) >= 1e6) {
      std::snprintf(buf, sizeof buf, "%gM", v / 1e6);
    } else {
      std::snprintf(buf, sizeof buf, "%gk", v / 1e3);
    }
    return buf;
  }
  int decimals = 0;
  for (double s = step; decimals < 4 && std::fabs(s - std::round(s)) > 1e-9; s *= 10) ++decimals;
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// "609", "4.5", "0.25", "12.3k": a bar's value, short.
std::string value_label(double v) {
  char buf[32];
  if (std::fabs(v) >= 10000) {
    std::snprintf(buf, sizeof buf, "%.1fk", v / 1000.0);
  } else if (std::fabs(v) >= 100) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
  } else if (std::fabs(v) >= 1) {
    std::snprintf(buf, sizeof buf, "%.1f", v);
  } else {
    std::snprintf(buf, sizeof buf, "%.2f", v);
  }
  return buf;
}

double value_top(const PlotSeries& s, std::size_t i) {
  const double v = s.values[i];
  if (!std::isfinite(v)) return 0;
  const double e = i < s.errors.size() && std::isfinite(s.errors[i]) ? s.errors[i] : 0;
  return v + std::max(0.0, e);
}

// The largest value + error over the first n values of every series.
double largest_top(const std::vector<PlotSeries>& series, std::size_t n) {
  double top = 0;
  for (const auto& s : series) {
    for (std::size_t i = 0; i < s.values.size() && i < n; ++i) top = std::max(top, value_top(s, i));
  }
  return top;
}

struct Frame {
  cv::Rect area;  // the plot area in image pixels
  AxisTicks ticks;
  int y_of(double v) const {
    const double f = ticks.top > 0 ? v / ticks.top : 0;
    return area.y + area.height - static_cast<int>(std::lround(f * area.height));
  }
};

// Panel title, y grid + ticks + label, axes, x label. Returns where values go.
Frame draw_axes(cv::Mat& img, const cv::Rect& panel, const std::string& title,
                const std::string& y_label, const std::string& x_label, double max_value,
                double y_max) {
  Frame f;
  f.area = cv::Rect(panel.x + kLeft, panel.y + kTop, panel.width - kLeft - kRight,
                    panel.height - kTop - kBottom);
  f.ticks = nice_ticks(max_value);
  if (y_max > 0) f.ticks = {nice_ticks(y_max).step, y_max};
  put_centred(img, title, f.area.x + f.area.width / 2, panel.y + 26, kPanelTitleScale,
              panel.width - 12, 1);
  for (int k = 0;; ++k) {
    const double v = k * f.ticks.step;
    if (v > f.ticks.top + f.ticks.step * 1e-6) break;
    const int y = f.y_of(v);
    if (k > 0) cv::line(img, {f.area.x + 1, y}, {f.area.x + f.area.width, y}, kGrid, 1);
    cv::line(img, {f.area.x - 5, y}, {f.area.x, y}, kAxis, 1);
    const std::string label = tick_label(v, f.ticks.step);
    const cv::Size s = text_size(label, kTickScale);
    put(img, label, f.area.x - 9 - s.width, y + s.height / 2, kTickScale);
  }
  cv::line(img, {f.area.x, f.area.y}, {f.area.x, f.area.y + f.area.height}, kAxis, 1);
  cv::line(img, {f.area.x, f.area.y + f.area.height},
           {f.area.x + f.area.width, f.area.y + f.area.height}, kAxis, 1);
  put_vertical(img, y_label, panel.x + 16, f.area.y + f.area.height / 2, kLabelScale);
  if (!x_label.empty()) {
    put_centred(img, x_label, f.area.x + f.area.width / 2, panel.y + panel.height - 14,
                kLabelScale, panel.width - 12);
  }
  return f;
}

void error_bar(cv::Mat& img, const Frame& f, int x, double v, double e, int cap) {
  if (!std::isfinite(e) || e <= 0) return;
  const int lo = f.y_of(std::max(0.0, v - e)), hi = f.y_of(v + e);
  cv::line(img, {x, lo}, {x, hi}, kErrorBar, 1, cv::LINE_AA);
  cv::line(img, {x - cap, lo}, {x + cap, lo}, kErrorBar, 1, cv::LINE_AA);
  cv::line(img, {x - cap, hi}, {x + cap, hi}, kErrorBar, 1, cv::LINE_AA);
}

double error_at(const PlotSeries& s, std::size_t i) {
  return i < s.errors.size() ? s.errors[i] : 0.0;
}

void draw_panel(cv::Mat& img, const cv::Rect& panel, const BarPanel& p) {
  const double max_value = largest_top(p.series, p.groups.size());
  const Frame f = draw_axes(img, panel, p.title, p.y_label, p.x_label, max_value, p.y_max);
  const int groups = std::max<int>(1, static_cast<int>(p.groups.size()));
  const double group_w = static_cast<double>(f.area.width) / groups;
  const int n = std::max<int>(1, static_cast<int>(p.series.size()));
  const double bar_w = group_w * 0.8 / n;
  for (int g = 0; g < static_cast<int>(p.groups.size()); ++g) {
    const double g0 = f.area.x + g * group_w + group_w * 0.1;
    for (int s = 0; s < static_cast<int>(p.series.size()); ++s) {
      const PlotSeries& series = p.series[s];
      if (g >= static_cast<int>(series.values.size()) || !std::isfinite(series.values[g])) continue;
      const double v = std::max(0.0, series.values[g]);
      const int x0 = static_cast<int>(std::lround(g0 + s * bar_w)) + 1;
      const int x1 = static_cast<int>(std::lround(g0 + (s + 1) * bar_w)) - 1;
      const int y = f.y_of(v), base = f.area.y + f.area.height - 1;
      if (x1 > x0 && base >= y) {
        cv::rectangle(img, cv::Point(x0, y), cv::Point(x1, base), bgr(series.colour), cv::FILLED);
      }
      const double e = error_at(series, g);
      error_bar(img, f, (x0 + x1) / 2, v, e, std::max(2, static_cast<int>(bar_w / 5)));
      // The value above the bar (and its error bar), when it fits the bar's width.
      const std::string label = value_label(series.values[g]);
      double scale = kValueScale;
      while (scale > 0.34 && text_size(label, scale).width > x1 - x0 + 4) scale -= 0.03;
      if (text_size(label, scale).width <= x1 - x0 + 4) {
        const int top = f.y_of(v + (std::isfinite(e) && e > 0 ? e : 0.0));
        put_centred(img, label, (x0 + x1) / 2, std::max(f.area.y - 2, top - 5), scale);
      }
    }
    const int centre = static_cast<int>(std::lround(f.area.x + (g + 0.5) * group_w));
    cv::line(img, {centre, f.area.y + f.area.height}, {centre, f.area.y + f.area.height + 5}, kAxis,
             1);
    put_centred(img, p.groups[g], centre, f.area.y + f.area.height + 24, kLabelScale,
                static_cast<int>(group_w) - 4);
  }
}

void draw_panel(cv::Mat& img, const cv::Rect& panel, const LinePanel& p) {
  const double max_value = largest_top(p.series, p.x_ticks.size());
  const Frame f = draw_axes(img, panel, p.title, p.y_label, p.x_label, max_value, p.y_max);
  const int n = std::max<int>(1, static_cast<int>(p.x_ticks.size()));
  const double step = static_cast<double>(f.area.width) / n;
  const int series_count = static_cast<int>(p.series.size());
  for (int i = 0; i < static_cast<int>(p.x_ticks.size()); ++i) {
    const int x = static_cast<int>(std::lround(f.area.x + (i + 0.5) * step));
    cv::line(img, {x, f.area.y + f.area.height}, {x, f.area.y + f.area.height + 5}, kAxis, 1);
    put_centred(img, p.x_ticks[i], x, f.area.y + f.area.height + 24, kTickScale,
                static_cast<int>(step) - 4);
  }
  for (int s = 0; s < series_count; ++s) {
    const PlotSeries& series = p.series[s];
    // Series side by side around each x position, so error bars do not hide one another.
    const double dodge =
        (s - (series_count - 1) / 2.0) * std::min(8.0, step / (2.0 * series_count));
    std::vector<cv::Point> points;
    auto flush = [&] {
      if (points.size() >= 2) {
        cv::polylines(img, points, false, bgr(series.colour), 2, cv::LINE_AA);
      }
      points.clear();
    };
    for (int i = 0; i < static_cast<int>(p.x_ticks.size()); ++i) {
      if (i >= static_cast<int>(series.values.size()) || !std::isfinite(series.values[i])) {
        flush();
        continue;
      }
      const int x = static_cast<int>(std::lround(f.area.x + (i + 0.5) * step + dodge));
      points.push_back({x, f.y_of(std::max(0.0, series.values[i]))});
    }
    flush();
    for (int i = 0; i < static_cast<int>(p.x_ticks.size()); ++i) {
      if (i >= static_cast<int>(series.values.size()) || !std::isfinite(series.values[i])) {
        // No value here (no run counted): say so above the axis, in the series' colour.
        const int x = static_cast<int>(std::lround(f.area.x + (i + 0.5) * step));
        const std::string na = "n/a";
        cv::putText(img, na, {x - text_size(na, kTickScale).width / 2,
                              f.area.y + f.area.height - 8 - 16 * s},
                    kFont, kTickScale, bgr(series.colour), 1, cv::LINE_AA);
        continue;
      }
      const double v = std::max(0.0, series.values[i]);
      const int x = static_cast<int>(std::lround(f.area.x + (i + 0.5) * step + dodge));
      error_bar(img, f, x, v, error_at(series, i), 4);
      cv::circle(img, {x, f.y_of(v)}, 5, bgr(series.colour), cv::FILLED, cv::LINE_AA);
      cv::circle(img, {x, f.y_of(v)}, 5, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    }
  }
}

void draw_panel(cv::Mat& img, const cv::Rect& panel, const CurvePanel& p) {
  const double max_value = largest_top(p.series, p.x.size());
  const Frame f = draw_axes(img, panel, p.title, p.y_label, p.x_label, max_value, p.y_max);
  const AxisTicks xt = nice_ticks(p.x.empty() ? 1.0 : std::max(p.x.back(), 1e-9));
  const auto x_of = [&](double v) {
    return f.area.x + static_cast<int>(std::lround(std::clamp(v / xt.top, 0.0, 1.0) * f.area.width));
  };
  for (int k = 0;; ++k) {
    const double v = k * xt.step;
    if (v > xt.top + xt.step * 1e-6) break;
    const int x = x_of(v);
    cv::line(img, {x, f.area.y + f.area.height}, {x, f.area.y + f.area.height + 5}, kAxis, 1);
    put_centred(img, tick_label(v, xt.step), x, f.area.y + f.area.height + 22, kTickScale);
  }
  for (const PlotSeries& s : p.series) {
    std::vector<cv::Point> line, upper, lower;
    for (std::size_t i = 0; i < s.values.size() && i < p.x.size(); ++i) {
      if (!std::isfinite(s.values[i])) continue;
      const int x = x_of(p.x[i]);
      line.push_back({x, f.y_of(std::max(0.0, s.values[i]))});
      const double e = error_at(s, i);
      if (std::isfinite(e) && e > 0) {
        upper.push_back({x, f.y_of(s.values[i] + e)});
        lower.push_back({x, f.y_of(std::max(0.0, s.values[i] - e))});
      }
    }
    if (upper.size() >= 2) {
      std::vector<cv::Point> band = upper;
      band.insert(band.end(), lower.rbegin(), lower.rend());
      cv::Mat overlay = img.clone();
      cv::fillPoly(overlay, std::vector<std::vector<cv::Point>>{band}, bgr(s.colour), cv::LINE_AA);
      cv::addWeighted(overlay, 0.18, img, 0.82, 0, img);
    }
    if (line.size() >= 2) cv::polylines(img, line, false, bgr(s.colour), 2, cv::LINE_AA);
  }
  for (std::size_t m = 0; m < p.marks.size(); ++m) {
    const int x = x_of(p.marks[m].x);
    for (int y = f.area.y; y < f.area.y + f.area.height; y += 8) {
      cv::line(img, {x, y}, {x, std::min(y + 4, f.area.y + f.area.height)}, kAxis, 1);
    }
    put(img, p.marks[m].label, x + 4, f.area.y + 14 + 16 * static_cast<int>(m), kTickScale);
  }
}

void draw_panel(cv::Mat& img, const cv::Rect& panel, const BoxPanel& p) {
  std::vector<std::vector<BoxStats>> stats(p.series.size());
  double max_value = 0;
  for (std::size_t s = 0; s < p.series.size(); ++s) {
    for (std::size_t g = 0; g < p.groups.size(); ++g) {
      stats[s].push_back(box_stats(g < p.series[s].samples.size() ? p.series[s].samples[g] : std::vector<double>{}));
      const BoxStats& b = stats[s].back();
      if (b.n > 0) max_value = std::max({max_value, b.high, b.outliers.empty() ? 0.0 : b.outliers.back()});
    }
  }
  const Frame f = draw_axes(img, panel, p.title, p.y_label, p.x_label, max_value, p.y_max);
  const int groups = std::max<int>(1, static_cast<int>(p.groups.size()));
  const double group_w = static_cast<double>(f.area.width) / groups;
  const int n = std::max<int>(1, static_cast<int>(p.series.size()));
  const double box_w = group_w * 0.8 / n;
  auto y_of = [&](double v) { return f.y_of(std::clamp(v, 0.0, f.ticks.top)); };
  for (int g = 0; g < static_cast<int>(p.groups.size()); ++g) {
    const double g0 = f.area.x + g * group_w + group_w * 0.1;
    for (int s = 0; s < static_cast<int>(p.series.size()); ++s) {
      const BoxStats& b = stats[s][g];
      if (b.n == 0) continue;
      const cv::Scalar colour = bgr(p.series[s].colour);
      const int x0 = static_cast<int>(std::lround(g0 + s * box_w + box_w * 0.12));
      const int x1 = static_cast<int>(std::lround(g0 + (s + 1) * box_w - box_w * 0.12));
      const int xm = (x0 + x1) / 2;
      cv::line(img, {xm, y_of(b.high)}, {xm, y_of(b.q3)}, kErrorBar, 1, cv::LINE_AA);
      cv::line(img, {xm, y_of(b.q1)}, {xm, y_of(b.low)}, kErrorBar, 1, cv::LINE_AA);
      cv::line(img, {xm - (x1 - x0) / 4, y_of(b.high)}, {xm + (x1 - x0) / 4, y_of(b.high)}, kErrorBar, 1);
      cv::line(img, {xm - (x1 - x0) / 4, y_of(b.low)}, {xm + (x1 - x0) / 4, y_of(b.low)}, kErrorBar, 1);
      const cv::Rect box(cv::Point(x0, y_of(b.q3)), cv::Point(x1, y_of(b.q1) + 1));
      cv::rectangle(img, box, colour, cv::FILLED);
      cv::rectangle(img, box, kErrorBar, 1);
      cv::line(img, {x0, y_of(b.median)}, {x1, y_of(b.median)}, cv::Scalar(255, 255, 255), 2);
      for (double o : b.outliers) cv::circle(img, {xm, y_of(o)}, 3, colour, 1, cv::LINE_AA);
    }
    const int centre = static_cast<int>(std::lround(f.area.x + (g + 0.5) * group_w));
    cv::line(img, {centre, f.area.y + f.area.height}, {centre, f.area.y + f.area.height + 5}, kAxis, 1);
    put_centred(img, p.groups[g], centre, f.area.y + f.area.height + 24, kLabelScale,
                static_cast<int>(group_w) - 4);
  }
}

void draw_legend(cv::Mat& img, const Figure& figure, int y) {
  std::vector<std::pair<std::string, Colour>> entries;
  auto add = [&](const auto& series) {
    for (const auto& s : series) {
      const bool seen = std::any_of(entries.begin(), entries.end(),
                                    [&](const auto& e) { return e.first == s.name; });
      if (!seen) entries.emplace_back(s.name, s.colour);
    }
  };
  for (const Panel& p : figure.panels) {
    std::visit([&](const auto& panel) { add(panel.series); }, p);
  }
  int total = 0;
  for (const auto& [name, colour] : entries) {
    total += 18 + 6 + text_size(name, kLabelScale).width + 24;
  }
  int x = std::max(8, (img.cols - total) / 2);
  for (const auto& [name, colour] : entries) {
    cv::rectangle(img, cv::Rect(x, y - 13, 18, 14), bgr(colour), cv::FILLED);
    x += 18 + 6;
    put(img, name, x, y, kLabelScale);
    x += text_size(name, kLabelScale).width + 24;
  }
}

}  // namespace

AxisTicks nice_ticks(double max_value) {
  if (!std::isfinite(max_value) || max_value <= 0) return {0.2, 1.0};
  const double raw = max_value / 7.0;  // about 7 intervals
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude * 10;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (raw <= m * magnitude * (1 + 1e-9)) {
      step = m * magnitude;
      break;
    }
  }
  AxisTicks t;
  t.step = step;
  t.top = std::ceil(max_value * 1.04 / step - 1e-9) * step;
  if (t.top < max_value) t.top += step;
  return t;
}

BoxStats box_stats(std::vector<double> samples) {
  BoxStats b;
  samples.erase(std::remove_if(samples.begin(), samples.end(), [](double v) { return !std::isfinite(v); }),
                samples.end());
  std::sort(samples.begin(), samples.end());
  b.n = samples.size();
  if (b.n == 0) {
    b.q1 = b.median = b.q3 = b.low = b.high = std::nan("");
    return b;
  }
  auto quantile = [&](double p) {
    const double h = (b.n - 1) * p;
    const std::size_t lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, b.n - 1);
    return samples[lo] + (h - lo) * (samples[hi] - samples[lo]);
  };
  b.q1 = quantile(0.25);
  b.median = quantile(0.5);
  b.q3 = quantile(0.75);
  const double reach = 1.5 * (b.q3 - b.q1);
  b.low = b.q1;
  b.high = b.q3;
  for (double v : samples) {
    if (v < b.q1 - reach || v > b.q3 + reach) {
      b.outliers.push_back(v);
    } else {
      b.low = std::min(b.low, v);
      b.high = std::max(b.high, v);
    }
  }
  return b;
}

void write_figure_png(const Figure& figure, const std::string& png_path) {
  cv::Mat img(figure.height(), figure.width(), CV_8UC3, cv::Scalar(255, 255, 255));
  put_centred(img, figure.title, img.cols / 2, 28, kTitleScale, img.cols - 16, 1);
  draw_legend(img, figure, 54);
  if (!figure.note.empty()) {
    const cv::Size s = text_size(figure.note, kTickScale);
    put(img, figure.note, img.cols - s.width - 10, kFigureBandPx - 2, kTickScale, 1,
        cv::Scalar(90, 90, 90));
  }
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const cv::Rect panel(static_cast<int>(i) * figure.panel_width, kFigureBandPx,
                         figure.panel_width, figure.panel_height);
    std::visit([&](const auto& p) { draw_panel(img, panel, p); }, figure.panels[i]);
  }
  bool written = false;
  try {
    written = cv::imwrite(png_path, img);
  } catch (const cv::Exception& e) {
    throw std::runtime_error("cannot write " + png_path + ": " + e.what());
  }
  if (!written) throw std::runtime_error("cannot write " + png_path);
}

}  // namespace swarm::tools
