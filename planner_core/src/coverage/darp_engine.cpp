#include "darp_engine.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>


namespace swarm::planner::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The hot loops are compiled twice, for AVX2 and for the x86-64 baseline (SSE2), and the loader
// picks the one the CPU runs (function multi-versioning). Lane for lane the same IEEE operations
// in the same order (no FMA: -ffp-contract=off; no reordered reductions), so the same results.
// GCC only: clang (the fuzz build) wants target_clones on a member's first declaration, in the
// class. Not in sanitizer builds: they need no speed, and ThreadSanitizer crashes in the ifunc
// resolvers, which run before it is set up (every test binary linking this segfaulted at start).
#if defined(__x86_64__) && defined(__gnu_linux__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
#define SWARM_DARP_HOT __attribute__((target_clones("avx2", "default")))
#else
#define SWARM_DARP_HOT
#endif

// Robot r takes the cell when its value is strictly lower (ties keep the lower robot index).
inline void take_if_lower(DarpEngine::Metric value, std::int32_t r, DarpEngine::Metric& best, std::int32_t& owner) {
  const bool lower = std::isless(value, best);
  best = lower ? value : best;
  owner = lower ? r : owner;
}

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
  best_next_.resize(m_);
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
  cell_x_.resize(m_);
  cell_y_.resize(m_);
  cell_column_.resize(m_);
  for (int i = 0; i < m_; ++i) {
    cell_column_[i] = g.cells[i].x;
    cell_x_[i] = g.cells[i].x;
    cell_y_[i] = g.cells[i].y;
  }
  own_field_.resize(n_);
  stray_field_.resize(n_);
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
    for (int i = 0; i < m; ++i) take_if_lower(e[i], r, best[i], own[i]);
  }
  finish_assignment(true);
}

void DarpEngine::finish_assignment(bool first) {
  for (int r = 0; r < n_; ++r) owner_[starts_[r]] = r;
  changed_.clear();
  // Blocks of cells without a change are passed over with one vectorised test each.
  constexpr int kBlock = 32;
  const std::int32_t* now = owner_.data();
  const std::int32_t* before = previous_owner_.data();
  for (int b = 0; b < m_; b += kBlock) {
    const int e = std::min(m_, b + kBlock);
    std::int32_t differ = 0;
    for (int i = b; i < e; ++i) differ |= now[i] ^ before[i];
    if (differ == 0) continue;
    for (int i = b; i < e; ++i) {
      if (now[i] != before[i]) changed_.push_back(i);
    }
  }
  if (first) {
    std::fill(counts_.begin(), counts_.end(), 0);
    for (int i = 0; i < m_; ++i) ++counts_[owner_[i]];
    return;
  }
  for (int c : changed_) {  // counts_ held previous_owner_'s; few cells change hands
    --counts_[previous_owner_[c]];
    ++counts_[owner_[c]];
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
    ok = ok && simple_point(space_.graph, owner_, c, owner_[c]);
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
  // (Raw pointers: a store through a byte pointer could otherwise alias every member.)
  const std::int32_t* __restrict own = owner_.data();
  const int* __restrict parent = parent_.data();
  const int* __restrict start = starts_.data();
  std::uint8_t* __restrict in_start = in_start_piece_.data();
  std::uint8_t* __restrict split = split_.data();
  for (int i = 0; i < m; ++i) {
    const int o = own[i];
    in_start[i] = parent[i] == parent[start[o]];
    split[o] |= !in_start[i];
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
    evaluate();
  }
}

SWARM_DARP_HOT void DarpEngine::update() {
  // Fairness factor m_r, per piece (robots in different pieces never compete for cells). The
  // pressure is towards the exact share (no dead band, as the reference at its first threshold);
  // only the goal test allows the tolerance.
  std::vector<double>& log_m = log_m_;
  log_m.assign(n_, 0.0);
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
  // last assignment): which robot is cheapest never changes, and the values stay near 0 where
  // cells change hands, so float keeps ample precision there and nothing can overflow.
  // The new values are compared as they are written: the next assignment is built in
  // best_next_ / previous_owner_ (free until then) while owner_ still holds the division the
  // connectivity corrections are computed from.
  const float level = static_cast<float>(config_.random_level);
  constexpr float kScale = 2.0f / 65536.0f;  // 16-bit draws: u = level * ((k + 0.5) * 2 / 65536 - 1)
  const int m = m_;
  const int words = (m + 3) / 4;
  noise_bits_.resize(static_cast<std::size_t>(words) * 4);
  std::fill(best_next_.begin(), best_next_.end(), std::numeric_limits<Metric>::infinity());
  std::fill(previous_owner_.begin(), previous_owner_.end(), 0);
  const Metric* __restrict shift = best_value_.data();
  Metric* __restrict best = best_next_.data();
  std::int32_t* __restrict own = previous_owner_.data();
  std::uint16_t* __restrict bits = noise_bits_.data();
  auto noise = [&](int i) { return level * ((static_cast<float>(bits[i]) + 0.5f) * kScale - 1.0f); };
  Rng rng = rng_;  // a local copy stays in registers (the stores below could alias the member)
  for (int r = 0; r < n_; ++r) {
    // One 64-bit draw gives four 16-bit uniforms: the perturbation only needs to break ties.
    for (int w = 0; w < words; ++w) {
      std::uint64_t b = rng.next();
      if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(bits + 4 * w, &b, sizeof b);  // the same four 16-bit fields, lowest first
      } else {
        for (int k = 0; k < 4; ++k, b >>= 16) bits[4 * w + k] = static_cast<std::uint16_t>(b & 0xffff);
      }
    }
    Metric* __restrict e = &log_metric_[static_cast<std::size_t>(r) * m_];
    const Metric lm = static_cast<Metric>(log_m[r]);
    if (split_[r]) {
      connectivity_correction(r, correction_);
      const Metric* __restrict c = correction_.data();
      for (int i = 0; i < m; ++i) {
        e[i] += lm + noise(i) + c[i] - shift[i];
        take_if_lower(e[i], r, best[i], own[i]);
      }
    } else {
      for (int i = 0; i < m; ++i) {
        e[i] += lm + noise(i) - shift[i];
        take_if_lower(e[i], r, best[i], own[i]);
      }
    }
  }
  rng_ = rng;
  best_value_.swap(best_next_);
  owner_.swap(previous_owner_);  // previous_owner_: the division evaluate() saw last
  finish_assignment(false);
  ++updates_;
}

SWARM_DARP_HOT void DarpEngine::connectivity_correction(int r, std::vector<Metric>& correction) {
  // Pieces of r: the one holding its start, and the others (found by evaluate()).
  own_.resize(m_);
  stray_.resize(m_);
  {
    const std::int32_t* __restrict owner = owner_.data();
    const std::uint8_t* __restrict in_start = in_start_piece_.data();
    std::uint8_t* __restrict own = own_.data();
    std::uint8_t* __restrict stray = stray_.data();
    const int m = m_;
    for (int i = 0; i < m; ++i) {
      const std::uint8_t mine = owner[i] == r;
      own[i] = mine & in_start[i];
      stray[i] = mine & (in_start[i] ^ 1);
    }
  }
  const int piece = space_.robot_piece[r];
  const DistanceField& f1 = distances_to(own_field_[r], own_, piece);
  const DistanceField& f2 = distances_to(stray_field_[r], stray_, piece);  // usually a few cells
  const std::vector<double>& d1 = f1.distance;
  const std::vector<double>& d2 = f2.distance;
  const bool one_piece = space_.pieces == 1;
  const double k1 = f1.max > 0 ? 1 / f1.max : 0.0;
  const double k2 = f2.max > 0 ? 1 / f2.max : 0.0;
  diff_.resize(m_);
  // d1 / max1 - d2 / max2, and its range over the piece (min and max are exact: any order of
  // taking them gives the same; lanes let them vectorise).
  constexpr int kLanes = 4;
  double lo_lane[kLanes], hi_lane[kLanes];
  std::fill_n(lo_lane, kLanes, kInf);
  std::fill_n(hi_lane, kLanes, -kInf);
  {
    const double* __restrict a = d1.data();
    const double* __restrict b = d2.data();
    double* __restrict diff = diff_.data();
    const int* __restrict piece_of = space_.piece.data();
    const int m = m_;
    for (int i = 0; i < m; ++i) diff[i] = a[i] * k1 - b[i] * k2;
    const int whole = one_piece ? m - m % kLanes : 0;
    for (int i = 0; i < whole; i += kLanes) {
      for (int k = 0; k < kLanes; ++k) {
        lo_lane[k] = std::min(lo_lane[k], diff[i + k]);
        hi_lane[k] = std::max(hi_lane[k], diff[i + k]);
      }
    }
    for (int i = whole; i < m; ++i) {
      if (!one_piece && piece_of[i] != piece) continue;
      lo_lane[0] = std::min(lo_lane[0], diff[i]);
      hi_lane[0] = std::max(hi_lane[0], diff[i]);
    }
  }
  const double lo = *std::min_element(lo_lane, lo_lane + kLanes);
  const double hi = *std::max_element(hi_lane, hi_lane + kLanes);
  const double cv = config_.connectivity_variation;
  const double scale = hi > lo ? 2 * cv / (hi - lo) : 0.0;
  correction.resize(m_);
  Metric* c = correction.data();
  if (scale <= 0) {
    std::fill(correction.begin(), correction.end(), 0.0f);
  } else if (one_piece) {
    for (int i = 0; i < m_; ++i) c[i] = static_cast<Metric>((diff_[i] - lo) * scale - cv);
  } else {
    for (int i = 0; i < m_; ++i) {
      c[i] = space_.piece[i] == piece ? static_cast<Metric>((diff_[i] - lo) * scale - cv) : 0.0f;
    }
  }
}

SWARM_DARP_HOT const DarpEngine::DistanceField& DarpEngine::distances_to(DistanceField& field,
                                                                         const std::vector<std::uint8_t>& source,
                                                                         int piece) {
  // More new cells than this: a new transform is cheaper than lowering to each of them.
  constexpr std::size_t kMaxAdded = 8;
  std::vector<double>& d = field.distance;
  if (field.valid) {
    // Cells gained and lost since, counted without branches (the sets are 0/1 per cell).
    const std::uint8_t* now = source.data();
    const std::uint8_t* before = field.source.data();
    int gained = 0, lost = 0;
    for (int i = 0; i < m_; ++i) {
      gained += now[i] & ~before[i] & 1;
      lost += before[i] & ~now[i] & 1;
    }
    if (gained == 0 && lost == 0) return field;
    if (lost == 0 && gained <= static_cast<int>(kMaxAdded) && config_.distance == DarpDistance::Euclidean) {
      added_.clear();
      for (int i = 0; i < m_; ++i) {
        if (now[i] != before[i]) added_.push_back(i);
      }
      // The set only grew: a distance can only drop, to one of the new cells. Squared distances
      // are integers, so comparing against the square of the stored root decides exactly (an
      // equal one may pass and then rewrites the same root).
      squared_distances_to(added_, near_);
      for (int i = 0; i < m_; ++i) {
        if (near_[i] < d[i] * d[i]) d[i] = std::sqrt(near_[i]);
      }
      for (int a : added_) field.source[a] = 1;
      field.max = max_in_piece(d, piece);
      return field;
    }
  }
  distances_from(source, d);
  field.source = source;
  // (The sets of a split robot are never empty; an empty one has no distances to lower.)
  field.valid = std::find(source.begin(), source.end(), 1) != source.end();
  field.max = max_in_piece(d, piece);
  return field;
}

SWARM_DARP_HOT void DarpEngine::squared_distances_to(const std::vector<int>& cells, std::vector<double>& out) const {
  out.assign(m_, kInf);
  const double* x = cell_x_.data();
  const double* y = cell_y_.data();
  double* d = out.data();
  for (int s : cells) {  // source by source: the inner loop vectorises
    const double sx = x[s], sy = y[s];
    for (int i = 0; i < m_; ++i) {
      const double dx = x[i] - sx;
      const double dy = y[i] - sy;
      d[i] = std::min(d[i], dx * dx + dy * dy);
    }
  }
}

SWARM_DARP_HOT double DarpEngine::max_in_piece(const std::vector<double>& d, int piece) const {
  constexpr int kLanes = 4;  // max is exact: lanes let it vectorise and give the same value
  double lane[kLanes] = {0, 0, 0, 0};
  const bool one_piece = space_.pieces == 1;
  const int whole = one_piece ? m_ - m_ % kLanes : 0;
  for (int i = 0; i < whole; i += kLanes) {
    for (int k = 0; k < kLanes; ++k) lane[k] = std::max(lane[k], d[i + k]);
  }
  for (int i = whole; i < m_; ++i) {
    if (one_piece || space_.piece[i] == piece) lane[0] = std::max(lane[0], d[i]);
  }
  return *std::max_element(lane, lane + kLanes);
}

namespace {

// One row of the exact squared Euclidean distance transform of Felzenszwalb & Huttenlocher
// ("Distance transforms of sampled functions", Theory of Computing 8, 2012): out[i] = min_p
// (x_i - p)^2 + f(p), f(p) = column_steps[p]^2 (the column pass), over the columns p listed in
// `roots` (ascending; the others hold no source), by the lower envelope of their parabolas,
// evaluated only at the row's region cells [begin, end) (x ascending). The envelope's
// breakpoints are kept as fractions of integers and compared by cross-multiplication, all in
// 64-bit integers: the transform is exact and needs neither division nor floating point.
// out[i] receives root[d^2], the distance. v, zn, zd: scratch of roots.size() + 1 entries.
void distance_row(const int* column_steps, const std::vector<int>& roots, const int* cell_x, int begin, int end,
                  int x0, const double* root, double* out, int* v, std::int64_t* zn, std::int64_t* zd) {
  auto f = [&](int p) { return static_cast<std::int64_t>(column_steps[p]) * column_steps[p]; };
  auto height = [&](int p) { return f(p) + static_cast<std::int64_t>(p) * p; };
  int k = 0;
  v[0] = roots[0];
  std::int64_t top = height(v[0]);  // height(v[k])
  for (std::size_t i = 1; i < roots.size(); ++i) {
    const int q = roots[i];
    const std::int64_t hq = height(q);
    std::int64_t num = 0, den = 0;
    for (;;) {
      num = hq - top;  // breakpoint with parabola k: num / den
      den = 2 * static_cast<std::int64_t>(q - v[k]);
      if (k == 0 || num * zd[k] > zn[k] * den) break;  // to the right of breakpoint k: keep k
      --k;
      top = height(v[k]);
    }
    ++k;
    v[k] = q;
    zn[k] = num;
    zd[k] = den;
    top = hq;
  }
  const int last = k;
  k = 0;
  for (int i = begin; i < end; ++i) {
    const std::int64_t q = cell_x[i] - x0;
    while (k < last && zn[k + 1] < q * zd[k + 1]) ++k;
    const std::int64_t dq = q - v[k];
    out[i] = root[dq * dq + f(v[k])];
  }
}

}  // namespace

void DarpEngine::distances_from(const std::vector<std::uint8_t>& source, std::vector<double>& out) {
  const RegionGraph& g = space_.graph;
  out.resize(m_);
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
  // is typically a handful of cells): directly, per source and cell. Only the set's border cells
  // (a 4-neighbour outside the set) can be the nearest to a cell outside it: from any other one,
  // a step towards that cell stays in the set and comes closer. Both ways are exact, which one
  // runs is only a matter of speed; a large set has many border cells and is not scanned.
  constexpr int kScanned = 64;
  int size = 0;
  for (int i = 0; i < m_; ++i) size += source[i];
  queue_.clear();
  for (int i = 0; i < m_ && size <= kScanned; ++i) {
    if (!source[i]) continue;
    bool border = false;
    for (int nb : g.next[i]) border |= nb < 0 || !source[nb];
    if (border) queue_.push_back(i);
  }
  if (size <= kScanned && queue_.size() <= 16) {
    squared_distances_to(queue_, out);
    double* d = out.data();
    for (int i = 0; i < m_; ++i) d[i] = source[i] ? 0.0 : std::sqrt(d[i]);  // vectorises (see CMakeLists.txt)
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
  if (roots_.empty()) {  // no source: no distance (all 0)
    std::fill(out.begin(), out.end(), 0.0);
    return;
  }
  if (root_.empty()) {
    // Square roots of every squared distance the box can hold, once (the same values sqrt gives).
    const std::size_t dx = box_w_ - 1, dy = box_h_ - 1;
    root_.resize(dx * dx + dy * dy + 1);
    for (std::size_t k = 0; k < root_.size(); ++k) root_[k] = std::sqrt(static_cast<double>(k));
  }
  v_.resize(roots_.size() + 1);
  zn_.resize(roots_.size() + 1);
  zd_.resize(roots_.size() + 1);
  for (int y = 0; y < box_h_; ++y) {
    if (row_begin_[y] == row_begin_[y + 1]) continue;
    distance_row(&steps_[y * w], roots_, cell_column_.data(), row_begin_[y], row_begin_[y + 1], box_x0_,
                 root_.data(), out.data(), v_.data(), zn_.data(), zd_.data());
  }
}

}  // namespace swarm::planner::detail
