#include "swarm/record/render.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/record/record.hpp"

namespace swarm::record {
namespace {

using planner::Cell;
using planner::CellState;
using planner::OccupancyGrid;

// Okabe & Ito (2008), "Color Universal Design": distinguishable under the common colour-vision
// deficiencies. Black is left out (it is the wall colour).
constexpr Rgb kPalette[] = {
    {0, 114, 178},    // blue
    {230, 159, 0},    // orange
    {0, 158, 115},    // bluish green
    {204, 121, 167},  // reddish purple
    {86, 180, 233},   // sky blue
    {213, 94, 0},     // vermillion
    {240, 228, 66},   // yellow
};
constexpr int kPaletteSize = static_cast<int>(sizeof(kPalette) / sizeof(kPalette[0]));

const cv::Scalar kText(20, 20, 20);
const cv::Scalar kBand(245, 245, 245);
const cv::Scalar kSegmentInk(60, 60, 60);

cv::Scalar bgr(Rgb c) { return cv::Scalar(c.b, c.g, c.r); }

// Everything the pictures need, pulled out of the frames once.
struct RecordIndex {
  const Header* header = nullptr;
  const Summary* summary = nullptr;
  std::vector<const MapVersion*> maps;  // in record order (tick order)
  std::vector<const Poses*> poses;
  std::vector<const Plan*> plans;
  int robots_per_group = 1;
};

RecordIndex index_frames(const std::vector<Frame>& frames) {
  RecordIndex idx;
  for (const Frame& f : frames) {
    switch (f.kind_case()) {
      case Frame::kHeader:
        if (idx.header == nullptr) idx.header = &f.header();
        break;
      case Frame::kSummary:
        idx.summary = &f.summary();
        break;
      case Frame::kMap:
        idx.maps.push_back(&f.map());
        break;
      case Frame::kPoses:
        idx.poses.push_back(&f.poses());
        break;
      case Frame::kPlan:
        idx.plans.push_back(&f.plan());
        break;
      default:
        break;
    }
  }
  if (idx.header == nullptr) {
    throw std::runtime_error(
        "run record has no Header frame; cannot draw it (is it a run record?)");
  }
  const Header& h = *idx.header;
  if (h.width() == 0 || h.height() == 0 || h.width() > 100000 || h.height() > 100000) {
    throw std::runtime_error("run record header: map size " + std::to_string(h.width()) + " x " +
                             std::to_string(h.height()) + " cells is not drawable");
  }
  std::uint32_t r = h.robots_per_group();
  if (r == 0 && h.has_scenario()) r = h.scenario().robots_per_group();
  idx.robots_per_group = std::max<int>(1, static_cast<int>(r));
  return idx;
}

std::string mode_text(const Header& h) {
  const auto mode = h.scenario().explore().mode();
  std::string s = swarm::scenario::Mode_Name(mode);
  for (char& c : s) {
    c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return s;
}

std::string map_text(const Header& h) {
  const std::string& m = h.scenario().map();
  // A YAML path shows as its file stem ("maps/office.yaml" -> "office").
  if (m.find('/') != std::string::npos || m.find('.') != std::string::npos) {
    const std::string stem = std::filesystem::path(m).stem().string();
    if (!stem.empty()) return stem;
  }
  return m;
}

class Canvas {
 public:
  explicit Canvas(const RenderGeometry& geo)
      : geo_(geo), image_(geo.image_height(), geo.image_width(), CV_8UC3, kBand) {}

  const RenderGeometry& geo() const { return geo_; }
  cv::Mat& image() { return image_; }

  void fill_cell(Cell c, const cv::Scalar& colour) {
    if (!inside(c)) return;
    cv::rectangle(image_, cv::Rect(geo_.left(c.x), geo_.top(c.y), geo_.scale, geo_.scale), colour,
                  cv::FILLED);
  }

  // `grid`; where it is unknown and `newer` (if given) knows the cell, the kSeen* colours.
  void draw_grid(const OccupancyGrid& grid, const OccupancyGrid* newer = nullptr) {
    auto vec = [](Rgb c) { return cv::Vec3b(c.b, c.g, c.r); };
    const cv::Vec3b unknown = vec(kUnknownColour), free_c = vec(kFreeColour),
                    occ = vec(kOccupiedColour), seen_free = vec(kSeenFreeColour),
                    seen_occ = vec(kSeenOccupiedColour);
    for (int y = 0; y < geo_.height_cells; ++y) {
      for (int x = 0; x < geo_.width_cells; ++x) {
        const CellState s = grid.at(Cell{x, y});
        const CellState later = s == CellState::Unknown && newer != nullptr
                                    ? newer->at(Cell{x, y})
                                    : CellState::Unknown;
        const cv::Vec3b& v = s == CellState::Free         ? free_c
                             : s == CellState::Occupied   ? occ
                             : later == CellState::Free     ? seen_free
                             : later == CellState::Occupied ? seen_occ
                                                            : unknown;
        const int top = geo_.top(y), left = geo_.left(x);
        for (int r = 0; r < geo_.scale; ++r) {
          cv::Vec3b* row = image_.ptr<cv::Vec3b>(top + r);
          for (int k = 0; k < geo_.scale; ++k) row[left + k] = v;
        }
      }
    }
  }

  cv::Point centre(Cell c) const { return {geo_.centre_col(c.x), geo_.centre_row(c.y)}; }
  bool inside(Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.x < geo_.width_cells && c.y < geo_.height_cells;
  }

  // Diagonal hatch over a cell: every 4th anti-diagonal pixel line.
  void hatch_cell(Cell c, const cv::Scalar& colour) {
    if (!inside(c)) return;
    const cv::Vec3b v(static_cast<uchar>(colour[0]), static_cast<uchar>(colour[1]),
                      static_cast<uchar>(colour[2]));
    for (int r = geo_.top(c.y); r < geo_.top(c.y) + geo_.scale; ++r) {
      cv::Vec3b* row = image_.ptr<cv::Vec3b>(r);
      for (int col = geo_.left(c.x); col < geo_.left(c.x) + geo_.scale; ++col) {
        if ((col + r) % 4 == 0) row[col] = v;
      }
    }
  }

  // Outline of a set of cells: the cell sides that do not touch another cell of the set.
  void outline_cells(const std::set<Cell>& cells, const cv::Scalar& colour, int thickness) {
    const int s = geo_.scale;
    for (const Cell& c : cells) {
      if (!inside(c)) continue;
      const int l = geo_.left(c.x), t = geo_.top(c.y), r = l + s - 1, b = t + s - 1;
      auto side = [&](cv::Point a, cv::Point z) {
        cv::line(image_, a, z, colour, thickness, cv::LINE_8);
      };
      if (!cells.count({c.x - 1, c.y})) side({l, t}, {l, b});
      if (!cells.count({c.x + 1, c.y})) side({r, t}, {r, b});
      if (!cells.count({c.x, c.y + 1})) side({l, t}, {r, t});
      if (!cells.count({c.x, c.y - 1})) side({l, b}, {r, b});
    }
  }

  void start_marker(Cell c) {
    if (!inside(c)) return;
    const int half = std::max(3, geo_.scale);  // the X spans about two cells
    const cv::Point p = centre(c);
    const int thick = std::max(2, geo_.scale / 3);
    const cv::Scalar red = bgr(kStartColour);
    const cv::Point d1(half, half), d2(half, -half);
    cv::line(image_, p - d1, p + d1, red, thick, cv::LINE_8);
    cv::line(image_, p - d2, p + d2, red, thick, cv::LINE_8);
  }

  // A font scale, at most `base`, at which `text` fits `available_px`; never below `floor` (the
  // image edge then clips the text).
  static double fitting_font_scale(const std::string& text, int available_px, double base,
                                   double floor) {
    int baseline = 0;
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, base, 1, &baseline);
    if (size.width <= available_px || size.width <= 0) return base;
    return std::max(floor, base * std::max(0, available_px) / size.width);
  }

  void title(const std::string& text) {
    const double fs = fitting_font_scale(text, geo_.image_width() - 8, 0.5, 0.35);
    cv::putText(image_, text, {4, 15}, cv::FONT_HERSHEY_SIMPLEX, fs, kText, 1, cv::LINE_AA);
  }

  // Two legend rows: coloured swatches with labels, the start marker and `notes`; below them
  // `more_notes`.
  void legend(int groups, const std::string& notes, const std::string& more_notes) {
    if (!more_notes.empty()) {
      const double more_fs = fitting_font_scale(more_notes, geo_.image_width() - 8, 0.35, 0.28);
      cv::putText(image_, more_notes, {4, 49}, cv::FONT_HERSHEY_SIMPLEX, more_fs, kText, 1,
                  cv::LINE_AA);
    }
    int x = 4;
    const int y = 32;
    const double fs = 0.35;
    for (int g = 0; g < groups; ++g) {
      cv::rectangle(image_, cv::Rect(x, y - 8, 9, 9), bgr(group_colour(g)), cv::FILLED);
      x += 12;
      const std::string label = "group " + std::to_string(g);
      cv::putText(image_, label, {x, y}, cv::FONT_HERSHEY_SIMPLEX, fs, kText, 1, cv::LINE_AA);
      int baseline = 0;
      x += cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, fs, 1, &baseline).width + 8;
    }
    // Start marker swatch.
    const cv::Point p(x + 4, y - 4);
    cv::line(image_, p + cv::Point(-4, -4), p + cv::Point(4, 4), bgr(kStartColour), 2, cv::LINE_8);
    cv::line(image_, p + cv::Point(-4, 4), p + cv::Point(4, -4), bgr(kStartColour), 2, cv::LINE_8);
    x += 12;
    const std::string text = "start   " + notes;
    const double notes_fs = fitting_font_scale(text, geo_.image_width() - x - 4, fs, 0.28);
    cv::putText(image_, text, {x, y}, cv::FONT_HERSHEY_SIMPLEX, notes_fs, kText, 1, cv::LINE_AA);
  }

  void write(const std::string& png_path) {
    bool ok = false;
    try {
      ok = cv::imwrite(png_path, image_);
    } catch (const cv::Exception& e) {
      throw std::runtime_error("cannot write " + png_path + ": " + e.what());
    }
    if (!ok) {
      throw std::runtime_error("cannot write " + png_path +
                               " (does its folder exist and is it writable?)");
    }
  }

 private:
  RenderGeometry geo_;
  cv::Mat image_;
};

int group_count(const RecordIndex& idx) {
  std::uint32_t g = idx.header->groups();
  if (g == 0 && idx.header->has_scenario()) g = idx.header->scenario().groups();
  return static_cast<int>(g);
}

Cell start_cell(const Header& h) { return {h.start_x(), h.start_y()}; }

// Last element with tick <= t, or nullptr.
template <typename T>
const T* at_or_before(const std::vector<const T*>& items, std::uint32_t t) {
  const T* found = nullptr;
  for (const T* item : items) {
    if (item->tick() <= t) found = item;
  }
  return found;
}

}  // namespace

Rgb group_colour(int group) {
  const int i = ((group % kPaletteSize) + kPaletteSize) % kPaletteSize;
  return kPalette[i];
}

namespace {

RenderGeometry geometry_of(const RecordIndex& idx, int scale) {
  if (scale < 1 || scale > 64) {
    throw std::runtime_error("render scale " + std::to_string(scale) +
                             " is out of range; use 1 to 64 pixels per cell");
  }
  return RenderGeometry{static_cast<int>(idx.header->width()),
                        static_cast<int>(idx.header->height()), scale};
}

// The planning round in force at `tick`: the highest round among the plans made at or before it.
std::optional<std::uint32_t> round_at(const RecordIndex& idx, std::uint32_t tick) {
  std::optional<std::uint32_t> round;
  for (const Plan* p : idx.plans) {
    if (p->tick() <= tick && (!round || p->round() > *round)) round = p->round();
  }
  return round;
}

SnapshotMaps snapshot_maps_of(const RecordIndex& idx, std::uint32_t tick) {
  SnapshotMaps m;
  m.round = round_at(idx, tick);
  const MapVersion* fused = at_or_before(idx.maps, tick);
  m.fused = map_of(*idx.header, fused);
  if (fused != nullptr) m.fused_tick = fused->tick();
  const MapVersion* planned = fused;
  if (m.round) {
    // The round's start version names the map its RoundStart carried (the version written at
    // the end of the run repeats the last round but names none).
    const MapVersion* start = nullptr;
    for (const MapVersion* v : idx.maps) {
      if (v->round() == *m.round && v->has_planning_map_tick()) {
        start = v;
        break;
      }
    }
    if (start != nullptr) {
      planned = nullptr;
      for (const MapVersion* v : idx.maps) {
        if (v->tick() == start->planning_map_tick()) {
          planned = v;
          break;
        }
      }
      if (planned == nullptr) {
        throw std::runtime_error("run record: round " + std::to_string(*m.round) +
                                 " was planned with the map version of tick " +
                                 std::to_string(start->planning_map_tick()) +
                                 ", which the record does not hold (damaged record?)");
      }
      m.planned_recorded = true;
    }
  }
  m.planned = planned == fused ? m.fused : map_of(*idx.header, planned);
  if (planned != nullptr) m.planned_tick = planned->tick();
  return m;
}

}  // namespace

SnapshotMaps snapshot_maps(const std::vector<Frame>& frames, std::uint32_t tick) {
  return snapshot_maps_of(index_frames(frames), tick);
}

RenderGeometry render_geometry(const std::vector<Frame>& frames, int scale) {
  return geometry_of(index_frames(frames), scale);
}

void render_map_png(const std::vector<Frame>& frames, const std::string& png_path, int scale) {
  const RecordIndex idx = index_frames(frames);
  const RenderGeometry geo = geometry_of(idx, scale);
  Canvas canvas(geo);
  canvas.draw_grid(map_of(*idx.header, idx.maps.empty() ? nullptr : idx.maps.back()));

  // Paths: one polyline per robot through its cell centres; a negative cell (unknown) breaks it.
  const int r_per_group = idx.robots_per_group;
  std::size_t robots = 0;
  for (const Poses* p : idx.poses) robots = std::max<std::size_t>(robots, p->xy_size() / 2);
  const int leader_px = std::max(2, scale * 2 / 3);
  const int member_px = std::max(1, scale / 3);
  // Members first, leaders on top.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t id = 0; id < robots; ++id) {
      const bool leader = id % r_per_group == 0;
      if (leader != (pass == 1)) continue;
      const cv::Scalar colour = bgr(group_colour(static_cast<int>(id) / r_per_group));
      const int thick = leader ? leader_px : member_px;
      std::optional<cv::Point> prev;
      for (const Poses* p : idx.poses) {
        if (static_cast<std::size_t>(p->xy_size()) < 2 * id + 2) continue;
        const Cell c{p->xy(2 * id), p->xy(2 * id + 1)};
        if (!canvas.inside(c)) {
          prev.reset();
          continue;
        }
        const cv::Point pt = canvas.centre(c);
        if (prev) {
          cv::line(canvas.image(), *prev, pt, colour, thick, cv::LINE_8);
        } else {
          cv::circle(canvas.image(), pt, std::max(0, thick / 2), colour, cv::FILLED, cv::LINE_8);
        }
        prev = pt;
      }
    }
  }
  canvas.start_marker(start_cell(*idx.header));

  const Header& h = *idx.header;
  std::string title = map_text(h) + " | " + mode_text(h);
  if (idx.summary != nullptr) {
    title += " | " + std::to_string(idx.summary->steps()) + " steps | " +
             std::to_string(idx.summary->planning_rounds()) + " planning rounds";
    if (idx.summary->has_explored_fraction()) {
      char buf[32];
      std::snprintf(buf, sizeof buf, " | %.1f%% explored",
                    100.0 * idx.summary->explored_fraction());
      title += buf;
    }
  } else {
    const std::uint32_t last = idx.poses.empty() ? 0 : idx.poses.back()->tick();
    title += " | incomplete record, last tick " + std::to_string(last);
  }
  canvas.title(title);
  canvas.legend(group_count(idx), "", "thick line: leader's path, thin: member's");
  canvas.write(png_path);
}

void render_frontier_png(const std::vector<Frame>& frames, std::uint32_t tick,
                         const std::string& png_path, int scale) {
  const RecordIndex idx = index_frames(frames);
  const RenderGeometry geo = geometry_of(idx, scale);
  Canvas canvas(geo);
  const SnapshotMaps maps = snapshot_maps_of(idx, tick);
  const bool newer = maps.planned_recorded && maps.fused_tick != maps.planned_tick;
  canvas.draw_grid(maps.planned, newer ? &maps.fused : nullptr);

  const std::optional<std::uint32_t> round = maps.round;
  std::vector<const Plan*> plans;
  if (round) {
    for (const Plan* p : idx.plans) {
      if (p->round() == *round && p->tick() <= tick) plans.push_back(p);
    }
  }

  // Group frontiers, filled in the group's colour.
  for (const Plan* p : plans) {
    const cv::Scalar colour = bgr(group_colour(static_cast<int>(p->group())));
    for (int i = 0; i + 1 < p->group_frontiers_xy_size(); i += 2) {
      canvas.fill_cell({p->group_frontiers_xy(i), p->group_frontiers_xy(i + 1)}, colour);
    }
  }
  // Global segments: hatched and outlined in ink; chosen ones outlined again in the chooser's
  // colour, after all the ink so no other group's outline covers it.
  auto segment_cells = [](const Segment& s) {
    std::set<Cell> cells;
    for (int i = 0; i + 1 < s.xy_size(); i += 2) cells.insert({s.xy(i), s.xy(i + 1)});
    return cells;
  };
  for (const Plan* p : plans) {
    for (const Segment& s : p->global_segments()) {
      const std::set<Cell> cells = segment_cells(s);
      for (const Cell& c : cells) canvas.hatch_cell(c, kSegmentInk);
      canvas.outline_cells(cells, kSegmentInk, 1);
    }
  }
  for (const Plan* p : plans) {
    const int chosen = p->chosen_segment();
    if (chosen >= 0 && chosen < p->global_segments_size()) {
      canvas.outline_cells(segment_cells(p->global_segments(chosen)),
                           bgr(group_colour(static_cast<int>(p->group()))), 2);
    }
  }

  // Robots at `tick`, each linked to its waypoint.
  const int r_per_group = idx.robots_per_group;
  const Poses* poses = at_or_before(idx.poses, tick);
  auto robot_cell = [&](int id) -> std::optional<Cell> {
    if (poses == nullptr || poses->xy_size() < 2 * id + 2) return std::nullopt;
    const Cell c{poses->xy(2 * id), poses->xy(2 * id + 1)};
    if (!canvas.inside(c)) return std::nullopt;
    return c;
  };
  for (const Plan* p : plans) {
    const int g = static_cast<int>(p->group());
    const cv::Scalar colour = bgr(group_colour(g));
    for (int k = 0; 2 * k + 1 < p->waypoints_xy_size(); ++k) {
      const Cell w{p->waypoints_xy(2 * k), p->waypoints_xy(2 * k + 1)};
      if (!canvas.inside(w)) continue;
      const cv::Point wp = canvas.centre(w);
      if (const auto rc = robot_cell(g * r_per_group + k)) {
        cv::line(canvas.image(), canvas.centre(*rc), wp, colour, 1, cv::LINE_AA);
      }
      cv::circle(canvas.image(), wp, std::max(3, scale / 2 + 1), colour, 1, cv::LINE_AA);
    }
  }
  if (poses != nullptr) {
    const int robots = poses->xy_size() / 2;
    for (int id = 0; id < robots; ++id) {
      const auto rc = robot_cell(id);
      if (!rc) continue;
      const bool leader = id % r_per_group == 0;
      const int radius = std::max(2, leader ? scale : scale * 2 / 3);
      const cv::Point pt = canvas.centre(*rc);
      cv::circle(canvas.image(), pt, radius, bgr(group_colour(id / r_per_group)), cv::FILLED,
                 cv::LINE_AA);
      cv::circle(canvas.image(), pt, radius, cv::Scalar(0, 0, 0), leader ? 2 : 1, cv::LINE_AA);
    }
  }
  canvas.start_marker(start_cell(*idx.header));

  const Header& h = *idx.header;
  std::string title = map_text(h) + " | " + mode_text(h) + " | tick " + std::to_string(tick);
  if (round) title += " | planning round " + std::to_string(*round);
  std::string map_note;
  if (maps.planned_tick) {
    if (maps.planned_recorded) {
      title += " | planned on the global map of tick " + std::to_string(*maps.planned_tick);
      if (newer) {
        map_note = "light/dark grey: free/wall fused by tick " + std::to_string(*maps.fused_tick);
      }
    } else {
      // An older record (or before the first plan): the planning map is not known.
      title += " | fused map of tick " + std::to_string(*maps.planned_tick);
    }
  }
  canvas.title(title);
  canvas.legend(group_count(idx), map_note,
                "filled: group frontiers, hatched: global frontier segments, ring: waypoint");
  canvas.write(png_path);
}

}  // namespace swarm::record
