#include "darp_engine.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>


namespace swarm::planner::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

DarpEngine::DarpEngine(const DarpSpace& space, std::vector<int> starts, const DarpConfig& config,
                       std::uint64_t stream)
    : space_(space),
      config_(config),
      rng_(mix_seed(config.seed, stream)),
      n_(space.robots()),
      m_(space.graph.size()),
      starts_(std::move(starts)) {
  assert(static_cast<int>(starts_.size()) == n_);
  const RegionGraph& g = space_.graph;
  int x1 = 0, y1 = 0;
  box_x0_ = g.width;
  box_y0_ = g.height;
  for (const Cell& c : g.cells) {
    box_x0_ = std::min(box_x0_, c.x);
    box_y0_ = std::min(box_y0_, c.y);
    x1 = std::max(x1, c.x);
    y1 = std::max(y1, c.y);
  }
  box_w_ = x1 - box_x0_ + 1;
  box_h_ = y1 - box_y0_ + 1;
  // Cells are numbered row-major: the cells of box row y are [row_begin_[y], row_begin_[y + 1]).
  row_begin_.assign(box_h_ + 1, 0);
  for (const Cell& c : g.cells) ++row_begin_[c.y - box_y0_ + 1];
  for (int y = 0; y < box_h_; ++y) row_begin_[y + 1] += row_begin_[y];

  // E_r(c) = distance from r's start; kept as log. A robot never gets a cell of another piece.
  log_metric_.assign(static_cast<std::size_t>(n_) * m_, std::numeric_limits<Metric>::infinity());
  std::vector<int> steps;
  for (int r = 0; r < n_; ++r) {
    Metric* e = &log_metric_[static_cast<std::size_t>(r) * m_];
    const Cell s = g.cells[starts_[r]];
    if (config_.distance == DarpDistance::Geodesic) steps = bfs_steps(g, {starts_[r]});
    for (int i = 0; i < m_; ++i) {
      if (space_.piece[i] != space_.robot_piece[r]) continue;
      double d = 0;
      if (config_.distance == DarpDistance::Geodesic) {
        d = steps[i];
      } else {
        const double dx = g.cells[i].x - s.x;
        const double dy = g.cells[i].y - s.y;
        d = std::sqrt(dx * dx + dy * dy);
      }
      // The start cell itself (d = 0) is pinned to r; any finite value will do there.
      e[i] = static_cast<Metric>(std::log(std::max(d, 0.5)));
    }
  }
  best_value_.resize(m_);
  owner_.resize(m_);
  previous_owner_.assign(m_, -1);
  counts_.resize(n_);
  split_.resize(n_);
  parent_.resize(m_);
  in_start_piece_.resize(m_);
  left_.resize(m_);
  down_.resize(m_);
  for (int i = 0; i < m_; ++i) {
    left_[i] = g.next[i][1];  // RegionGraph order: +x, -x, +y, -y
    down_[i] = g.next[i][3];
  }
  assign();
  evaluate();
}

void DarpEngine::assign() {
  owner_.swap(previous_owner_);  // previous_owner_: the division evaluate() saw last
  // Robot-major sweeps keep the inner loop a plain compare-and-select over contiguous arrays.
  std::copy_n(log_metric_.begin(), m_, best_value_.begin());
  std::fill(owner_.begin(), owner_.end(), 0);
  for (int r = 1; r < n_; ++r) {
    const Metric* e = &log_metric_[static_cast<std::size_t>(r) * m_];
    Metric* best = best_value_.data();
    std::int32_t* own = owner_.data();
    const int m = m_;  // a local bound: the stores below could alias a member
    for (int i = 0; i < m; ++i) {
      const bool lower = std::isless(e[i], best[i]);
      best[i] = lower ? e[i] : best[i];
      own[i] = lower ? r : own[i];
    }
  }
  for (int r = 0; r < n_; ++r) owner_[starts_[r]] = r;
  std::fill(counts_.begin(), counts_.end(), 0);
  changed_.clear();
  for (int i = 0; i < m_; ++i) {
    ++counts_[owner_[i]];
    if (owner_[i] != previous_owner_[i]) changed_.push_back(i);
  }
}

namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

}  // namespace

bool DarpEngine::simple_point(int c, int r) const {
  // The cell's 4-neighbours owned by r, in order around it (+x, +y, -x, -y); two consecutive ones
  // are joined when the corner cell between them is r's too. Removing c keeps r's cells around it
  // together exactly when that leaves one group.
  const auto& nb = space_.graph.next[c];  // RegionGraph order: +x, -x, +y, -y
  const int ring[4] = {nb[0], nb[2], nb[1], nb[3]};
  constexpr int kTowardsNext[4] = {2, 1, 3, 0};  // the direction of ring[k + 1] as seen from c
  auto mine = [&](int cell) { return cell >= 0 && owner_[cell] == r; };
  int present = 0, joined = 0;
  for (int k = 0; k < 4; ++k) {
    if (!mine(ring[k])) continue;
    ++present;
    if (mine(ring[(k + 1) % 4]) && mine(space_.graph.next[ring[k]][kTowardsNext[k]])) ++joined;
  }
  return present > 0 && (joined == 4 || present - joined == 1);
}

bool DarpEngine::still_connected() {
  // Near convergence a handful of cells change hands per iteration. Replay the changes one by
  // one from the previous division, in which every region was connected: a region stays
  // connected when a cell it loses is a simple point (simple_point) and a cell it gains touches
  // it. Any other change asks for the full labelling (a false alarm only costs time).
  if (!connected_before_) return false;
  gained_by_.clear();
  for (int c : changed_) {
    gained_by_.push_back(owner_[c]);
    owner_[c] = previous_owner_[c];
  }
  bool ok = true;
  for (std::size_t k = 0; k < changed_.size(); ++k) {
    const int c = changed_[k];
    ok = ok && simple_point(c, owner_[c]);
    owner_[c] = gained_by_[k];
    if (ok) {
      bool touches = false;
      for (int nb : space_.graph.next[c]) touches |= nb >= 0 && owner_[nb] == owner_[c];
      ok = touches;
    }
  }
  return ok;
}

void DarpEngine::evaluate() {
  if (still_connected()) {
    std::fill(split_.begin(), split_.end(), 0);
    score_ = {};
    for (int r = 0; r < n_; ++r) {
      score_.max_deviation = std::max(score_.max_deviation, std::abs(counts_[r] - space_.shares[r]));
    }
    return;
  }
  // The connected pieces of every region at once, by two-pass labelling: union-find over the
  // cells in row-major order, joining each cell to its -x and -y neighbours of the same owner,
  // every root being the smallest index of its piece. Walking the arrays in order is what makes
  // this cheap (a BFS per region jumps around memory).
  const int m = m_;
  for (int i = 0; i < m; ++i) {
    const int o = owner_[i];
    // The -x neighbour (i - 1) was finished last, and nothing was joined since: its parent is a root.
    const int l = left_[i];
    int root = l >= 0 && owner_[l] == o ? parent_[l] : i;
    const int d = down_[i];
    if (d >= 0 && owner_[d] == o) {
      const int rd = find_root(parent_, d);
      if (root == i) {
        root = rd;
      } else if (rd != root) {
        parent_[std::max(root, rd)] = std::min(root, rd);
        root = std::min(root, rd);
      }
    }
    parent_[i] = root;
  }
  // Every parent is a smaller index, so one forward pass leaves each cell pointing at its root.
  for (int i = 0; i < m; ++i) parent_[i] = parent_[parent_[i]];
  std::fill(split_.begin(), split_.end(), 0);
  for (int i = 0; i < m; ++i) {
    const int o = owner_[i];
    in_start_piece_[i] = parent_[i] == parent_[starts_[o]];
    split_[o] |= !in_start_piece_[i];
  }
  score_ = {};
  for (int r = 0; r < n_; ++r) {
    score_.split += split_[r];
    score_.max_deviation = std::max(score_.max_deviation, std::abs(counts_[r] - space_.shares[r]));
  }
  connected_before_ = score_.split == 0;
}

DarpStatus DarpEngine::run(int budget, const std::function<bool()>& should_stop,
                           std::vector<int>& best, DivisionScore& best_score) {
  for (;;) {
    if (best.empty() || score_.better_than(best_score)) {
      best = owner_;
      best_score = score_;
    }
    if (goal()) return DarpStatus::Converged;
    if (updates_ >= budget) return DarpStatus::Failed;
    if (should_stop && should_stop()) return DarpStatus::Stopped;
    update();
    assign();
    evaluate();
  }
}

void DarpEngine::update() {
  // Fairness factor m_r, per piece (robots in different pieces never compete for cells). The
  // pressure is towards the exact share (no dead band, as the reference at its first threshold);
  // only the goal test allows the tolerance.
  std::vector<double> log_m(n_, 0.0);
  for (int p = 0; p < space_.pieces; ++p) {
    int np = 0;
    for (int r = 0; r < n_; ++r) np += space_.robot_piece[r] == p;
    double excess = 0;  // D
    double over_x = 0;  // X
    for (int r = 0; r < n_; ++r) {
      if (space_.robot_piece[r] != p || counts_[r] <= space_.shares[r]) continue;
      const double s = space_.shares[r];
      excess += (counts_[r] - s) / (np * s);
      over_x += counts_[r] / (np * s);
    }
    if (over_x <= 0) continue;
    for (int r = 0; r < n_; ++r) {
      if (space_.robot_piece[r] != p) continue;
      const double x = counts_[r] / (np * space_.shares[r]);
      const double step = (x / over_x) * (excess / 2);
      const bool over = counts_[r] > space_.shares[r];
      log_m[r] = std::log(std::max(over ? 1 + step : 1 - step, 1e-3));
    }
  }

  // Every value of a cell is shifted by the same amount (the cell's smallest value, found by the
  // last assign()): which robot is cheapest never changes, and the values stay near 0 where
  // cells change hands, so float keeps ample precision there and nothing can overflow.
  const float level = static_cast<float>(config_.random_level);
  constexpr float kScale = 2.0f / 65536.0f;  // 16-bit draws: u = level * ((k + 0.5) * 2 / 65536 - 1)
  noise_.resize(m_ + 3);
  const Metric* shift = best_value_.data();
  for (int r = 0; r < n_; ++r) {
    // One 64-bit draw gives four 16-bit uniforms: the perturbation only needs to break ties.
    for (int i = 0; i < m_; i += 4) {
      std::uint64_t bits = rng_.next();
      for (int k = 0; k < 4; ++k, bits >>= 16) {
        noise_[i + k] = level * ((static_cast<float>(bits & 0xffff) + 0.5f) * kScale - 1.0f);
      }
    }
    Metric* e = &log_metric_[static_cast<std::size_t>(r) * m_];
    const Metric lm = static_cast<Metric>(log_m[r]);
    const Metric* u = noise_.data();
    if (split_[r]) {
      connectivity_correction(r, correction_);
      const Metric* c = correction_.data();
      for (int i = 0; i < m_; ++i) e[i] += lm + u[i] + c[i] - shift[i];
    } else {
      for (int i = 0; i < m_; ++i) e[i] += lm + u[i] - shift[i];
    }
  }
  ++updates_;
}

void DarpEngine::connectivity_correction(int r, std::vector<Metric>& correction) {
  // Pieces of r: the one holding its start, and the others (found by evaluate()).
  own_.assign(m_, 0);
  stray_.assign(m_, 0);
  for (int i = 0; i < m_; ++i) {
    if (owner_[i] != r) continue;
    (in_start_piece_[i] ? own_ : stray_)[i] = 1;
  }
  distances_from(own_, d1_);
  distances_from(stray_, d2_);  // usually a few cells: see distances_from
  const int piece = space_.robot_piece[r];
  const bool one_piece = space_.pieces == 1;
  double max1 = 0, max2 = 0;
  for (int i = 0; i < m_; ++i) {
    if (!one_piece && space_.piece[i] != piece) continue;
    max1 = std::max(max1, d1_[i]);
    max2 = std::max(max2, d2_[i]);
  }
  const double k1 = max1 > 0 ? 1 / max1 : 0.0;
  const double k2 = max2 > 0 ? 1 / max2 : 0.0;
  double lo = kInf, hi = -kInf;
  for (int i = 0; i < m_; ++i) {
    if (!one_piece && space_.piece[i] != piece) continue;
    d1_[i] = d1_[i] * k1 - d2_[i] * k2;  // d1_ now holds d1 / max1 - d2 / max2
    lo = std::min(lo, d1_[i]);
    hi = std::max(hi, d1_[i]);
  }
  const double cv = config_.connectivity_variation;
  const double scale = hi > lo ? 2 * cv / (hi - lo) : 0.0;
  correction.assign(m_, 0.0f);
  if (scale <= 0) return;
  for (int i = 0; i < m_; ++i) {
    if (one_piece || space_.piece[i] == piece) correction[i] = static_cast<Metric>((d1_[i] - lo) * scale - cv);
  }
}

namespace {

// One row of the exact squared Euclidean distance transform of Felzenszwalb & Huttenlocher
// ("Distance transforms of sampled functions", Theory of Computing 8, 2012): out[i] = min_p
// (x_i - p)^2 + f(p), f(p) = column_steps[p]^2 (the column pass), over the columns p listed in
// `roots` (ascending; the others hold no source), by the lower envelope of their parabolas, evaluated only at the row's region cells
// [begin, end) (x ascending). The envelope's breakpoints are kept as fractions and compared by
// cross-multiplication: every quantity is an integer below 2^53, so the transform is exact and
// needs no division. v, zn, zd: scratch of roots.size() + 1 entries.
void squared_distance_row(const int* column_steps, const std::vector<int>& roots, const Cell* cells, int begin,
                          int end, int x0, double* out, int* v, double* zn, double* zd) {
  auto f = [&](int p) { return static_cast<double>(column_steps[p]) * column_steps[p]; };
  auto height = [&](int p) { return f(p) + static_cast<double>(p) * p; };
  int k = 0;
  v[0] = roots[0];
  for (std::size_t i = 1; i < roots.size(); ++i) {
    const int q = roots[i];
    double num = 0, den = 0;
    for (;;) {
      num = height(q) - height(v[k]);  // breakpoint with parabola k: num / den
      den = 2.0 * (q - v[k]);
      if (k == 0 || num * zd[k] > zn[k] * den) break;  // to the right of breakpoint k: keep k
      --k;
    }
    ++k;
    v[k] = q;
    zn[k] = num;
    zd[k] = den;
  }
  const int last = k;
  k = 0;
  for (int i = begin; i < end; ++i) {
    const int q = cells[i].x - x0;
    while (k < last && zn[k + 1] < q * zd[k + 1]) ++k;
    const double dq = q - v[k];
    out[i] = dq * dq + f(v[k]);
  }
}

}  // namespace

void DarpEngine::distances_from(const std::vector<std::uint8_t>& source, std::vector<double>& out) {
  const RegionGraph& g = space_.graph;
  out.assign(m_, 0.0);
  if (config_.distance == DarpDistance::Geodesic) {
    // BFS steps through the region; cells of other pieces keep 0 (they are never r's).
    queue_.clear();
    for (int i = 0; i < m_; ++i) {
      if (source[i]) queue_.push_back(i);
    }
    steps_ = bfs_steps(g, queue_);
    for (int i = 0; i < m_; ++i) out[i] = std::max(steps_[i], 0);
    return;
  }
  // Euclidean distance, walls ignored (as the reference). A few sources (a region's stray piece
  // is typically a handful of cells): directly, per cell and source.
  queue_.clear();
  for (int i = 0; i < m_; ++i) {
    if (source[i]) queue_.push_back(i);
  }
  if (queue_.size() <= 16) {
    for (int i = 0; i < m_; ++i) {
      double best = kInf;
      for (int s : queue_) {
        const double dx = g.cells[i].x - g.cells[s].x;
        const double dy = g.cells[i].y - g.cells[s].y;
        best = std::min(best, dx * dx + dy * dy);
      }
      out[i] = best;
    }
    for (double& d : out) d = std::sqrt(d);  // a separate loop vectorises (see CMakeLists.txt)
    return;
  }
  // Otherwise the exact transform over the bounding box, computed here rather than with OpenCV:
  // this runs twice per split region per iteration on small images, where a library call's
  // set-up and thread-pool dispatch cost more than the transform itself.
  const std::size_t w = box_w_;
  // Columns: steps to the nearest source in the same column, by a sweep down and one up, all
  // columns at once row by row (contiguous memory; the input is 0 or "none", so the general
  // lower envelope is not needed in this direction).
  constexpr int kNone = 1 << 20;  // more steps than any map has rows
  steps_.assign(w * box_h_, kNone);
  for (int i = 0; i < m_; ++i) {
    if (source[i]) steps_[(g.cells[i].y - box_y0_) * w + (g.cells[i].x - box_x0_)] = 0;
  }
  for (int y = 1; y < box_h_; ++y) {
    const int* above = &steps_[(y - 1) * w];
    int* row = &steps_[y * w];
    for (std::size_t x = 0; x < w; ++x) row[x] = std::min(row[x], above[x] + 1);
  }
  for (int y = box_h_ - 2; y >= 0; --y) {
    int* row = &steps_[y * w];
    const int* below = &steps_[(y + 1) * w];
    for (std::size_t x = 0; x < w; ++x) row[x] = std::min(row[x], below[x] + 1);
  }
  // Rows: only the columns that hold a source anywhere have finite values; only region cells
  // need a distance.
  roots_.clear();
  for (int x = 0; x < box_w_; ++x) {
    if (steps_[x] < kNone / 2) roots_.push_back(x);
  }
  if (roots_.empty()) return;  // no source: no distance (all 0)
  v_.resize(roots_.size() + 1);
  zn_.resize(roots_.size() + 1);
  zd_.resize(roots_.size() + 1);
  for (int y = 0; y < box_h_; ++y) {
    if (row_begin_[y] == row_begin_[y + 1]) continue;
    squared_distance_row(&steps_[y * w], roots_, g.cells.data(), row_begin_[y], row_begin_[y + 1], box_x0_,
                         out.data(), v_.data(), zn_.data(), zd_.data());
  }
  for (double& d : out) d = std::sqrt(d);
}

}  // namespace swarm::planner::detail
