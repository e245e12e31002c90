#include "swarm/planner/sensing/raycast.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>

namespace swarm::planner {
namespace {

// Boundary distance along an axis the ray never crosses.
constexpr float kNever = 1e30f;
// Direction components below this never cross a boundary within any grid.
constexpr float kTiny = 1e-20f;
constexpr CellState kOcc = CellState::Occupied;
// Marks "ends a beam of this scan" inside integrate_scan only; never survives the call.
constexpr CellState kHitThisScan = static_cast<CellState>(3);

struct Direction {
  float dx = 1.0f;
  float dy = 0.0f;
};

Direction direction_of(double angle) {
  return {static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
}

// The grid-independent part of a ray's start: which way it steps and the float distances of the
// boundary crossings. Scans start at cell centres, so this is computed once per beam direction.
struct RayStart {
  bool up_x = true;   // steps towards +x
  bool up_y = true;   // steps towards +y
  float tx = kNever;  // distance at which the ray crosses its first vertical cell boundary
  float ty = kNever;  // ... its first horizontal cell boundary
  float dtx = kNever;  // distance between vertical boundaries along the ray
  float dty = kNever;
};

// fx, fy: position inside the cell, in [0, 1].
RayStart ray_start(float fx, float fy, Direction d) {
  RayStart r;
  r.up_x = d.dx > 0.0f;
  r.up_y = d.dy > 0.0f;
  if (std::fabs(d.dx) > kTiny) {
    const float ax = std::fabs(d.dx);
    r.dtx = 1.0f / ax;
    r.tx = (r.up_x ? 1.0f - fx : fx) / ax;
  }
  if (std::fabs(d.dy) > kTiny) {
    const float ay = std::fabs(d.dy);
    r.dty = 1.0f / ay;
    r.ty = (r.up_y ? 1.0f - fy : fy) / ay;
  }
  return r;
}

// One ray's traversal state. Every function here advances it with the same float operations, so
// cast_ray, scan and integrate_scan agree to the bit on which cell is entered at which distance.
struct Walker {
  int idx = 0;     // linear index of the current cell
  int step_x = 0;  // index delta of one x step (+-1)
  int step_y = 0;  // index delta of one y step (+-width)
  int left_x = 0;  // x steps remaining before leaving the grid
  int left_y = 0;  // y steps remaining before leaving the grid
  float tx = kNever;
  float ty = kNever;
  float dtx = kNever;
  float dty = kNever;
};

inline Walker start_walk(const OccupancyGrid& g, int cx, int cy, const RayStart& r) {
  Walker w;
  w.idx = cy * g.width() + cx;
  w.step_x = r.up_x ? 1 : -1;
  w.left_x = r.up_x ? g.width() - 1 - cx : cx;
  w.step_y = r.up_y ? g.width() : -g.width();
  w.left_y = r.up_y ? g.height() - 1 - cy : cy;
  w.tx = r.tx;
  w.ty = r.ty;
  w.dtx = r.dtx;
  w.dty = r.dty;
  return w;
}

// The hot loop of the simulator: one comparison and one table lookup per crossed cell.
inline float trace(const CellState* cells, Walker w, float max_range) {
  for (;;) {
    if (w.tx == w.ty) [[unlikely]] {
      // Exactly through a corner: blocked if either cell sharing the corner is Occupied.
      const float t = w.tx;
      if (t >= max_range) return max_range;
      if (w.left_x == 0 || w.left_y == 0) return t;
      if (cells[w.idx + w.step_x] == kOcc || cells[w.idx + w.step_y] == kOcc) return t;
      w.idx += w.step_x + w.step_y;
      --w.left_x;
      --w.left_y;
      w.tx += w.dtx;
      w.ty += w.dty;
      if (cells[w.idx] == kOcc) return t;
      continue;
    }
    // Plain branches: measured 2-7x faster than mask/select variants. Scans start at cell centres,
    // so each beam direction repeats its x/y step pattern and the branch predictor learns it.
    const bool along_x = w.tx < w.ty;
    const float t = along_x ? w.tx : w.ty;
    if (t >= max_range) return max_range;
    const int left = along_x ? w.left_x : w.left_y;
    if (left == 0) return t;  // the next cell is outside: the world ends in a wall
    w.left_x -= along_x;
    w.left_y -= !along_x;
    w.idx += along_x ? w.step_x : w.step_y;
    w.tx += along_x ? w.dtx : 0.0f;
    w.ty += along_x ? 0.0f : w.dty;
    if (cells[w.idx] == kOcc) return t;
  }
}

// Per-thread table of beam starts from a cell centre: scan and integrate_scan are called with the
// same beam count over and over, and cos/sin and divisions dominate a short ray otherwise.
const std::vector<RayStart>& beam_starts(int beams) {
  thread_local std::vector<RayStart> table;
  thread_local int table_beams = -1;
  if (table_beams != beams) {
    table.resize(static_cast<std::size_t>(beams));
    for (int i = 0; i < beams; ++i) {
      const Direction d = direction_of(beam_angle(i, beams));
      table[static_cast<std::size_t>(i)] = ray_start(0.5f, 0.5f, d);
    }
    table_beams = beams;
  }
  return table;
}

}  // namespace

double beam_angle(int i, int beams) { return 2.0 * std::numbers::pi * i / beams; }

float cast_ray(const OccupancyGrid& truth, double x, double y, double angle_rad,
               float max_range_cells) {
  const double fx_floor = std::floor(x);
  const double fy_floor = std::floor(y);
  if (!(fx_floor >= 0.0 && fy_floor >= 0.0 && fx_floor < truth.width() &&
        fy_floor < truth.height())) {
    return 0.0f;
  }
  const int cx = static_cast<int>(fx_floor);
  const int cy = static_cast<int>(fy_floor);
  if (truth.at(Cell{cx, cy}) == kOcc) return 0.0f;
  const RayStart r = ray_start(static_cast<float>(x - fx_floor), static_cast<float>(y - fy_floor),
                               direction_of(angle_rad));
  const Walker w = start_walk(truth, cx, cy, r);
  return trace(truth.data().data(), w, max_range_cells);
}

void scan(const OccupancyGrid& truth, Cell origin, int beams, float max_range_cells,
          float* ranges_out) {
  if (beams <= 0) return;
  if (truth.at(origin) == kOcc) {  // also covers out of bounds
    for (int i = 0; i < beams; ++i) ranges_out[i] = 0.0f;
    return;
  }
  const std::vector<RayStart>& starts = beam_starts(beams);
  const CellState* cells = truth.data().data();
  for (int i = 0; i < beams; ++i) {
    const Walker w = start_walk(truth, origin.x, origin.y, starts[static_cast<std::size_t>(i)]);
    ranges_out[i] = trace(cells, w, max_range_cells);
  }
}

int integrate_scan(OccupancyGrid& map, Cell origin, const float* ranges, int beams,
                   float max_range_cells, std::vector<CellChange>* changes) {
  if (!map.in_bounds(origin)) return 0;
  thread_local std::vector<int> passed;  // cells some beam crossed before its end
  thread_local std::vector<int> hits;    // cells some beam ended in
  passed.clear();
  hits.clear();
  const int origin_idx = map.index(origin);
  passed.push_back(origin_idx);

  const std::vector<RayStart>& starts = beam_starts(beams < 0 ? 0 : beams);
  for (int i = 0; i < beams; ++i) {
    float r = ranges[i];
    if (!(r >= 0.0f)) continue;  // negative or NaN: no information
    const bool hit = r < max_range_cells;
    if (!hit) r = max_range_cells;
    Walker w = start_walk(map, origin.x, origin.y, starts[static_cast<std::size_t>(i)]);
    // Same stepping as trace(): the current cell is kept while the next boundary lies at or
    // before the end point, so the cell entered exactly at distance r is the one hit.
    for (;;) {
      const bool corner = w.tx == w.ty;
      const bool along_x = w.tx < w.ty;
      const float t = along_x ? w.tx : w.ty;
      if (hit ? t > r : t >= r) {
        if (!hit) {
          passed.push_back(w.idx);  // the range ends inside this cell
        } else if (w.idx != origin_idx) {
          hits.push_back(w.idx);  // the beam ended in this cell; the origin always stays Free
        }
        break;
      }
      passed.push_back(w.idx);
      if (corner) {
        if (hit && t == r) break;  // stopped at a corner: which cell was hit is ambiguous
        if (w.left_x == 0 || w.left_y == 0) break;
        w.idx += w.step_x + w.step_y;
        --w.left_x;
        --w.left_y;
        w.tx += w.dtx;
        w.ty += w.dty;
        continue;
      }
      const int left = along_x ? w.left_x : w.left_y;
      if (left == 0) break;  // the end lies outside the grid
      w.left_x -= along_x;
      w.left_y -= !along_x;
      w.idx += along_x ? w.step_x : w.step_y;
      w.tx += along_x ? w.dtx : 0.0f;
      w.ty += along_x ? 0.0f : w.dty;
    }
  }

  // Occupied wins within the scan: tag the hit cells first so that freeing skips them.
  std::vector<CellState>& cells = map.data();
  int changed = 0;
  for (const int h : hits) {
    const CellState s = cells[static_cast<std::size_t>(h)];
    if (s == kHitThisScan) continue;
    if (s != kOcc) {
      ++changed;
      if (changes) changes->push_back({h, kOcc});
    }
    cells[static_cast<std::size_t>(h)] = kHitThisScan;
  }
  for (const int p : passed) {
    CellState& s = cells[static_cast<std::size_t>(p)];
    if (s == kHitThisScan || s == CellState::Free) continue;
    s = CellState::Free;
    ++changed;
    if (changes) changes->push_back({p, CellState::Free});
  }
  for (const int h : hits) cells[static_cast<std::size_t>(h)] = kOcc;
  return changed;
}

}  // namespace swarm::planner
