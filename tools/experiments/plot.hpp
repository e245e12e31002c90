// Charts for experiment results, drawn with OpenCV into PNG files: grouped bar charts with error
// bars, line charts with error bars, curves over a numeric x axis (coverage over time) and grouped
// box plots, one or more panels side by side under one title and one
// legend (the legend lists every series name once, in first-seen order, so panels that plot the
// same methods share it).
//
// Layout: a band of kFigureBandPx rows on top holds the title and the legend; below it the panels,
// each panel_width x panel_height pixels, left to right. Each panel has its own title, y axis
// (from 0 to a rounded maximum above every value + error, with "nice" ticks and grid lines), axis
// labels and x tick labels. Line charts put their x values at equal spacing (categories), so an
// "unlimited" point or a 0 delay sits beside the others.
//
//   swarm::tools::BarPanel steps{"Steps to explore", "steps", {"open", "maze1"}, {}};
//   steps.series.push_back({"group-frontier", {0, 114, 178}, {180, 390}, {12, 30}});
//   steps.series.push_back({"baseline", {213, 94, 0}, {210, 620}, {9, 41}});
//   swarm::tools::Figure f{"Exploration (mean ± std over 5 seeds)", {steps}};
//   swarm::tools::write_figure_png(f, "table2.png");  // 640 x (kFigureBandPx + 480) pixels
//
// A value that is NaN is not drawn (a bar is left out; a line skips the point and writes "n/a"
// in its colour above the axis there); an error that is NaN or 0 draws no error bar. Text is
// drawn in ASCII ('±' becomes "+/-", '↔' becomes "<->"). Thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace swarm::tools {

struct Colour {
  std::uint8_t r = 0, g = 0, b = 0;
};

struct PlotSeries {
  std::string name;            // the legend entry
  Colour colour;
  std::vector<double> values;  // one per group (bars) or per x position (lines)
  std::vector<double> errors;  // same length, or empty for no error bars
};

struct BarPanel {
  std::string title;
  std::string y_label;
  std::vector<std::string> groups;  // x tick labels, one per group of bars
  std::vector<PlotSeries> series;   // one bar per series in each group
  std::string x_label;              // optional
  double y_max = 0;                 // > 0: the y axis ends here (100 for percentages); 0 = auto
};

struct LinePanel {
  std::string title;
  std::string y_label;
  std::vector<std::string> x_ticks;  // one label per x position
  std::vector<PlotSeries> series;    // one line per series
  std::string x_label;
  double y_max = 0;                  // > 0: the y axis ends here; 0 = from the values
};

// Curves over a numeric x axis (e.g. coverage over time): every series has one value per entry of
// `x` (shared, increasing), drawn as a plain line (no markers); errors, if given, as a light band
// (value - error .. value + error). The x axis runs from 0 to a nice value >= x.back() with ticks
// from nice_ticks. Each mark is a dashed vertical line with its label at the top.
struct CurvePanel {
  std::string title;
  std::string y_label;
  std::string x_label;
  std::vector<double> x;
  std::vector<PlotSeries> series;
  double y_max = 0;  // > 0: the y axis ends here; 0 = from the values
  struct Mark {
    double x = 0;
    std::string label;
  };
  std::vector<Mark> marks;
};

// Box plots (Tukey): per group one box per series, from the lower to the upper quartile with a
// line at the median, whiskers to the furthest sample within 1.5 box lengths of the box, and
// the samples beyond as small circles (the DARP paper's Fig. 8/9).
struct BoxSeries {
  std::string name;  // the legend entry
  Colour colour;
  std::vector<std::vector<double>> samples;  // one set per group (non-finite samples are ignored)
};

struct BoxPanel {
  std::string title;
  std::string y_label;
  std::vector<std::string> groups;  // x tick labels
  std::vector<BoxSeries> series;
  std::string x_label;
  double y_max = 0;  // > 0: the y axis ends here; 0 = from the samples
};

using Panel = std::variant<BarPanel, LinePanel, CurvePanel, BoxPanel>;

inline constexpr int kFigureBandPx = 72;  // title + legend rows above the panels

struct Figure {
  std::string title;
  std::vector<Panel> panels;
  int panel_width = 640;
  int panel_height = 480;
  std::string note;  // optional small line under the legend, e.g. "error bars: std over seeds"

  int width() const { return panel_width * static_cast<int>(panels.empty() ? 1 : panels.size()); }
  int height() const { return kFigureBandPx + panel_height; }
};

// Draws `figure` and writes it as PNG to `png_path` (width() x height() pixels). Throws
// std::runtime_error naming the path when it cannot be written.
void write_figure_png(const Figure& figure, const std::string& png_path);

// The y axis a panel uses for values up to `max_value`: ticks from 0 by `step` up to `top`
// (top >= max_value, at most about 8 ticks). Exposed for tests.
struct AxisTicks {
  double step = 1;
  double top = 1;
};
[[nodiscard]] AxisTicks nice_ticks(double max_value);

// What a box shows. Quartiles interpolate linearly between order statistics (the usual "type 7":
// q = x[(n - 1) p]); n == 0 gives NaNs.
struct BoxStats {
  std::size_t n = 0;
  double q1 = 0, median = 0, q3 = 0;
  double low = 0, high = 0;       // whisker ends: extreme samples within 1.5 IQR of the box
  std::vector<double> outliers;  // samples beyond the whiskers, ascending
};
[[nodiscard]] BoxStats box_stats(std::vector<double> samples);

}  // namespace swarm::tools
