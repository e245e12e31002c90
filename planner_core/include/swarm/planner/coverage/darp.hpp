// DARP: divide a region's free cells among robots so that every robot gets a connected region of
// (nearly) its share of the cells. Kapoutsis, Chatzichristofis & Kosmatopoulos, "DARP: Divide
// Areas Algorithm for Optimal Multi-Robot Coverage Path Planning", J. Intell. Robot. Syst. 86
// (2017); with the BFS + K-Means initialisation of docs/papers.md section 2
// (seeds/000_adfe46c08ea6d43e.txt).
//
// The algorithm. Every robot r has an evaluation matrix E_r (one value per cell); each cell goes to
// the robot with the smallest value (ties: lowest robot index). E_r starts as the distance from
// r's start cell to the cell (Euclidean, as the paper; or geodesic = BFS steps through the region),
// so the first division is a Voronoi split. Each iteration then multiplies E_r by
//   - m_r, the fairness correction (as the reference implementations): with x_r = k_r / (n s_r)
//     (k_r cells, s_r share, n robots), robots with k_r > s_r are "over"; D = their summed
//     (k_r - s_r) / (n s_r), X = their summed x_r; m_r = 1 + (x_r / X) D / 2 for an over robot,
//     1 - (x_r / X) D / 2 for every other robot (m_r = 1 for all when nobody is over). The pull
//     is towards the exact share, as the reference's first stage; only the goal allows 1 cell;
//   - C_r, the connectivity correction, for a robot whose region is split: from d1 = distance to
//     the piece holding its start and d2 = distance to its other pieces, each divided by its
//     maximum, C_r = d1 - d2 rescaled to [-cv, +cv] (cv = connectivity_variation) and applied as
//     exp(C_r): cells near the robot's own piece get cheaper, its stray pieces dearer. Distances
//     are the exact Euclidean distance transform (Felzenszwalb & Huttenlocher 2012, walls
//     ignored, as the reference) or BFS steps through the region (geodesic);
//   - a random factor exp(u), u uniform in [-random_level, +random_level] per cell and robot.
// Converged when every region is 4-connected, holds its start cell and |k_r - s_r| <= tolerance
// (1 cell, the paper's goal). One iteration = one metric update; a division that is already a
// goal needs 0 (the paper's "0 iterations" for one robot). Stops after max_iterations updates
// (Failed) or when should_stop() returns true (Stopped, polled before every update), returning the
// best division seen (fewest split regions, then smallest max |k_r - s_r|).
//
// Overflow. The reference multiplies float64 metrics forever and overflows after ~20,000
// iterations (data/README.md). Here every metric is kept as its logarithm,
// so the multiplications are additions (of log m_r, C_r and u), and after every update all the
// values of a cell are shifted by the same amount, that cell's smallest value: which robot is
// cheapest at a cell never depends on such a shift, and every cell's values then hold only the
// differences between robots, which are near 0 exactly where cells change hands, however long
// DARP runs (there a float's 24-bit mantissa resolves the 1e-4 random factor many times over).
// The factors are exp(C) and exp(u) instead of the reference's 1 + C and 1 + u: identical to
// within 5e-5 at these magnitudes.
//
// Shares. s_r = (cells of r's component of the region) * w_r / (sum of the weights of the robots
// in that component): robots divide the 4-connected piece of the region they stand in. Every
// region cell counts, start cells included. Region cells in a piece with no robot are reported
// (assignment kUnreachable, unreachable_cells), not divided.
//
// Initialisation (DarpInit) decides the cells the regions grow from (`starts` in the result):
//   Given     the robots' own cells (plain DARP; the paper's "standalone");
//   Random    random distinct cells of each robot's piece, matched to the robots by least total
//             distance (Hungarian);
//   KMeans    K-Means (k = n) over the region's cells, Lloyd started from the robots' cells, each
//             centre snapped to the nearest unused cell of its robot's piece (paper: Baseline 2);
//   BfsKMeans the paper's method: a multi-source BFS from the current starts splits the region
//             into n connected candidate regions (a geodesic Voronoi), each candidate region's mean
//             (the K-Means update) snapped to its nearest cell inside that candidate region becomes
//             that robot's new start (one such K-Means iteration per re-initialisation, as
//             docs/papers.md decides; bfs_kmeans_steps > 1 iterates it, stopping when no start
//             moves). Imbalance alpha = 1 - Jain is measured on the first division from the
//             robots' cells (alpha0); if alpha0 > alpha_threshold (or always, with
//             reinit_always) the step is applied, the division re-probed (alpha_reinit), and
//             repeated while alpha > alpha_threshold, at most max_reinitialisations (L) times;
//             DARP then runs from the last starts. Every abandoned probe counts one iteration.
// As in the paper, the starts are where the regions grow from, i.e. the robots' new initial
// positions: with Random, KMeans or BfsKMeans a robot may have to drive to its region first
// (coverage_plan.hpp's plan_coverage gives that approach path). With Given every region holds its
// robot. alpha0 is always measured from the robots' own cells (for Random and KMeans it is
// informational and not counted); alpha_reinit holds the alpha of the first division from each
// new set of starts.
//
// Methods (DivisionMethod). Darp: DARP alone, as above (it may end Failed with regions split or
// unbalanced). Auto, the default: DARP first, for at most auto_darp_iterations updates (fewer
// when max_iterations is smaller); if it has not converged by then, its best division is
// repaired (division_repair.hpp: split regions reconnected, then cells handed along chains of
// neighbouring regions until every region is within tolerance; a region may give up its start
// and grow from the cell nearest its robot instead; should that get stuck, up to repair_restarts
// fresh first divisions, from K-Means and then random starts, are repaired too and the best kept;
// docs/division.md). Auto ends Converged whenever it finds such
// a division; Impossible when it can prove none exists (a cut cell that no regions of the right
// sizes fit around; message says which), with the most balanced connected division it found;
// Failed only when it found none and proved nothing. `finished_by` says which method produced
// the division returned.
//
// Bad input (a value, never a throw): no robot, a robot outside the map or not on a Free cell of
// the region, two robots on one cell, a non-positive or non-finite weight, weights of the wrong
// length, a region mask of the wrong size. (Robots stand on distinct cells, so there are never
// more robots than cells.) The live task must put the robots' own cells into a region mask.
//
// Connectivity is checked every iteration by replaying the few cells that changed hands (a region
// stays connected when a cell it loses is a simple point and a cell it gains touches it), and by
// a full union-find labelling when that cannot tell.
//
// Units: cells. Deterministic per config.seed (all draws through rng.hpp). Thread-safe: no shared
// state. Cost per iteration O(n * cells), plus two distance transforms per split region (each
// kept per robot: reused while the region's pieces stay the same, lowered when they only gain
// a few cells).
//
//   DarpRequest req;
//   req.robots = {{3, 4}, {40, 20}, {12, 30}};
//   DarpConfig cfg;                                 // Euclidean, Given, 10,000 iterations
//   cfg.distance = DarpDistance::Geodesic;
//   DarpResult r = divide_areas(map, req, cfg, [&] { return clock::now() > deadline; });
//   if (r.status == DarpStatus::Converged) { /* r.assignment[map.index(c)] == robot of cell c */ }
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

enum class DarpDistance : std::uint8_t { Euclidean, Geodesic };
enum class DarpInit : std::uint8_t { Given, Random, KMeans, BfsKMeans };
enum class DivisionMethod : std::uint8_t { Darp, Auto };
enum class DarpStatus : std::uint8_t {
  Converged,   // every region connected, holding its start, within tolerance of its share
  Failed,      // no such division found; the best division seen is returned
  Stopped,     // should_stop() said so (Darp); the best division seen is returned
  BadInput,    // see message; nothing else is filled in
  Impossible,  // Auto: no such division exists (message: why); the most balanced one found
};

[[nodiscard]] const char* to_string(DarpStatus status);
[[nodiscard]] const char* to_string(DarpDistance distance);
[[nodiscard]] const char* to_string(DarpInit init);
[[nodiscard]] const char* to_string(DivisionMethod method);
// "euclidean" / "geodesic", "given" / "random" / "kmeans" / "bfs-kmeans"; nullopt otherwise.
[[nodiscard]] std::optional<DarpDistance> parse_darp_distance(const std::string& text);
[[nodiscard]] std::optional<DarpInit> parse_darp_init(const std::string& text);
// "darp" / "auto"; nullopt otherwise.
[[nodiscard]] std::optional<DivisionMethod> parse_division_method(const std::string& text);

struct DarpConfig {
  DivisionMethod method = DivisionMethod::Auto;
  int auto_darp_iterations = 100;        // Auto: DARP's updates before the repair takes over
  int repair_restarts = 8;               // Auto: fresh first divisions the repair may try after DARP's
  int max_iterations = 10000;            // I_max (paper); metric updates, probes included
  DarpDistance distance = DarpDistance::Euclidean;
  DarpInit init = DarpInit::Given;
  bool reinit_always = false;            // BfsKMeans: re-initialise even when alpha0 <= threshold
  double alpha_threshold = 0.21;         // alpha_th (paper, empirical)
  int max_reinitialisations = 2;         // L (paper)
  double tolerance_cells = 1.0;          // goal: |k_r - s_r| <= this
  double connectivity_variation = 0.01;  // cv: C_r spans [-cv, +cv] (reference CCvariation)
  double random_level = 1e-4;            // u spans [-level, +level] (reference randomLevel)
  int kmeans_max_iterations = 100;       // Lloyd iterations of the KMeans initialisation
  int bfs_kmeans_steps = 1;              // BfsKMeans: K-Means iterations per re-initialisation
  std::uint64_t seed = 1;                // random factors, Random starts
};

struct DarpRequest {
  std::vector<Cell> robots;            // each on a Free cell of the region, all distinct
  std::vector<double> weights;         // per robot, > 0; empty = equal portions
  std::vector<std::uint8_t> region;    // per grid cell, non-zero = divide it; empty = every Free cell
};

inline constexpr int kOutsideRegion = -1;  // blocked, unknown, or not in the region mask
inline constexpr int kUnreachable = -2;    // in the region, but in a piece no robot stands in

struct DarpResult {
  DarpStatus status = DarpStatus::BadInput;
  std::string message;                  // BadInput: what is wrong (robot index, cell, field)
  int iterations = 0;                   // metric updates + abandoned probes
  std::vector<int> assignment;          // per grid cell: robot, kOutsideRegion or kUnreachable
  std::vector<Cell> starts;             // per robot: the cell its region grew from and holds
  std::vector<int> cells;               // per robot: cells assigned, start included
  std::vector<double> shares;           // per robot: s_r
  double alpha0 = std::numeric_limits<double>::quiet_NaN();  // 1 - Jain, first division, own cells
  std::vector<double> alpha_reinit;     // alpha of the first division from each new set of starts
  double final_imbalance = std::numeric_limits<double>::quiet_NaN();  // 1 - Jain of `cells`
  double max_deviation = 0;             // max_r |k_r - s_r|
  int split_regions = 0;                // regions not 4-connected (0 when converged)
  int unreachable_cells = 0;            // region cells marked kUnreachable
  std::string finished_by = "darp";     // "darp", or "repair" when Auto repaired DARP's best
  int repair_moves = 0;                 // cells the repair handed to another region
  bool starts_moved = false;            // the repair grew some region from another cell than DARP's start
  double seconds = 0;                   // wall time of the whole division
};

// Divides the region (request.region, or every Free cell of `map`) among request.robots.
[[nodiscard]] DarpResult divide_areas(const OccupancyGrid& map, const DarpRequest& request,
                                      const DarpConfig& config = {},
                                      const std::function<bool()>& should_stop = {});

// Jain's fairness index (sum x)^2 / (n sum x^2) of non-negative loads; 1 for n == 0 or all zero.
[[nodiscard]] double jain_index(const std::vector<double>& loads);
// The paper's imbalance alpha = 1 - jain_index(cells_r / weight_r) (weights empty = equal).
[[nodiscard]] double imbalance(const std::vector<int>& cells, const std::vector<double>& weights = {});

}  // namespace swarm::planner
